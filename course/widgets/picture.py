"""A lesson's pictures: the widget an app's picture is shown in, stills, pixels as they are.

:class:`Picture` is the widget: the encoded picture the kernel draws, and the
student's pointer on it (its browser half is ``picture.js``); a
:class:`~course.widgets.figure_view.FigureView` renders a matplotlib figure
into it, and :func:`png_bytes` is the fast PNG encoder a picture redrawn at
every step of a drag needs. :class:`Still` is a finished picture for a
notebook. :func:`pixel_figure` and :func:`pixel_axes` place axes in whole
picture pixels, and :class:`PixelPanel` shows an image at a whole zoom by
writing its pixels into the canvas, without matplotlib's resampling.

The building blocks of the apps and the lessons' figures (a picture widget,
stills, pixel panels): the apps and figures, which validate their own
arguments, are their only callers, so this module checks no input
(``UNCHECKED = True``; the fuzz test skips it), but for :func:`pixel_figure`'s
``zoom``, which every lesson figure passes on from its own caller.
"""

from __future__ import annotations

import base64
import io
import struct
import zlib
from pathlib import Path
from typing import Any

import anywidget
import matplotlib
import numpy as np
import traitlets
from IPython.display import display
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Patch

from course import limits
from course._validate import as_int, describe
from course.i18n import _

__all__ = [
    "GRAY_PIXELS",
    "Picture",
    "PixelPanel",
    "Still",
    "ZoomedPixels",
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
    ``course.widgets.figure_view._opaque_rgb`` first (numpy copies three
    bytes of four slowly).

    Examples
    --------
    >>> from PIL import Image as PILImage
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
    true}`` message of changed rectangles
    (:meth:`~course.widgets.figure_view.FigureView.publish_patches`), which
    says both at once (each message is one more for the kernel, the server
    and the browser to pass on at every step of a drag).
    """

    _esm = (Path(__file__).parent / "picture.js").read_text(encoding="utf-8")
    value = traitlets.Bytes(b"").tag(sync=True)
    format = traitlets.Unicode("png").tag(sync=True)
    width = traitlets.Int(0).tag(sync=True)
    height = traitlets.Int(0).tag(sync=True)
    handles = traitlets.List([]).tag(sync=True)
    clickable = traitlets.Bool(False).tag(sync=True)


def pixel_axes(figure: Figure, left: int, bottom: int, width: int, height: int) -> Axes:
    """Axes placed in whole picture pixels: ``left``, ``bottom`` from the figure's corner."""
    columns, rows = figure.bbox.width, figure.bbox.height
    return figure.add_axes((left / columns, bottom / rows, width / columns, height / rows))


class ZoomedPixels:
    """An image's pixels, (h, w, 3) uint8, each shown as ``zoom`` x ``zoom`` picture pixels.

    What a :class:`PixelPanel` leaves in its app's ``pixel_images``: Agg's
    canvas gets it zoomed (:meth:`zoomed`), and during a drag the browser
    gets the pixels as they are and zooms them itself, a step's pixels a
    ``zoom``-squared of the zoomed image's. ``at`` is the picture pixel
    (column, row) of its top-left corner from the axes' own: a window
    into the axes, over the still picture there
    (:attr:`~course.widgets.figure_view.FigureView.still_images`), when
    only that window changes from step to step (lesson 08's clone).

    >>> ZoomedPixels(np.zeros((2, 3, 3), dtype=np.uint8), 4).shape
    (8, 12, 3)
    """

    def __init__(self, pixels: np.ndarray, zoom: int, at: tuple[int, int] = (0, 0)) -> None:
        self.pixels, self.zoom = np.ascontiguousarray(pixels, dtype=np.uint8), zoom
        self.at = at

    @property
    def shape(self) -> tuple[int, int, int]:
        height, width = self.pixels.shape[:2]
        return height * self.zoom, width * self.zoom, 3

    def zoomed(self) -> np.ndarray:
        """The (h * zoom, w * zoom, 3) pixels the picture shows."""
        return np.repeat(np.repeat(self.pixels, self.zoom, axis=0), self.zoom, axis=1)


class PixelPanel:
    """An image shown at a whole zoom, ``zoom`` x ``zoom`` screen pixels per image pixel.

    Like ``imshow(values, cmap, vmin, vmax, interpolation="nearest")`` in
    ``axes``, but the coloured pixels are written into the picture as they
    are (:meth:`~course.widgets.figure_view.FigureView.render_moving`),
    which costs a tenth of matplotlib's resampling; artists drawn in
    ``axes`` (grid lines, curves) come on top. The axes' data coordinates
    are the image's, y down. ``cmap`` is a colormap name or a ``Colormap``;
    an (H, W, 3) image in [0, 1] is shown as RGB.
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
        self.app.pixel_images[self.axes] = ZoomedPixels(pixels, self.zoom)

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
