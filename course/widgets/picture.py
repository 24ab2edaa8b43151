"""The picture an app draws into, and the pixels it writes into it as they are.

:class:`Picture` is the widget: the encoded picture the kernel draws, and the
student's pointer on it (its browser half is ``picture.js``). :class:`FigureView`
renders a matplotlib ``Figure`` on the Agg canvas into it, the whole figure or,
while something is dragged, only what moves over a cached background
(blitting). :class:`PixelPanel` shows an image at a whole zoom by writing its
pixels into the canvas, without matplotlib's resampling. :func:`png_bytes` is
the fast PNG encoder a picture redrawn at every step of a drag needs.

The building blocks of the apps (a picture widget, figure views, pixel
panels): the apps, which validate their own arguments, are their only
callers, so this module checks no input (``UNCHECKED = True``; the fuzz test
skips it), but for :func:`pixel_figure`'s ``zoom``, which every lesson figure
passes on from its own caller.
"""

from __future__ import annotations

import base64
import io
import json
import struct
import zlib
from pathlib import Path
from typing import Any

import anywidget
import matplotlib
import numpy as np
import traitlets
from IPython.display import display
from matplotlib import colors as mcolors
from matplotlib import ft2font
from matplotlib.axes import Axes
from matplotlib.backends import backend_agg
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.path import Path as MatplotlibPath
from matplotlib.text import Text
from PIL import Image as PILImage

from course import limits
from course._validate import as_int, describe
from course.i18n import _
from course.widgets.browser_drawing import CommandRecorder, NotDrawable

__all__ = [
    "GRAY_PIXELS",
    "FigureView",
    "FixedText",
    "Picture",
    "PixelPanel",
    "Still",
    "bare_axes",
    "pixel_axes",
    "pixel_figure",
    "png_bytes",
    "rounding_level",
]

UNCHECKED = True  # see the module docstring

#: imshow settings for a gray image in [0, 1], pixels drawn as flat squares.
GRAY_PIXELS = {"cmap": "gray", "vmin": 0.0, "vmax": 1.0, "interpolation": "nearest"}


def rounding_level(value: float, bound: float = 1e-12, spec: str = ".1e") -> str:
    """A difference or residual as a lesson prints it: "below 1e-12" when it is that small.

    Results that agree "to rounding" differ in their last bits from one CPU,
    BLAS build or thread count to the next (numpy and OpenBLAS pick their
    SIMD paths by processor), so their digits are not printed: a printed
    number must be the same on every machine. ``bound`` is chosen well above
    what rounding can reach; a value at or above it is printed with ``spec``.

    Examples
    --------
    >>> rounding_level(3.1e-15), rounding_level(2.5e-4), rounding_level(3e-13, bound=1e-10)
    ('below 1e-12', '2.5e-04', 'below 1e-10')
    """
    value = float(value)
    if abs(value) < bound:
        shown = f"{bound:.0e}".replace("e-0", "e-").replace("e+0", "e+")
        return _("below {bound}").format(bound=shown)
    return format(value, spec)


def png_bytes(pixels: np.ndarray) -> bytes:
    """An (H, W, 3) RGB or (H, W, 4) RGBA uint8 image as PNG: no filter, zlib level 1.

    What a picture redrawn at every step of a drag needs: Pillow's encoder
    tries an adaptive filter on every row, and on the course's line art
    that costs three times as long (5.5 against 1.6 ms for lesson 01's
    500 x 500 picture) for a file no smaller (41 against 33 kB). RGBA rows
    are copied whole; RGB from an RGBA canvas is best cut by
    :func:`_opaque_rgb` first (numpy copies three bytes of four slowly).

    Examples
    --------
    >>> png = png_bytes(np.zeros((2, 3, 3), dtype=np.uint8))
    >>> PILImage.open(io.BytesIO(png)).size
    (3, 2)
    >>> PILImage.open(io.BytesIO(png_bytes(np.zeros((2, 3, 4), dtype=np.uint8)))).mode
    'RGBA'
    """
    if not (
        isinstance(pixels, np.ndarray)
        and pixels.dtype == np.uint8
        and pixels.ndim == 3
        and pixels.shape[2] in (3, 4)
    ):
        raise ValueError(
            _("pixels must be an (H, W, 3) or (H, W, 4) uint8 array; got {given}").format(
                given=describe(pixels)
            )
        )
    height, width, channels = pixels.shape
    rows = np.zeros((height, 1 + channels * width), dtype=np.uint8)  # filter byte 0: none
    # One copy, however strided the pixels are (a rectangle cut from a picture is).
    after_filter_byte = np.ndarray(
        (height, width, channels),
        np.uint8,
        buffer=rows,
        offset=1,
        strides=(rows.strides[0], channels, 1),
    )
    after_filter_byte[...] = pixels

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (
            struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
        )

    colour_type = 2 if channels == 3 else 6  # 8-bit RGB, or RGBA
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", zlib.compress(rows, 1))
        + chunk(b"IEND", b"")
    )


def bare_axes(axes: Any) -> Any:
    """The axes without ticks, for a picture: returned, so it can wrap ``add_subplot``."""
    axes.set_xticks([])
    axes.set_yticks([])
    return axes


class Picture(anywidget.AnyWidget):
    """An app's picture: the PNG the kernel draws, and the student's pointer on it.

    ``value`` holds the PNG. ``handles`` lists what a press would grab, in
    picture pixels (row 0 at the top), so that the browser shows a grabbing
    hand over it: ``[x, y, radius, 0, 0, 0, 0]`` for a point and ``[0, 0, 0,
    left, top, right, bottom]`` for a box. Presses, moves and releases come
    back as messages ``{"kind", "x", "y"}`` in picture pixels; the kernel
    answers each once its picture is published: with ``{"kind": "drawn"}``,
    or, while a handle is held, with the step's ``{"kind": "patch", "drawn":
    true}`` message of changed rectangles (:meth:`FigureView.publish_patches`),
    which says both at once (each message is one more for the kernel, the
    server and the browser to pass on at every step of a drag).
    """

    _esm = (Path(__file__).parent / "picture.js").read_text(encoding="utf-8")
    value = traitlets.Bytes(b"").tag(sync=True)
    format = traitlets.Unicode("png").tag(sync=True)
    width = traitlets.Int(0).tag(sync=True)
    height = traitlets.Int(0).tag(sync=True)
    handles = traitlets.List([]).tag(sync=True)
    clickable = traitlets.Bool(False).tag(sync=True)


class FigureView:
    """A matplotlib ``Figure`` of ``shape = (H, W)`` pixels, rendered into a :class:`Picture`.

    ``format`` is ``"png"`` (lossless: line art, pixels to count) or ``"jpeg"``
    (photographs: on lesson 08's lake, 2.0 ms to encode against PNG's 12 ms,
    74 kB against 212 kB; at quality :data:`JPEG_QUALITY` with full-resolution
    colour no channel moves by more than 19 of 255).
    """

    #: JPEG quality of the photographic apps (colour kept at full resolution).
    JPEG_QUALITY = 95
    #: False sends a drag's steps as patches only (rectangles of Agg's pixels): for one
    #: view, or, set on the class, for every app of a kernel (benchmarks/bench_hub.py).
    draw_in_browser = True

    def __init__(
        self, shape: tuple[int, int] = (500, 500), dpi: int = 100, format: str = "png"
    ) -> None:
        rows, columns = shape
        if format not in ("png", "jpeg"):
            raise ValueError(
                _("format must be one of 'png', 'jpeg'; got {given}").format(given=repr(format))
            )
        self.figure = Figure(figsize=(columns / dpi, rows / dpi), dpi=dpi)
        self.canvas = FigureCanvasAgg(self.figure)
        self.image = Picture(width=columns, height=rows, format=format)
        self._background = None
        # The moving lines' Agg calls, replayed at a drag's steps (render_moving).
        self._replays: dict[Line2D, _LineReplay | None] = {}
        # The RGBA pixels the browser holds: the last whole picture and the patches since.
        self._shown: np.ndarray | None = None
        # During a drag the browser draws the moving artists from recorded commands over
        # the background it is sent once (browser_drawing): None until tried, False when
        # the moving artists hold something only Agg draws, until invalidate().
        self._browser_draws: bool | None = None
        self._backdrop_sent = False
        self._recorder: CommandRecorder | None = None
        self._drawn: list[bytes] | None = None  # the drawing's buffers the browser shows
        self._command_replays: dict[Line2D, _LineReplay | None] = {}
        #: True while the browser waits for the picture of its pointer message: the next
        #: patch tells it the picture is drawn (``"drawn": true``), and clears this.
        self.awaited = False

    def pixels(self) -> np.ndarray:
        """The picture as last rendered, RGBA pixels (height, width, 4) uint8, before encoding."""
        return np.asarray(self.canvas.buffer_rgba()).copy()

    def render(self) -> bytes:
        """Draw the whole figure into the picture and return the PNG bytes."""
        self.canvas.draw()
        return self.publish()

    def render_moving(
        self, artists: list, images: dict | None = None, patches: bool = False
    ) -> bytes:
        """Redraw only ``artists`` (made ``set_animated(True)``) over a cached background.

        Blitting: the first call draws everything else once and keeps it;
        later calls restore it and draw just the moving artists. Call
        :meth:`invalidate` when something in the background changes.
        ``images`` maps axes to (h, w, 3) uint8 pictures the size of the axes
        in pixels: written into the picture as they are, under the artists,
        without matplotlib's resampling (for images shown pixel for pixel).
        ``patches`` is for the steps of a drag, and then the empty bytes are
        returned: the browser is sent the moving artists as drawing commands
        (:meth:`publish_drawing`), or, where it cannot draw them (``images``,
        or an artist only Agg draws), only the changed rectangles
        (:meth:`publish_patches`). During such steps a moving line is drawn
        by replaying the Agg calls of its last full draw with its new data
        (:class:`_LineReplay`), as long as its style is the one it was drawn
        with; :meth:`invalidate`, which a new view calls for anyway, drops
        the recordings.
        """
        if patches and not images and self.draw_in_browser and self._browser_draws is not False:
            if self.publish_drawing(artists):
                return b""
        if self._background is None:
            self._draw_background()
        else:
            self.canvas.restore_region(self._background)
        for axes, image in (images or {}).items():
            self.paste(axes, image)
        renderer = self.canvas.get_renderer()
        _GlyphCache.install(renderer)
        if not patches:
            self._replays.clear()  # drawn in full: a line's style may have changed
        for artist in artists:
            if _empty_line(artist):  # an unused level of a construction: nothing to draw
                continue
            replay = self._replays.get(artist) if patches else None
            if replay is not None and replay.draw(renderer):
                continue
            if patches and isinstance(artist, Line2D):
                self._replays[artist] = _LineReplay.record(artist, renderer)
            else:
                self.figure.draw_artist(artist)
        if patches and self.publish_patches():
            return b""
        return self.publish()

    def paste(self, axes: Axes, image: np.ndarray) -> None:
        """Write ``image``, (h, w, 3) uint8, into the canvas where ``axes`` is: h x w pixels."""
        box = axes.get_window_extent()
        left, top = round(box.x0), round(self.figure.bbox.height - box.y1)
        height, width = image.shape[:2]
        if (round(box.width), round(box.height)) != (width, height):
            raise ValueError(
                _(
                    "image: expected the axes' {rows} x {columns} pixels; got {height} x {width}"
                ).format(
                    rows=round(box.height), columns=round(box.width), height=height, width=width
                )
            )
        canvas = np.asarray(self.canvas.buffer_rgba())
        canvas[top : top + height, left : left + width, :3] = image
        canvas[top : top + height, left : left + width, 3] = 255

    def invalidate(self) -> None:
        """Forget the cached background; the next :meth:`render_moving` redraws it."""
        self._background = None
        self._replays.clear()
        self._browser_draws = None
        self._backdrop_sent = False
        self._command_replays.clear()

    def _draw_background(self) -> None:
        self.canvas.draw()  # skips animated artists
        self._background = self.canvas.copy_from_bbox(self.figure.bbox)
        self._backdrop_sent = False

    def _encoded(self) -> bytes:
        """The canvas as it stands, encoded in the picture's format."""
        # The figure is opaque: its alpha channel is 255 everywhere, and is dropped.
        pixels = np.asarray(self.canvas.buffer_rgba())[..., :3]
        if self.image.format == "jpeg":
            buffer = io.BytesIO()
            PILImage.fromarray(pixels).save(
                buffer, format="jpeg", quality=self.JPEG_QUALITY, subsampling=0
            )
            return buffer.getvalue()
        return png_bytes(pixels)

    def publish(self) -> bytes:
        """Encode the canvas as it stands into the picture; return the encoded bytes."""
        encoded = self._encoded()
        self.image.value = encoded
        self._shown = np.array(self.canvas.buffer_rgba())
        self._backdrop_sent = False  # picture.js drops its backdrop with a new picture
        return encoded

    def publish_drawing(self, artists: list) -> bool:
        """Send the browser ``artists`` as drawing commands, to draw over the still background.

        One message ``{"kind": "drawing"}`` whose buffers are the commands
        (a JSON list, UTF-8) and their vertices and codes
        (:mod:`course.widgets.browser_drawing`); the first after the
        background was drawn anew also carries it (``"backdrop": true``, its
        encoded picture as the first buffer). The commands travel as a
        buffer, not in the message's content: ipykernel would copy and check
        every number of the content in Python (``json_clean``), which took
        longer than the drawing.
        Nothing is drawn with Agg, so a step costs what matplotlib takes to
        lay the artists out; a step whose commands are the last ones sends
        nothing. Returns False, having sent nothing, when an
        artist holds something the browser cannot draw as Agg does: then
        :meth:`render_moving` draws with Agg until :meth:`invalidate`.
        """
        renderer = self.canvas.get_renderer()
        if self._recorder is None or self._recorder.agg is not renderer:
            self._recorder = CommandRecorder(renderer)
        recorder = self._recorder
        recorder.start()
        replays = self._command_replays
        try:
            for artist in artists:
                if _empty_line(artist):
                    continue
                replay = replays.get(artist)
                if replay is not None and replay.draw(recorder):
                    continue
                if isinstance(artist, Line2D):  # matplotlib's calls, replayed at later steps
                    replays[artist] = _LineReplay.record(artist, recorder)
                else:
                    artist.draw(recorder)
        except NotDrawable:
            self._browser_draws = False
            return False
        self._browser_draws = True
        commands, geometry = recorder.finish()
        buffers = [json.dumps(commands, separators=(",", ":")).encode(), *geometry]
        # Sent only with a background in hand: _draw_background and invalidate clear it.
        if self._backdrop_sent and buffers == self._drawn:
            return True  # the browser shows it already
        self._drawn = buffers
        content: dict[str, Any] = {"kind": "drawing"}
        buffers = list(buffers)
        if not self._backdrop_sent:
            if self._background is None:
                self._draw_background()
            else:
                self.canvas.restore_region(self._background)
            content["backdrop"] = True
            buffers.insert(0, self._encoded())
            self._backdrop_sent = True
        if self.awaited:
            content["drawn"], self.awaited = True, False
        self.image.send(content, buffers=buffers)
        # The browser no longer shows the canvas's last picture: no patch can follow it.
        self._shown = None
        return True

    def publish_patches(self) -> bool:
        """Send the browser only the rectangles that changed since what it shows.

        A drag moves a few lines under a title: encoding the whole picture at
        every step costs more than drawing it. The changed pixels are found by
        comparing with the pixels the browser holds; the rows that changed are
        grouped into bands (split where :data:`PATCH_GAP` rows or more did not
        change), each band cut to its changed columns and sent as an RGB PNG in one
        message ``{"kind": "patch", "rectangles": [[left, top, width, height],
        ...]}`` with one buffer per rectangle, which ``picture.js`` paints over
        its picture. ``value`` keeps the last whole picture: the drag's end
        publishes it. Returns False, having sent nothing, when a patch cannot
        stand for the picture: no whole picture published yet, or JPEG.
        """
        if self._shown is None or self.image.format != "png":
            return False
        current = np.asarray(self.canvas.buffer_rgba())
        if current.shape != self._shown.shape:
            return False
        changed = _as_words(current) != _as_words(self._shown)
        rectangles, buffers = [], []
        for top, bottom in _bands(np.flatnonzero(changed.any(axis=1)), PATCH_GAP):
            columns = np.flatnonzero(changed[top:bottom].any(axis=0))
            left, right = int(columns[0]), int(columns[-1]) + 1
            rectangles.append([left, top, right - left, bottom - top])
            buffers.append(png_bytes(_opaque_rgb(current[top:bottom, left:right])))
            self._shown[top:bottom, left:right] = current[top:bottom, left:right]
        if rectangles:
            content = {"kind": "patch", "rectangles": rectangles}
            if self.awaited:
                content["drawn"], self.awaited = True, False
            self.image.send(content, buffers=buffers)
        return True


#: Unchanged rows that split a patch in two: fewer cost more in messages than they save.
PATCH_GAP = 12


def _opaque_rgb(pixels: np.ndarray) -> np.ndarray:
    """(H, W, 4) uint8 pixels of an opaque picture as (H, W, 3): its alpha is 255 throughout.

    Pillow drops the alpha channel at the speed of a copy, where numpy copies
    three bytes of four one pixel at a time; zlib then has a quarter less to
    read, which pays for the copy, and a patch is 9% smaller.

    >>> _opaque_rgb(np.full((1, 2, 4), 7, dtype=np.uint8)).shape
    (1, 2, 3)
    """
    height, width = pixels.shape[:2]
    rgba = PILImage.frombuffer(
        "RGBA", (width, height), np.ascontiguousarray(pixels), "raw", "RGBA", 0, 1
    )
    return np.asarray(rgba.convert("RGB"))


def _as_words(pixels: np.ndarray) -> np.ndarray:
    """(H, W, 4) uint8 pixels as (H, W) 32-bit words: one comparison per pixel."""
    return np.ascontiguousarray(pixels).view(np.uint32)[..., 0]


def _bands(rows: np.ndarray, gap: int) -> list[tuple[int, int]]:
    """Sorted row indices as [top, bottom) bands, split where ``gap`` or more rows are missing.

    >>> _bands(np.array([2, 3, 4, 30, 31]), 12)
    [(2, 5), (30, 32)]
    >>> _bands(np.array([], dtype=int), 12)
    []
    """
    if len(rows) == 0:
        return []
    splits = np.flatnonzero(np.diff(rows) > gap)
    starts = [int(rows[0]), *(int(rows[i + 1]) for i in splits)]
    ends = [*(int(rows[i]) + 1 for i in splits), int(rows[-1]) + 1]
    return list(zip(starts, ends, strict=True))


# Matplotlib 3.11's FreeType render mode; older releases draw text their own way, uncached.
_RENDER_NORMAL = getattr(getattr(ft2font, "RenderMode", None), "NORMAL", None)


class _GlyphCache:
    """Agg's text drawing with each glyph's bitmap rendered once, then reused.

    Matplotlib 3.11 asks FreeType for every glyph of a text at every draw; a
    drag redraws the title of lesson 01's app (41 glyphs, its numbers new at
    each step) and a point's label, which cost half the drawing. FreeType's
    bitmap of a glyph depends on its font, size, flags and the position's
    fraction of a pixel (in 1/64ths) only: moved by whole pixels, it is the
    same bitmap, so a cached copy painted at the new place gives exactly the
    pixels Agg draws (the tests compare them). Rotated, slanted, stretched,
    aliased and mathtext text goes to Agg's own method unchanged, as does
    everything on a matplotlib without this private method.
    """

    def __init__(self, renderer: Any, original: Any) -> None:
        self.renderer, self.original = renderer, original
        self.bitmaps: dict[tuple, tuple[np.ndarray, int, int]] = {}

    @classmethod
    def install(cls, renderer: Any) -> None:
        """Route ``renderer``'s glyph drawing through a cache, once, where matplotlib allows."""
        original = getattr(renderer, "_draw_text_glyphs_and_boxes", None)
        if original is None or isinstance(original, cls) or _RENDER_NORMAL is None:
            return
        renderer._draw_text_glyphs_and_boxes = cls(renderer, original)
        renderer.draw_text = _LayoutCache(renderer, renderer.draw_text)

    def __call__(self, gc: Any, x: float, y: float, angle: float, glyphs: Any, boxes: Any) -> None:
        glyphs = list(glyphs)
        plain = all(glyph[3] == 0 and glyph[4] == 1 for glyph in glyphs)  # no slant, no stretch
        if angle != 0 or boxes or not gc.get_antialiased() or not plain:
            self.original(gc, x, y, angle, glyphs, boxes)
            return
        flags = backend_agg.get_hinting_flag()
        renderer = self.renderer
        height = renderer.height
        pieces = []  # (bitmap, left column, top row) per glyph
        for font, size, glyph_index, _slant, _extend, dx, dy in glyphs:  # dy is upwards
            # The glyph's origin in FreeType's 26.6 fixed point, y upwards, as Agg places it.
            origin_x = round(0x40 * (x + dx))
            origin_y = round(0x40 * (height - y + dy))
            key = (font.fname, size, renderer.dpi, glyph_index, flags, origin_x % 64, origin_y % 64)
            cached = self.bitmaps.get(key)
            if cached is None:
                font.set_size(size, renderer.dpi)
                font._set_transform([[0x10000, 0], [0, 0x10000]], [origin_x, origin_y])
                bitmap = font._render_glyph(glyph_index, flags, _RENDER_NORMAL)
                cached = (
                    np.array(bitmap.buffer),
                    bitmap.left - (origin_x >> 6),
                    bitmap.top - (origin_y >> 6),
                )
                self.bitmaps[key] = cached
            buffer, left, top = cached
            pieces.append((buffer, (origin_x >> 6) + left, int(height) - ((origin_y >> 6) + top)))
        # One call into Agg for the whole text where no two glyphs' inked pixels meet
        # (each call converts the graphics context anew: a tenth of a millisecond for
        # B(t)'s numbers); where they do, Agg blends each glyph over the last, as it does.
        merged = _merged_bitmaps(pieces) if len(pieces) > 1 else None
        for buffer, left, top in [merged] if merged is not None else pieces:
            # draw_text_image's y is downwards, at the bitmap's bottom side.
            renderer._renderer.draw_text_image(buffer, left, top + buffer.shape[0], 0, gc)


def _merged_bitmaps(
    pieces: list[tuple[np.ndarray, int, int]],
) -> tuple[np.ndarray, int, int] | None:
    """Glyph bitmaps placed at (left, top) as one bitmap; None if two inked pixels meet.

    Agg leaves a pixel a bitmap does not cover (0) as it is, so one bitmap of
    glyphs that share no inked pixel paints what painting them one by one does.

    >>> dot = np.full((1, 1), 200, dtype=np.uint8)
    >>> image, left, top = _merged_bitmaps([(dot, 3, 5), (dot, 5, 6)])
    >>> image.tolist(), left, top
    ([[200, 0, 0], [0, 0, 200]], 3, 5)
    >>> _merged_bitmaps([(dot, 3, 5), (dot, 3, 5)]) is None
    True
    """
    left = min(piece[1] for piece in pieces)
    top = min(piece[2] for piece in pieces)
    right = max(piece[1] + piece[0].shape[1] for piece in pieces)
    bottom = max(piece[2] + piece[0].shape[0] for piece in pieces)
    image = np.zeros((bottom - top, right - left), dtype=np.uint8)
    for buffer, column, row in pieces:
        height, width = buffer.shape
        region = image[row - top : row - top + height, column - left : column - left + width]
        if np.logical_and(region, buffer).any():
            return None
        region |= buffer
    return image, left, top


class _LayoutCache:
    """Agg's ``draw_text`` with each text's glyph layout computed once, then reused.

    Matplotlib 3.11 lays a text out anew (shaping it, loading and hinting
    every glyph) at every draw: a quarter of a millisecond for a point's
    label "P1", which a drag redraws at every step. The layout (which glyphs
    of which font, at which offsets from the text's origin) depends on the
    string, the font, its size, the resolution and the hinting only, not on
    where the text stands, so the cached one is the one Agg computes (the
    tests compare the pixels). Mathtext and anything with font features or
    a language go to Agg unchanged. At most :attr:`SIZE` layouts are kept.

    A drag shows new numbers at every step ("(355.0, 213.8)" takes Agg a
    millisecond to lay out): a string of :data:`COMPOSABLE` characters is
    laid out from the layouts of its pairs of neighbours, each computed
    once. Shaping such a string moves each glyph by its predecessor's
    advance and their pair's kerning, which is what the pair's layout holds;
    the sums are of multiples of 1/64 pixel, exact in floating point (the
    tests compare with Agg's layout of every pair and of random strings).
    """

    SIZE = 256
    #: Numbers and what surrounds them: no ligatures, nothing shaped beyond a pair.
    COMPOSABLE = frozenset("0123456789.,-+() ")

    def __init__(self, renderer: Any, original: Any) -> None:
        self.renderer, self.original = renderer, original
        self.layouts: dict[tuple, list[tuple]] = {}
        self.pairs: dict[tuple, tuple | None] = {}

    def __call__(
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
        plain = mtext is None or (mtext.get_fontfeatures() is None and mtext.get_language() is None)
        if ismath or not plain:
            self.original(gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)
            return
        renderer = self.renderer
        font = renderer._prepare_font(prop)  # the font list rcParams give now, sized
        size = prop.get_size_in_points()
        flags = backend_agg.get_hinting_flag()
        key = (font, s, size, renderer.dpi, flags)
        glyphs = self.layouts.get(key)
        if glyphs is None:
            glyphs = self._composed(font, s, size, flags)
            if glyphs is None:
                glyphs = [
                    (item.ft_object, size, item.glyph_index, 0, 1, item.x, item.y)
                    for item in font._layout(s, flags=flags)
                ]
            if len(self.layouts) >= self.SIZE:
                self.layouts.clear()
            self.layouts[key] = glyphs
        renderer._draw_text_glyphs_and_boxes(gc, x, y, angle, glyphs, [])

    def _composed(self, font: Any, s: str, size: float, flags: Any) -> list[tuple] | None:
        """The layout of ``s`` from its pairs' layouts; None unless every pair is plain."""
        if len(s) < 2 or not self.COMPOSABLE.issuperset(s):
            return None
        glyphs, x, previous = [], 0.0, None
        for index in range(len(s) - 1):
            pair = self._pair(font, s[index : index + 2], size, flags)
            if pair is None or (previous is not None and previous != pair[0]):
                return None  # a pair shaped into something else: Agg lays the string out
            glyphs.append((*pair[0], 0, 1, x, 0.0))
            x += pair[2]
            previous = pair[1]
        glyphs.append((*previous, 0, 1, x, 0.0))
        return glyphs

    def _pair(self, font: Any, pair: str, size: float, flags: Any) -> tuple | None:
        """((font, size, glyph), (font, size, glyph), advance) of a two-glyph layout, or None."""
        key = (font, pair, size, self.renderer.dpi, flags)
        if key not in self.pairs:
            items = font._layout(pair, flags=flags)
            plain = len(items) == 2 and items[0].x == 0 and items[0].y == 0 and items[1].y == 0
            self.pairs[key] = (
                (
                    (items[0].ft_object, size, items[0].glyph_index),
                    (items[1].ft_object, size, items[1].glyph_index),
                    items[1].x,
                )
                if plain
                else None
            )
        return self.pairs[key]


class FixedText(Text):
    """A one-line text that stays where it stands while its characters change: numbers.

    ``Text.draw`` measures every new string to place it, and FreeType lays
    it out and hints its glyphs to do so (a millisecond for "(355.0,
    213.8)"), though a left-aligned text only moves when its ascent or
    descent do. Those of a string are the largest of its characters' (its
    box is the union of theirs), so a string of characters measured once
    needs no measuring: it is drawn where ``Text.draw`` puts the first
    string with the same ascent and descent, by the call ``Text.draw``
    makes. Anything else (rotated, centred, several lines, mathtext, a box,
    path effects) is drawn by ``Text.draw``.

    Examples
    --------
    >>> view = FigureView(shape=(30, 100))
    >>> numbers = view.figure.add_artist(FixedText(0.05, 0.3, "(3.5, -2.0)", animated=True))
    >>> _ = view.render_moving([numbers])
    >>> numbers.set_text("(41.0, 7.5)")
    >>> _ = view.render_moving([numbers])
    >>> bool((view.pixels()[..., 0] < 128).any()), len(numbers._origins)
    (True, 1)
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._extents: dict[tuple, tuple[float, float]] = {}
        self._origins: dict[tuple, tuple[float, float]] = {}

    def draw(self, renderer: Any) -> None:
        text = self.get_text()
        plain = (
            renderer is not None
            and self.get_visible()
            and text
            and "\n" not in text
            and self.get_rotation() == 0
            and self.get_horizontalalignment() == "left"
            and not self.get_usetex()
            and not self.get_wrap()
            and self._bbox_patch is None
            and not self.get_path_effects()
            and not self._preprocess_math(text)[1]
        )
        origin = self._origin(renderer, text) if plain else None
        if origin is None:
            super().draw(renderer)
            return
        self._renderer = renderer
        renderer.open_group("text", self.get_gid())
        gc = renderer.new_gc()  # set up as Text.draw sets it up
        gc.set_foreground(mcolors.to_rgba(self.get_color()), isRGBA=True)
        gc.set_alpha(self.get_alpha())
        gc.set_url(self._url)
        gc.set_antialiased(self._antialiased)
        gc.set_snap(self.get_snap())
        self._set_gc_clip(gc)
        renderer.draw_text(
            gc, *origin, text, self._fontproperties, self.get_rotation(), ismath=False, mtext=self
        )
        gc.restore()
        renderer.close_group("text")
        self.stale = False

    def _origin(self, renderer: Any, text: str) -> tuple[float, float] | None:
        """Where Text.draw would draw ``text``: measured for its ascent and descent once."""
        place = (
            id(renderer),
            renderer.dpi,
            hash(self._fontproperties),
            renderer.get_canvas_width_height(),
            self._x,
            self._y,
            self.get_verticalalignment(),
            tuple(self.get_transform().get_matrix().ravel()),
        )
        ascent = descent = 0.0
        for character in set(text):
            key = (place[:3], character)
            if key not in self._extents:
                _, height, down = renderer.get_text_width_height_descent(
                    character, self._fontproperties, False
                )
                self._extents[key] = (height - down, down)
            up, down = self._extents[key]
            ascent, descent = max(ascent, up), max(descent, down)
        key = (*place, ascent, descent)
        if key not in self._origins:
            _, height, down = renderer.get_text_width_height_descent(
                text, self._fontproperties, False
            )
            if (height - down, down) != (ascent, descent):
                return None  # not the union of its characters' boxes: measured by Text.draw
            # Text.draw's own arithmetic, on this text's layout.
            _, info, _ = self._get_layout(renderer)
            x, y = info[0][2]
            posx, posy = self.get_transform().transform(
                (float(self.convert_xunits(self._x)), float(self.convert_yunits(self._y)))
            )
            x, y = x + posx, y + posy
            if renderer.flipy():
                y = renderer.get_canvas_width_height()[1] - y
            self._origins[key] = (x, y)
        return self._origins[key]


class _Recorder:
    """A renderer that draws as ``renderer`` does and keeps the calls that draw paths."""

    def __init__(self, renderer: Any) -> None:
        self._renderer = renderer
        self.calls: list[tuple] = []

    def __getattr__(self, name: str) -> Any:
        return getattr(self._renderer, name)

    def draw_path(self, gc: Any, path: Any, transform: Any, rgbFace: Any = None) -> None:
        self.calls.append(("path", gc, path, transform, rgbFace))
        self._renderer.draw_path(gc, path, transform, rgbFace)

    def draw_markers(
        self,
        gc: Any,
        marker_path: Any,
        marker_trans: Any,
        path: Any,
        trans: Any,
        rgbFace: Any = None,
    ) -> None:
        self.calls.append(("markers", gc, marker_path, marker_trans, path, trans, rgbFace))
        self._renderer.draw_markers(gc, marker_path, marker_trans, path, trans, rgbFace)


def _line_style(line: Line2D) -> tuple:
    """What a line's Agg calls depend on besides its data: a change means a new recording."""
    return (
        line.get_visible(),
        str(line.get_color()),
        line.get_linewidth(),
        line.get_linestyle(),
        str(line.get_marker()),
        line.get_markersize(),
        str(line.get_markerfacecolor()),
        str(line.get_markeredgecolor()),
        line.get_markeredgewidth(),
        line.get_alpha(),
        line.get_antialiased(),
        line.get_clip_on(),
        id(line.get_transform()),
    )


class _LineReplay:
    """A moving line drawn by replaying its Agg calls with new data.

    ``Line2D.draw`` spends three quarters of its time in Python (unit
    conversion, transform bookkeeping, a graphics context set up property by
    property) for one or two calls into Agg: a drag of lesson 01's P1
    redraws seven lines at every step. :meth:`record` draws the line as
    matplotlib does through a :class:`_Recorder`; :meth:`draw` then makes
    the same calls, with the same graphics contexts and transforms, on a
    path built from the line's new data exactly as ``Line2D.recache`` builds
    it, so Agg gets the same input a full draw gives it. A line is recorded
    only where that holds: affine transforms (the path goes to Agg as it
    is), the default draw style, no mark-every, gap colour, sketch, path
    effects, filter or rasterization; and :meth:`draw` refuses (returns
    False) once the line's style differs from the recorded. A new view
    (limits, axes moved) comes with :meth:`FigureView.invalidate`, as the
    cached background needs it too, and that drops every recording.
    """

    def __init__(self, line: Line2D, calls: list[tuple], style: tuple) -> None:
        self.line, self.calls, self.style = line, calls, style

    @classmethod
    def record(cls, line: Line2D, renderer: Any) -> _LineReplay | None:
        """Draw ``line`` into ``renderer``; return its replay, or None if it cannot have one."""
        plain = (
            line.get_drawstyle() == "default"
            and line.get_markevery() is None
            and line.get_gapcolor() is None
            and line.get_sketch_params() is None
            and not line.get_path_effects()
            and not line.get_rasterized()
            and line.get_agg_filter() is None
        )
        if not plain:
            line.draw(renderer)
            return None
        style = _line_style(line)
        recorder = _Recorder(renderer)
        line.draw(recorder)
        data = line._path  # built by the draw's recache
        calls = []
        for call in recorder.calls:
            path = call[2] if call[0] == "path" else call[4]
            if path.vertices is not data.vertices or path.codes is not None:
                return None  # transformed or cut on the way to Agg: not this line's data
            if call[0] == "path" and path is not data:
                return None
            calls.append(call)
        return cls(line, calls, style) if calls else None

    def draw(self, renderer: Any) -> bool:
        """Draw the line with its current data as its recorded draw would; False if it cannot."""
        line = self.line
        if _line_style(line) != self.style:
            return False
        if line._invalidx or line._invalidy:  # as Line2D.draw: the path from the new data
            line.recache()
        path = line._path
        if len(path.vertices) == 0 or line._subslice:
            return False
        for call in self.calls:
            if call[0] == "path":
                _, gc, _, transform, face = call
                renderer.draw_path(gc, path, transform, face)
            else:
                _, gc, marker_path, marker_trans, _, trans, face = call
                points = MatplotlibPath._fast_from_codes_and_verts(path.vertices, None, path)
                renderer.draw_markers(gc, marker_path, marker_trans, points, trans, face)
        line.stale = False
        return True


def _empty_line(artist: Any) -> bool:
    return isinstance(artist, Line2D) and len(artist.get_xdata(orig=True)) == 0


def pixel_axes(figure: Figure, left: int, bottom: int, width: int, height: int) -> Axes:
    """Axes placed in whole picture pixels: ``left``, ``bottom`` from the figure's corner."""
    columns, rows = figure.bbox.width, figure.bbox.height
    return figure.add_axes((left / columns, bottom / rows, width / columns, height / rows))


class PixelPanel:
    """An image shown at a whole zoom, ``zoom`` x ``zoom`` screen pixels per image pixel.

    Like ``imshow(values, cmap, vmin, vmax, interpolation="nearest")`` in
    ``axes``, but the coloured pixels are written into the picture as they
    are (:meth:`FigureView.render_moving`), which costs a tenth of
    matplotlib's resampling; artists drawn in ``axes`` (grid lines, curves)
    come on top. The axes' data coordinates are the image's, y down.
    ``cmap`` is a colormap name or a ``Colormap``; an (H, W, 3) image in
    [0, 1] is shown as RGB.
    """

    def __init__(
        self,
        app: Any,
        axes: Axes,
        shape: tuple[int, int],
        zoom: int,
        cmap: Any = "gray",
        vmin: float = 0.0,
        vmax: float = 1.0,
    ) -> None:
        height, width = shape
        self.app, self.axes, self.zoom = app, axes, zoom
        self.colormap = matplotlib.colormaps[cmap] if isinstance(cmap, str) else cmap
        self.vmin, self.vmax = vmin, vmax
        axes.set_xlim(0, width)
        axes.set_ylim(height, 0)
        self.values = np.zeros(shape)

    def set_data(self, values: Any) -> None:
        self.values = np.asarray(values)
        if self.values.ndim == 3:  # RGB in [0, 1], as imshow shows it: 255 times, truncated
            pixels = (np.clip(self.values, 0.0, 1.0) * 255).astype(np.uint8)
        else:
            scaled = (self.values - self.vmin) / (self.vmax - self.vmin)
            pixels = self.colormap(scaled, bytes=True)[..., :3]
        zoomed = np.repeat(np.repeat(pixels, self.zoom, axis=0), self.zoom, axis=1)
        self.app.pixel_images[self.axes] = zoomed

    def get_array(self) -> np.ndarray:
        return self.values


class Still:
    """A finished picture for a notebook: shown as an image, its text form is its caption.

    What the lessons' figure functions return: the picture is drawn once, by
    the library, so a notebook needs no plotting code; the caption is stable
    text for the notebook's checks (nbval compares it, not the pixels).
    ``data`` is PNG, or JPEG for a photograph.
    """

    def __init__(self, data: bytes, caption: str) -> None:
        self.data = data
        self.caption = caption

    @property
    def png(self) -> bytes | None:
        """The PNG bytes, or None for a JPEG still."""
        return self.data if self.data.startswith(b"\x89PNG") else None

    @classmethod
    def of(cls, figure: Figure, caption: str) -> Still:
        """Render ``figure`` on the Agg canvas as it is sized, without trimming."""
        buffer = io.BytesIO()
        FigureCanvasAgg(figure).print_png(buffer)
        return cls(buffer.getvalue(), caption)

    def _repr_png_(self) -> bytes | None:
        return self.png

    def _ipython_display_(self) -> None:
        """In a notebook: the picture, then its caption as a line a student can read.

        JupyterLab and Voila show only a picture's richest form, so a caption kept as
        its text form alone is never seen, and the lessons' text quotes it. The
        picture keeps the caption as its text form too: the website's alt text.
        """
        kind = "image/png" if self.png is not None else "image/jpeg"
        encoded = base64.b64encode(self.data).decode("ascii")
        display({kind: encoded, "text/plain": self.caption}, raw=True)
        print(self.caption)

    def _repr_jpeg_(self) -> bytes | None:
        return None if self.png is not None else self.data

    def __repr__(self) -> str:
        return self.caption


def pixel_figure(
    windows: list[tuple[np.ndarray, tuple[int, int, int, int], str]],
    zoom: int,
    legend: list[tuple[str, str]] | None = None,
    gap: int = 18,
    title_height: int = 34,
    legend_height: int = 26,
    reserve_left: int = 0,
    reserve_right: int = 0,
) -> tuple[Figure, list[Axes]]:
    """Side-by-side pixel views at a whole zoom: each image pixel is ``zoom`` x ``zoom``.

    ``windows`` holds (image, extent, title) per panel: an (h, w, 3) RGB or
    (h, w) gray crop in [0, 1] with its extent ``(left, right, bottom,
    top)`` in image coordinates (:func:`course.raster.canvas.crop`). Every axes is
    placed in whole picture pixels and exactly ``zoom`` times its crop, so
    nearest sampling draws each pixel as a flat square with nothing
    resampled. ``legend`` adds (colour, label) patches above the panels;
    ``reserve_left`` and ``reserve_right`` leave that many picture pixels
    free at either side, for another panel or a colour bar. Returns the
    figure and the axes, in data coordinates of the image (y down), to draw
    marks on.
    """
    # The one check here: every lesson figure passes its caller's zoom straight on.
    zoom = as_int(zoom, "zoom", minimum=1, maximum=limits.MAX_ZOOM)
    widths = [window.shape[1] * zoom for window, _, _ in windows]
    heights = [window.shape[0] * zoom for window, _, _ in windows]
    top = title_height + (legend_height if legend else 0)
    columns = reserve_left + sum(widths) + gap * (len(windows) + 1) + reserve_right
    rows = max(heights) + top + gap // 2
    if columns * rows > limits.MAX_FIGURE_PIXELS:
        raise ValueError(
            _(
                "windows at zoom {zoom} make a {columns} x {rows} picture, more than the "
                "{most} pixels allowed: crop smaller windows or zoom less"
            ).format(zoom=zoom, columns=columns, rows=rows, most=limits.MAX_FIGURE_PIXELS)
        )
    figure = Figure(figsize=(columns / 100, rows / 100), dpi=100)
    axes_list = []
    left = reserve_left + gap
    for (window, extent, title), width, height in zip(windows, widths, heights, strict=True):
        axes = pixel_axes(figure, left, rows - top - height, width, height)
        cmap = "gray" if window.ndim == 2 else None
        axes.imshow(window, extent=extent, interpolation="nearest", cmap=cmap, vmin=0, vmax=1)
        axes.set_xlim(extent[0], extent[1])
        axes.set_ylim(extent[2], extent[3])
        bare_axes(axes)
        axes.set_title(title, fontsize=9)
        axes_list.append(axes)
        left += width + gap
    if legend:
        figure.legend(
            handles=[
                Patch(facecolor=colour, edgecolor="0.5", label=label) for colour, label in legend
            ],
            loc="upper center",
            ncols=len(legend),
            fontsize=8,
            frameon=False,
        )
    return figure, axes_list
