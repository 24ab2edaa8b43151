"""How the lesson modules draw their key pictures and place their landmarks.

A lesson's registry entry (:mod:`course.classroom.registry`) holds pictures,
each a function returning PNG bytes, and landmark functions, each naming
pixels of an app's picture whose colour the library determines. These are
their tools: an app or a figure as a PNG, a preview for the course map, a
point in data coordinates as a pixel of an app's picture, a value as the
colour a colormap shows, and the share of pixels that two pictures disagree on.

Classroom tooling for the course's authors and its browser tests: its
inputs come from the lesson registry, never from a student, so this module
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import io
from collections.abc import Callable
from typing import Any

import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image as PILImage

from course.antialias.coverage import segment_distance
from course.classroom.registry import Landmark, Picture
from course.i18n import _
from course.widgets.base import SliderApp
from course.widgets.picture import Still

__all__ = [
    "BLACK",
    "CRIMSON",
    "DIFFERING_SHARE",
    "PIXEL_TOLERANCE",
    "WHITE",
    "app_picture",
    "clear_point",
    "colormap_color",
    "differing_share",
    "figure_picture",
    "gray_color",
    "landmark_at",
    "landmark_in_box",
    "preview",
    "read_only",
    "rgb_color",
    "segments_of",
    "thumbnail",
]

UNCHECKED = True  # see the module docstring

BLACK, WHITE = (0, 0, 0), (255, 255, 255)

CRIMSON = (220, 20, 60)
# A picture shows what the library draws when at most DIFFERING_SHARE of its
# pixels differ by more than PIXEL_TOLERANCE in a channel (the kernel and the
# test run the same matplotlib; a wrong value moves whole artists).
PIXEL_TOLERANCE = 24
DIFFERING_SHARE = 0.001


def app_picture(app: SliderApp) -> bytes:
    """The picture an app shows for its current control values, as a PNG.

    A photographic app sends JPEG to the browser; its picture is encoded
    again here, losslessly, from the figure as drawn.
    """
    shown = app.refresh()
    if app.view.image.format == "png":
        return shown
    buffer = io.BytesIO()
    PILImage.fromarray(np.asarray(app.view.canvas.buffer_rgba())).save(buffer, format="png")
    return buffer.getvalue()


def still_picture(name: str, caption: str, draw: Callable[..., Still], *arguments: Any) -> Picture:
    """A registry picture drawn by a lesson's figure function, ``draw(*arguments)``."""
    return Picture(name, caption, lambda: draw(*arguments).data)


def panel_picture(app: SliderApp, axes: Any, pad: int = 6) -> bytes:
    """One panel of an app's picture, at full size, with its title and labels: a PNG.

    For the course map's previews: a single legible panel rather than the
    whole app shrunk. The panel is the axes' tight box (ticks, labels and
    title included) on the picture the app shows for its current values.
    """
    app.refresh()
    pixels = np.asarray(app.view.canvas.buffer_rgba())[..., :3]
    renderer = app.view.canvas.get_renderer()
    box = axes.get_tightbbox(renderer)
    height, width = pixels.shape[:2]
    left, right = max(0, int(box.x0) - pad), min(width, int(np.ceil(box.x1)) + pad)
    top, bottom = (
        max(0, int(height - box.y1) - pad),
        min(height, int(np.ceil(height - box.y0)) + pad),
    )
    buffer = io.BytesIO()
    PILImage.fromarray(np.ascontiguousarray(pixels[top:bottom, left:right])).save(buffer, "png")
    return buffer.getvalue()


def png_of_gray(image: Any) -> bytes:
    """A gray image in [0, 1] as a PNG, one pixel per pixel.

    Examples
    --------
    >>> PILImage.open(io.BytesIO(png_of_gray(np.zeros((3, 5))))).size
    (5, 3)
    """
    levels = np.round(np.clip(np.asarray(image, dtype=float), 0.0, 1.0) * 255).astype(np.uint8)
    buffer = io.BytesIO()
    PILImage.fromarray(levels).save(buffer, "png")
    return buffer.getvalue()


def figure_picture(figure: Figure) -> bytes:
    """A still figure as the notebook shows it inline: PNG, cropped to its content.

    Examples
    --------
    >>> figure = Figure(figsize=(1, 1), dpi=20)
    >>> _ = figure.add_subplot().plot([0, 1])
    >>> figure_picture(figure)[:8]
    b'\\x89PNG\\r\\n\\x1a\\n'
    """
    buffer = io.BytesIO()
    FigureCanvasAgg(figure)  # attach an Agg canvas: no pyplot, no backend switch
    figure.savefig(buffer, format="png", bbox_inches="tight")
    return buffer.getvalue()


def differing_share(picture: np.ndarray, expected: np.ndarray) -> float:
    """The share of pixels that differ by more than PIXEL_TOLERANCE in some channel.

    Examples
    --------
    >>> picture = np.zeros((2, 2, 3), dtype=int)
    >>> expected = picture.copy()
    >>> expected[0, 0, 1] = 200
    >>> differing_share(picture, expected)
    0.25
    """
    if picture.shape != expected.shape:
        raise ValueError(
            _(
                "picture: expected the shape of the library's picture {expected_shape}; got "
                "{picture_shape}"
            ).format(expected_shape=expected.shape, picture_shape=picture.shape)
        )
    differing = np.abs(picture.astype(int) - expected.astype(int)) > PIXEL_TOLERANCE
    return float(differing.any(axis=2).mean())


def thumbnail(png: bytes, columns: int) -> bytes:
    """A PNG scaled to ``columns`` pixels across (Lanczos, no aliasing), in 256 colours.

    A preview a few times smaller than the full picture, so that a notebook
    showing one per lesson stays small.

    Examples
    --------
    >>> buffer = io.BytesIO()
    >>> PILImage.new("RGB", (40, 20), "red").save(buffer, format="png")
    >>> PILImage.open(io.BytesIO(thumbnail(buffer.getvalue(), 10))).size
    (10, 5)
    """
    image = PILImage.open(io.BytesIO(png)).convert("RGB")
    rows = max(1, round(image.height * columns / image.width))
    small = image.resize((columns, rows), PILImage.Resampling.LANCZOS)
    buffer = io.BytesIO()
    small.quantize(256, method=PILImage.Quantize.MEDIANCUT).save(buffer, "png", optimize=True)
    return buffer.getvalue()


def preview(picture: Picture, columns: int | None = None) -> bytes:
    """A registered picture as a compact PNG (256 colours) for the course map.

    At its own width unless ``columns`` is given: a single-panel preview is
    legible only at full size.
    """
    png = picture.render()
    return thumbnail(png, columns or PILImage.open(io.BytesIO(png)).width)


def gray_color(value: float) -> tuple[int, int, int]:
    """The RGB colour of ``value`` in [0, 1] on a 0-1 gray scale (values outside are clipped).

    Examples
    --------
    >>> gray_color(0.5), gray_color(1.7)
    ((128, 128, 128), (255, 255, 255))
    """
    level = round(float(np.clip(value, 0.0, 1.0)) * 255)
    return (level, level, level)


def landmark_at(
    app: SliderApp, axes: Any, point: Any, color: tuple[int, int, int], what: str, tolerance=40
) -> Landmark:
    """The picture pixel where ``axes`` draws the data point ``point``.

    Matplotlib's display coordinates have y up from the figure's bottom;
    the picture's rows go down from its top, hence the flip.
    """
    x, y = axes.transData.transform(np.asarray(point, dtype=float))
    return _landmark(app, x, y, color, what, tolerance)


def _landmark(app: SliderApp, x: float, y: float, color, what: str, tolerance: int) -> Landmark:
    """The picture pixel that contains display point (x, y): pixel (r, c) spans [c, c + 1)."""
    row = int(np.floor(app.figure.bbox.height - y))
    return Landmark(what, row, int(np.floor(x)), color, tolerance)


def landmark_in_box(
    app: SliderApp,
    axes: Any,
    extent: tuple[float, float, float, float],
    point: Any,
    color: tuple[int, int, int],
    what: str,
    tolerance: int = 40,
) -> Landmark:
    """The picture pixel of ``point`` when ``axes`` shows exactly ``extent``, y down.

    For zoomed views: ``extent = (left, right, bottom, top)`` is the window
    the library says the axes must show (``course.raster.canvas.crop`` returns it),
    and the point is placed in the axes' box from that alone, not from the
    axes' own limits, so a view of the wrong window cannot pass.
    """
    left, right, bottom, top = (float(value) for value in extent)
    x, y = (float(value) for value in point)
    box = axes.get_window_extent()
    display_x = box.x0 + (x - left) / (right - left) * box.width
    display_y = box.y1 - (y - top) / (bottom - top) * box.height
    return _landmark(app, display_x, display_y, color, what, tolerance)


def colormap_color(name: str, value: float, low: float = 0.0, high: float = 1.0) -> tuple[int, ...]:
    """The RGB colour (0-255) of ``value`` on colormap ``name`` scaled from low to high.

    Examples
    --------
    >>> colormap_color("Greys", 0.0), colormap_color("Greys", 1.0)
    ((255, 255, 255), (0, 0, 0))
    """
    rgba = matplotlib.colormaps[name]((value - low) / (high - low), bytes=True)
    return tuple(int(channel) for channel in rgba[:3])


def rgb_color(value: Any) -> tuple[int, int, int]:
    """An RGB colour in [0, 1] as imshow shows it: 255 times, truncated to an integer.

    Examples
    --------
    >>> rgb_color([1.0, 0.5, -0.2])
    (255, 127, 0)
    """
    red, green, blue = (int(channel * 255) for channel in np.clip(value, 0.0, 1.0))
    return (red, green, blue)


def clear_point(column: int, row: int, segments: np.ndarray) -> tuple[float, float]:
    """The quarter point of pixel (column, row) farthest from ``segments`` (M, 2, 2).

    A pixel drawn as a flat square under a line (the true curve, the ideal
    line) shows its own colour there.

    Examples
    --------
    >>> clear_point(0, 0, np.array([[[0.0, 0.0], [1.0, 0.0]]]))  # a line along the top edge
    (0.25, 0.75)
    """
    offsets = np.array([[0.25, 0.25], [0.75, 0.25], [0.25, 0.75], [0.75, 0.75]])
    candidates = np.array([column, row]) + offsets
    distance, _, _ = segment_distance(
        candidates[:, :1], candidates[:, 1:], segments[None, :, 0], segments[None, :, 1]
    )
    x, y = candidates[int(np.argmax(distance.min(axis=1)))]
    return float(x), float(y)


def segments_of(polyline: np.ndarray) -> np.ndarray:
    """The segments (M - 1, 2, 2) between consecutive points of an (M, 2) polyline."""
    return np.stack([polyline[:-1], polyline[1:]], axis=1)


def read_only(array: np.ndarray) -> np.ndarray:
    """``array``, made read-only: a cached picture's data cannot be changed by a caller."""
    array.flags.writeable = False
    return array
