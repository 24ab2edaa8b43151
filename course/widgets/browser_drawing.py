"""A drag's moving artists as drawing commands that the browser carries out.

At every step of a drag the kernel used to draw the moving artists with Agg,
compare the picture with the last one, and encode the changed rectangles as
PNG: on lesson 01's app that is most of the kernel's time per step, and the
time per step decides how many students a server holds. The browser can draw
lines, markers and text itself. So during a drag the kernel lets matplotlib
draw the moving artists as it always does, but into :class:`CommandRecorder`,
a renderer that keeps what it is asked to draw (each path in picture pixels,
its colours, width, dashes and clip box; each text at the place Agg would put
it) instead of painting it. ``picture.js`` paints those commands on a canvas
over the picture's still background, which it is sent once per drag. The
release draws the whole picture with Agg again, so the picture a student
keeps is matplotlib's, pixel for pixel.

What a canvas cannot draw as matplotlib does (an image, mathtext, a hatch, a
clip path that is not a rectangle, a sketch) raises :class:`NotDrawable`,
and the app falls back to Agg and patches (``FigureView.render_moving``).

A ``"drawing"`` message's last four buffers are pixels (RGB, row by row), its
commands (a JSON list, UTF-8), their vertices (float32 pairs, little-endian)
and their codes (uint8), the commands in picture pixels with y down:

- ``{"pixels": [start, width, height], "at": [left, top], "zoom": zoom}``:
  ``width`` x ``height`` pixels from byte ``start`` of the pixels' buffer,
  each drawn as ``zoom`` x ``zoom`` picture pixels from (left, top), over
  whatever is there and whatever the clip (a pixel panel, written first);
- ``{"path": [start, count], **style}``: a path whose vertices are ``count``
  (x, y) pairs of the message's float32 buffer from pair ``start``, and
  whose codes are the same entries of its uint8 buffer (matplotlib's
  ``Path`` codes: 1 move, 2 line, 3 and 4 quadratic and cubic Bezier
  control points, 79 close);
- ``{"marker": [start, count], "at": [start, count], **style}``: the marker
  path (relative to its centre) drawn at each of the ``at`` points;
- ``{"text": s, "x", "y", "angle", "font": [size px, weight, style,
  families], "color", "clip"}``: a text whose baseline starts at (x, y).

``style`` holds ``"stroke"`` and ``"fill"`` (RGBA in [0, 1], or None),
``"width"`` (pixels), ``"dash"`` ([offset, [on, off, ...]] in pixels, or
None), ``"cap"``, ``"join"`` and ``"clip"`` ([left, top, width, height], or
None).

The apps are this module's only callers, through ``FigureView``
(``UNCHECKED = True``).
"""

from __future__ import annotations

import json
from typing import Any

import numpy as np
from matplotlib import rcParams
from matplotlib._path import affine_transform, cleanup_path
from matplotlib.backend_bases import GraphicsContextBase, RendererBase
from matplotlib.font_manager import FontProperties, weight_dict
from matplotlib.path import Path as MatplotlibPath
from matplotlib.transforms import Affine2D

__all__ = ["CommandRecorder", "NotDrawable"]

UNCHECKED = True  # see the module docstring

#: matplotlib's cap styles by the canvas's names.
_CAPS = {"butt": "butt", "projecting": "square", "round": "round"}
_GENERIC_FAMILIES = ("serif", "sans-serif", "cursive", "fantasy", "monospace")


class NotDrawable(Exception):
    """Something the browser's canvas cannot draw as Agg does: draw with Agg instead."""


#: The codes of the places markers are drawn at: all MOVETO.
_MOVES = np.full(4096, MatplotlibPath.MOVETO, dtype=np.uint8)


def _json_fields(fields: dict) -> str:
    """``fields`` as the members of a JSON object, without its braces.

    >>> _json_fields({"width": 1.5, "dash": None})
    '"width":1.5,"dash":null'
    """
    return json.dumps(fields, separators=(",", ":"))[1:-1]


def _gc_key(gc: GraphicsContextBase, rgbFace: Any) -> tuple:
    """All a path's style is read from: the graphics context's state and the face colour."""
    offset, dashes = gc._dashes
    clip = gc._cliprect
    return (
        tuple(gc._rgb), gc._linewidth, offset, None if dashes is None else tuple(dashes),
        gc._capstyle, gc._joinstyle, gc._alpha, gc._forced_alpha,
        None if clip is None else tuple(clip.extents), gc._clippath, gc._hatch, gc._sketch,
        None if rgbFace is None else tuple(rgbFace),
    )  # fmt: skip


def _rounded(values: Any, digits: int = 3) -> list[float]:
    return [round(float(value), digits) for value in values]


def _agg_snaps(vertices: np.ndarray, codes: np.ndarray | None, snap: bool | None) -> bool:
    """Whether Agg snaps a path of these vertices (pixels) to the pixel grid.

    Agg's rule (``PathSnapper::should_snap``): always if ``snap`` is True,
    never if False, and if None when the path has no curves, at most 1024
    vertices, and only horizontal and vertical lines.

    >>> square = np.array([[0, 0], [2, 0], [2, 2], [0, 2]])
    >>> slanted = np.array([[0, 0], [2, 0], [3, 2]])
    >>> _agg_snaps(square, None, None), _agg_snaps(slanted, None, None)
    (True, False)
    >>> _agg_snaps(square, None, False), _agg_snaps(np.zeros((2000, 2)), None, None)
    (False, False)
    """
    if snap is not None:
        return bool(snap)
    if len(vertices) > 1024:
        return False
    if codes is None:
        codes = np.full(len(vertices), MatplotlibPath.LINETO)
        codes[:1] = MatplotlibPath.MOVETO
    if np.isin(codes, (MatplotlibPath.CURVE3, MatplotlibPath.CURVE4)).any():
        return False
    steps = np.abs(np.diff(vertices, axis=0))
    lines = codes[1:] == MatplotlibPath.LINETO
    return not (lines & (steps[:, 0] >= 1e-4) & (steps[:, 1] >= 1e-4)).any()


class CommandRecorder(RendererBase):
    """A matplotlib renderer that records drawing commands for ``picture.js``.

    ``agg`` is the figure's Agg renderer: text is measured by it, so that
    every text is placed where Agg would place it. Call :meth:`start`, draw
    the artists into the recorder (``artist.draw(recorder)``), then
    :meth:`finish` for the drawing's four buffers. Each command is kept as
    its JSON text: a path's style is encoded once, when its paint is read, so
    that a step joins strings rather than encoding every number again.

    Examples
    --------
    >>> from matplotlib.backends.backend_agg import FigureCanvasAgg
    >>> from matplotlib.figure import Figure
    >>> figure = Figure(figsize=(1, 1), dpi=100)
    >>> canvas = FigureCanvasAgg(figure)
    >>> axes = figure.add_axes((0, 0, 1, 1), xlim=(0, 1), ylim=(0, 1))
    >>> (line,) = axes.plot([0, 1], [0, 0.5], color="red", linewidth=1.44)  # 2 px at 100 dpi
    >>> recorder = CommandRecorder(canvas.get_renderer())
    >>> recorder.start()
    >>> line.draw(recorder)
    >>> pixels, commands, vertices, codes = recorder.finish()
    >>> (command,) = json.loads(commands)
    >>> command["path"], command["stroke"], command["width"]
    ([0, 2], [1.0, 0.0, 0.0, 1.0], 2.0)
    >>> np.frombuffer(vertices, "<f4").tolist(), list(codes)
    ([0.0, 100.0, 100.0, 50.0], [1, 2])
    """

    def __init__(self, agg: Any) -> None:
        super().__init__()
        self.agg = agg
        self.dpi = agg.dpi
        self.width, self.height = agg.get_canvas_width_height()
        self._fonts: dict[int, list] = {}
        #: From display pixels (y up) to picture pixels (y down).
        self._down = Affine2D().scale(1.0, -1.0).translate(0.0, self.height)
        self._styles: dict[tuple, tuple[str, float] | None] = {}  # path_paint's, by _gc_key
        self.start()

    def start(self) -> None:
        """Forget the commands recorded so far."""
        if len(self._styles) > 256:  # clip boxes of views gone by
            self._styles.clear()
        self.commands: list[str] = []  # each command's JSON text
        #: Each text command as (its index in ``commands``, x, y, the rest of its JSON).
        self.texts: list[tuple[int, float, float, str]] = []
        self._vertices: list[np.ndarray] = []
        self._codes: list[np.ndarray] = []
        self._count = 0
        self._pixels: list[bytes] = []
        self._pixel_bytes = 0
        #: While not None, each command's making as (method, arguments), to make it again.
        self.log: list[tuple[str, tuple]] | None = None
        # Whether a long line is simplified (Path._update_values): read once for the drawing.
        self._simplifies = rcParams["path.simplify"] and rcParams["path.simplify_threshold"] > 0

    def finish(self) -> list[bytes]:
        """The pixels, the commands (a JSON list, UTF-8), their vertices and their codes."""
        vertices = np.concatenate(self._vertices) if self._vertices else np.zeros((0, 2))
        codes = np.concatenate(self._codes) if self._codes else np.zeros(0)
        return [
            b"".join(self._pixels),
            f"[{','.join(self.commands)}]".encode(),
            vertices.astype("<f4").tobytes(),
            codes.astype(np.uint8).tobytes(),
        ]

    def recorded(self) -> list[dict]:
        """The commands recorded so far, decoded."""
        return [json.loads(command) for command in self.commands]

    # --- what matplotlib asks of a renderer --------------------------------

    def flipy(self) -> bool:
        return True  # as Agg: text is placed with y down

    def get_canvas_width_height(self) -> tuple[float, float]:
        return self.width, self.height

    def points_to_pixels(self, points: Any) -> Any:
        return points * self.dpi / 72

    def get_text_width_height_descent(self, s: str, prop: Any, ismath: Any) -> Any:
        return self.agg.get_text_width_height_descent(s, prop, ismath)

    def new_gc(self) -> GraphicsContextBase:
        return GraphicsContextBase()

    def option_image_nocomposite(self) -> bool:
        return True

    def draw_image(self, gc: Any, x: float, y: float, im: Any, transform: Any = None) -> None:
        raise NotDrawable("an image")

    def draw_gouraud_triangles(
        self, gc: Any, triangles_array: Any, colors_array: Any, transform: Any
    ) -> None:
        raise NotDrawable("Gouraud-shaded triangles")

    def draw_tex(self, *args: Any, **kwargs: Any) -> None:
        raise NotDrawable("TeX")

    def draw_path(self, gc: Any, path: Any, transform: Any, rgbFace: Any = None) -> None:
        paint = self.path_paint(gc, transform, rgbFace)
        if paint is not None:
            self.add_path(paint, path)

    def draw_markers(
        self,
        gc: Any,
        marker_path: Any,
        marker_trans: Any,
        path: Any,
        trans: Any,
        rgbFace: Any = None,
    ) -> None:
        paint = self.marker_paint(gc, marker_path, marker_trans, trans, rgbFace)
        if paint is not None:
            self.add_markers(paint, path.vertices)

    def draw_path_collection(
        self, gc: Any, master_transform: Any, paths: Any, all_transforms: Any, *given: Any,
        hatchcolors: Any = None,
    ) -> None:  # fmt: skip
        # given: offsets, offset_trans, facecolors, edgecolors, linewidths, linestyles,
        # antialiaseds, urls, offset_position, as RendererBase.draw_path_collection's.
        hatchcolors = [] if hatchcolors is None else hatchcolors
        one = (given[0], *given[2:8], hatchcolors)  # one value each, or none
        if len(all_transforms) or max(len(values) for values in one) > 1:
            super().draw_path_collection(
                gc, master_transform, paths, all_transforms, *given, hatchcolors=hatchcolors
            )
            return
        # Every path is drawn with the graphics context, face and offset the base class
        # sets up for the first (a pixel grid's dozens of lines): one paint for them all.
        for x, y, _, gc0, face in self._iter_collection(
            gc, [None], *given, hatchcolors=hatchcolors
        ):
            transform = master_transform
            if x != 0 or y != 0:
                transform = master_transform.frozen().translate(x, y)
            paint = self.path_paint(gc0, transform, face)
            for path in paths if paint is not None else ():
                self.add_path(paint, path)

    # --- a call's paint, kept by a replay for the next steps ----------------
    #
    # A call's command depends on its path and on what ``gc``, the transforms and the
    # face say. A moving line (``LineReplay``) is drawn with the same ``gc`` and transform
    # at every step of a drag: they are read once into a *paint*, and each step only
    # makes the command from the line's new vertices (``add_path``, ``add_markers``).

    def path_paint(self, gc: Any, transform: Any, rgbFace: Any = None) -> tuple | None:
        """What :meth:`draw_path` reads from all but the path; None if it draws nothing."""
        # A collection draws each of its paths with a graphics context set up alike (a
        # pixel grid: dozens of lines a step): its style is read and encoded once.
        key = _gc_key(gc, rgbFace)
        if key not in self._styles:
            style = self._style(gc, rgbFace)
            self._styles[key] = style and (
                _json_fields(style),
                style["width"] if style["stroke"] else 0.0,
            )
        if self._styles[key] is None:
            return None
        style, stroke_width = self._styles[key]
        to_picture = (transform + self._down).frozen()  # picture pixels, y down
        return style, to_picture, gc.get_snap(), stroke_width, rgbFace is None

    def add_path(self, paint: tuple, path: Any) -> None:
        """Record ``path`` drawn with ``paint`` (:meth:`path_paint`)."""
        style, to_picture, snap, stroke_width, unfilled = paint
        # As Agg does: in picture pixels (y down), NaNs dropped, snapped to the pixel
        # grid where Agg snaps, long unfilled lines simplified.
        vertices, codes = cleanup_path(
            path, to_picture, True, None, snap, stroke_width, path.should_simplify and unfilled,
            True, None,
        )  # fmt: skip
        self._add_cleaned(style, vertices, codes)

    def add_line(self, paint: tuple, vertices: np.ndarray) -> None:
        """Record the line through ``vertices``, (N, 2), drawn with ``paint``: as :meth:`add_path`.

        The path ``Line2D`` would make of them is simplified, as matplotlib
        decides, from 128 vertices (``Path.should_simplify``).
        """
        style, to_picture, snap, stroke_width, unfilled = paint
        path = MatplotlibPath._fast_from_codes_and_verts(vertices, None)
        simplify = unfilled and len(vertices) >= 128 and self._simplifies
        vertices, codes = cleanup_path(
            path, to_picture, True, None, snap, stroke_width, simplify, True, None
        )
        self._add_cleaned(style, vertices, codes)

    def _add_cleaned(self, style: str, vertices: np.ndarray, codes: np.ndarray) -> None:
        if self.log is not None:
            self.log.append(("_add_cleaned", (style, vertices, codes)))
        if len(codes) > 1:  # without the STOP that ends them
            start, count = self._add(vertices[:-1], codes[:-1])
            self.commands.append(f'{{"path":[{start},{count}],{style}}}')

    def marker_paint(
        self, gc: Any, marker_path: Any, marker_trans: Any, trans: Any, rgbFace: Any = None
    ) -> tuple | None:
        """What :meth:`draw_markers` reads from all but the places; None if it draws nothing."""
        style = self._style(gc, rgbFace)
        if style is None:
            return None
        # As Agg places a marker: its centre on a whole pixel, its shape snapped to the
        # pixel grid where Agg snaps it, else moved to the centre of that pixel.
        local = marker_trans + Affine2D().scale(1.0, -1.0)
        snap = _agg_snaps(local.transform(marker_path.vertices), marker_path.codes, gc.get_snap())
        marker = marker_path.cleaned(
            transform=local,
            snap=snap,
            stroke_width=style["width"] if style["stroke"] else 0.0,
            curves=True,
        )
        shape = marker.vertices[:-1] + (0.0 if snap else 0.5)
        to_picture = (trans + self._down).get_matrix()  # an affine transform's, frozen
        return _json_fields(style), shape, marker.codes[:-1], to_picture

    def add_markers(self, paint: tuple, points: np.ndarray) -> None:
        """Record the markers of ``paint`` (:meth:`marker_paint`) at ``points``, (N, 2)."""
        style, shape, codes, to_picture = paint
        places = affine_transform(points, to_picture)
        if not np.isfinite(places).all():
            places = places[np.isfinite(places).all(axis=1)]
        places += 0.5
        np.floor(places, out=places)
        self._add_markers_at(style, shape, codes, places)

    def _add_markers_at(
        self, style: str, shape: np.ndarray, codes: np.ndarray, places: np.ndarray
    ) -> None:
        if self.log is not None:
            self.log.append(("_add_markers_at", (style, shape, codes, places)))
        if len(places) == 0 or len(shape) == 0:
            return
        many = len(places)
        moves = _MOVES[:many] if many <= len(_MOVES) else np.full(many, MatplotlibPath.MOVETO)
        (start, count), (at, _) = self._add(shape, codes), self._add(places, moves)
        self.commands.append(f'{{"marker":[{start},{count}],"at":[{at},{many}],{style}}}')

    def draw_text(
        self,
        gc: Any,
        x: float,
        y: float,
        s: str,
        prop: Any,
        angle: float,
        ismath: Any = False,
        mtext: Any = None,
    ) -> None:
        if ismath:
            raise NotDrawable("mathtext")
        self._check_gc(gc)
        rest = {
            "text": s,
            "angle": round(float(angle), 3),
            "font": self._font(prop),
            "color": _rounded(gc.get_rgb()),
            "clip": self._clip(gc),
        }
        # Agg places glyphs to 1/64 pixel. y is down already: flipy() is True.
        self.add_text(round(float(x), 4), round(float(y), 4), _json_fields(rest))

    def add_pixels(self, left: int, top: int, pixels: np.ndarray, zoom: int) -> None:
        """Record (h, w, 3) uint8 ``pixels``, each ``zoom`` x ``zoom``, from picture (left, top).

        Written over whatever is there, as ``FigureView.paste`` writes them.
        """
        height, width = pixels.shape[:2]
        start = self._pixel_bytes
        self._pixels.append(pixels.tobytes())
        self._pixel_bytes += len(self._pixels[-1])
        self.commands.append(
            f'{{"pixels":[{start},{width},{height}],"at":[{left},{top}],"zoom":{zoom}}}'
        )

    def add_text(self, x: float, y: float, rest: str) -> None:
        """Record a text command whose baseline starts at (x, y), the rest of it JSON fields."""
        if self.log is not None:
            self.log.append(("add_text", (x, y, rest)))
        self.texts.append((len(self.commands), x, y, rest))
        self.commands.append(f'{{"x":{x!r},"y":{y!r},{rest}}}')

    # --- the recording -----------------------------------------------------

    def _add(self, vertices: np.ndarray, codes: np.ndarray) -> tuple[int, int]:
        """Store vertices and their codes; their (start, count)."""
        self._vertices.append(vertices)
        self._codes.append(codes)
        start, self._count = self._count, self._count + len(vertices)
        return start, len(vertices)

    def _check_gc(self, gc: Any) -> None:
        if gc.get_hatch() is not None:
            raise NotDrawable("a hatch")
        if gc.get_sketch_params() is not None:
            raise NotDrawable("a sketch")
        clip_path, _transform = gc.get_clip_path()
        if clip_path is not None:
            raise NotDrawable("a clip path")

    def _clip(self, gc: Any) -> list[float] | None:
        box = gc.get_clip_rectangle()
        if box is None:
            return None
        x0, y0, x1, y1 = box.extents
        return _rounded((x0, self.height - y1, x1 - x0, y1 - y0), 2)

    def _style(self, gc: Any, rgbFace: Any) -> dict | None:
        """A path's paint as the canvas takes it, as Agg reads it from ``gc``; None if none."""
        self._check_gc(gc)
        width = float(self.points_to_pixels(gc.get_linewidth()))
        stroke = gc.get_rgb() if width > 0 else None
        if stroke is not None and stroke[3] == 0:
            stroke = None
        fill = None
        if rgbFace is not None:
            alpha = (
                gc.get_alpha()
                if gc.get_forced_alpha()
                else (rgbFace[3] if len(rgbFace) > 3 else 1.0)
            )
            fill = (*rgbFace[:3], alpha) if alpha > 0 else None
        if stroke is None and fill is None:
            return None
        offset, dashes = gc.get_dashes()
        dash = None
        if dashes is not None and len(dashes) and stroke is not None:
            dash = [
                round(float(self.points_to_pixels(offset or 0)), 3),
                _rounded(self.points_to_pixels(np.asarray(dashes, dtype=float))),
            ]
        return {
            "stroke": None if stroke is None else _rounded(stroke),
            "fill": None if fill is None else _rounded(fill),
            "width": round(width, 3),
            "dash": dash,
            "cap": _CAPS[gc.get_capstyle()],
            "join": gc.get_joinstyle(),
            "clip": self._clip(gc),
        }

    def _font(self, prop: FontProperties) -> list:
        """[size in pixels, CSS weight, CSS style, [families]], as ``prop`` asks for."""
        key = hash(prop)
        if key not in self._fonts:
            families: list[str] = []
            for family in prop.get_family():
                if family in _GENERIC_FAMILIES:
                    families += [*rcParams[f"font.{family}"], family]
                else:
                    families.append(family)
            weight = prop.get_weight()
            self._fonts[key] = [
                round(float(self.points_to_pixels(prop.get_size_in_points())), 3),
                weight_dict.get(weight, weight) if isinstance(weight, str) else int(weight),
                prop.get_style(),
                list(dict.fromkeys(families)),
            ]
        return self._fonts[key]
