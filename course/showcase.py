"""How a lesson is shown outside its notebook: key pictures and checked slider moves.

The pieces of a :class:`course.lessons.Lesson` entry: a :class:`Picture`
(a PNG for the gallery and the course map), a :class:`SliderMove` (a slider
the browser tests move like a student) and the :class:`Landmark` pixels
whose colour the library determines for the value the slider then shows.
The helpers turn an app or a figure into a PNG and a point in data
coordinates into a pixel of an app's picture.
"""

from __future__ import annotations

import io
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import ipywidgets as widgets
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image as PILImage

from course.widgets.base import SliderApp

__all__ = [
    "CRIMSON",
    "DIFFERING_SHARE",
    "PIXEL_TOLERANCE",
    "Landmark",
    "Picture",
    "SliderMove",
    "app_picture",
    "differing_share",
    "figure_picture",
    "gray_color",
    "landmark_at",
    "landmark_in_box",
    "nearest_stop",
    "neighbour_value",
    "readout_shows",
    "slider_stops",
    "thumbnail",
    "value_after_keys",
]

CRIMSON = (220, 20, 60)
# A picture shows what the library draws when at most DIFFERING_SHARE of its
# pixels differ by more than PIXEL_TOLERANCE in a channel (the kernel and the
# test run the same matplotlib; a wrong value moves whole artists).
PIXEL_TOLERANCE = 24
DIFFERING_SHARE = 0.001


@dataclass(frozen=True)
class Landmark:
    """A pixel of an app's picture whose colour the library determines.

    ``row`` and ``column`` index the picture (row 0 at the top); the pixel
    must be within ``tolerance`` of ``color`` in every RGB channel (0-255).
    """

    what: str
    row: int
    column: int
    color: tuple[int, int, int]
    tolerance: int = 40


@dataclass(frozen=True)
class SliderMove:
    """How a student moves one slider of a lesson's app, and what must follow.

    ``app`` counts the notebook's slider apps from 0 in the order the
    notebook shows them. ``build`` makes that app exactly as the notebook's
    cell does, so that a test can set ``control`` to the value the browser
    shows and render the picture the kernel should have sent. ``moves`` are
    key sequences pressed on the slider's focused handle (Playwright key
    names); the picture is checked after each one, so each must end on a
    value the slider's readout shows unambiguously. ``landmarks(app)`` names
    pixels whose colour the library computes for the app's current control
    values (for lesson 01, the red dot at the point ``de_casteljau`` returns).
    """

    build: Callable[[], SliderApp]
    control: str
    moves: tuple[tuple[str, ...], ...]
    landmarks: Callable[[SliderApp], list[Landmark]]
    app: int = 0


@dataclass(frozen=True)
class Picture:
    """One key figure of a lesson: a file name (no suffix), a caption, a PNG renderer."""

    name: str
    caption: str
    render: Callable[[], bytes]

    def preview(self, width: int = 420) -> bytes:
        """The picture ``width`` pixels wide, as a small PNG (for the course map)."""
        return thumbnail(self.render(), width)


def app_picture(app: SliderApp) -> bytes:
    """The PNG an app shows for its current control values."""
    return app.refresh()


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
            f"picture: expected the shape of the library's picture {expected.shape}; "
            f"got {picture.shape}"
        )
    differing = np.abs(picture.astype(int) - expected.astype(int)) > PIXEL_TOLERANCE
    return float(differing.any(axis=2).mean())


def thumbnail(png: bytes, width: int) -> bytes:
    """A PNG scaled to ``width`` pixels (Lanczos, no aliasing), in 256 colours.

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
    height = max(1, round(image.height * width / image.width))
    small = image.resize((width, height), PILImage.Resampling.LANCZOS)
    buffer = io.BytesIO()
    small.quantize(256, method=PILImage.Quantize.MEDIANCUT).save(buffer, "png", optimize=True)
    return buffer.getvalue()


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
    the library says the axes must show (``course.canvas.crop`` returns it),
    and the point is placed in the axes' box from that alone, not from the
    axes' own limits, so a view of the wrong window cannot pass.
    """
    left, right, bottom, top = (float(value) for value in extent)
    x, y = (float(value) for value in point)
    box = axes.get_window_extent()
    display_x = box.x0 + (x - left) / (right - left) * box.width
    display_y = box.y1 - (y - top) / (bottom - top) * box.height
    return _landmark(app, display_x, display_y, color, what, tolerance)


def slider_stops(control: widgets.ValueWidget) -> list[Any]:
    """Every value a slider's handle can stop at, in order.

    Examples
    --------
    >>> slider_stops(widgets.FloatSlider(min=0.0, max=0.5, step=0.125))
    [0.0, 0.125, 0.25, 0.375, 0.5]
    >>> slider_stops(widgets.SelectionSlider(options=(1, 10, 100)))
    [1, 10, 100]
    """
    if isinstance(control, widgets.SelectionSlider):
        return list(control._options_values)
    if isinstance(control, widgets.IntSlider):
        return list(range(control.min, control.max + 1, control.step))
    if isinstance(control, widgets.FloatSlider):
        count = round((control.max - control.min) / control.step)
        stops = control.min + np.arange(count + 1) * control.step
        return [float(value) for value in np.minimum(stops, control.max)]
    raise TypeError(
        "control: expected an IntSlider, FloatSlider or SelectionSlider; "
        f"got {type(control).__name__}"
    )


#: What a key pressed on a focused slider handle does (noUiSlider, ipywidgets'
#: slider): move by this many stops, or go to the first or the last (None).
KEY_STEPS = {
    "ArrowRight": 1,
    "ArrowUp": 1,
    "ArrowLeft": -1,
    "ArrowDown": -1,
    "Home": None,
    "End": None,
}


def value_after_keys(control: widgets.ValueWidget, start: Any, keys: tuple[str, ...]) -> Any:
    """The value a slider holds after ``keys`` are pressed on its handle, from ``start``.

    Each arrow key moves the value by the slider's step, to the nearest stop
    (a value off the grid snaps to it); Home and End go to the ends. Readouts
    round (two decimals by default), so the browser tests predict the value
    and check that the readout shows it.

    Examples
    --------
    >>> control = widgets.FloatSlider(min=0.0, max=1.0, step=0.25)
    >>> value_after_keys(control, 0.3, ("ArrowRight",)), value_after_keys(control, 0.3, ("End",))
    (0.5, 1.0)
    >>> value_after_keys(widgets.SelectionSlider(options=(1, 10, 100)), 1, ("ArrowRight",) * 5)
    100
    """
    stops = slider_stops(control)
    if isinstance(control, widgets.SelectionSlider):
        # The handle moves over the options' indices.
        index = _after_keys(list(range(len(stops))), 1, stops.index(start), keys)
        return stops[index]
    return _after_keys(stops, control.step, start, keys)


def _after_keys(grid: list[Any], step: Any, position: Any, keys: tuple[str, ...]) -> Any:
    for key in keys:
        if key not in KEY_STEPS:
            raise ValueError(f"keys: expected keys among {sorted(KEY_STEPS)}; got {key!r}")
        if key == "Home":
            position = grid[0]
        elif key == "End":
            position = grid[-1]
        else:
            position = _nearest(grid, position + KEY_STEPS[key] * step)
    return position


def _nearest(grid: list[Any], target: Any) -> Any:
    return min(grid, key=lambda stop: abs(stop - target))


def nearest_stop(control: widgets.ValueWidget, value: Any) -> Any:
    """The stop nearest ``value``: where the browser puts a value off the slider's grid.

    JupyterLab shows a slider whose value is not a multiple of its step from
    its minimum at the nearest stop, and sends that value to the kernel.

    Examples
    --------
    >>> round(nearest_stop(widgets.FloatSlider(min=0.0, max=1.0, step=1 / 72), 0.3) * 72, 9)
    22.0
    """
    if isinstance(control, widgets.SelectionSlider):
        return value
    return _nearest(slider_stops(control), value)


def readout_shows(control: widgets.ValueWidget, value: Any, readout: str) -> bool:
    """Whether the slider's readout text can be ``value`` rounded by its format.

    Examples
    --------
    >>> control = widgets.FloatSlider(step=0.005)
    >>> readout_shows(control, 0.115, "0.12"), readout_shows(control, 0.115, "0.13")
    (True, False)
    """
    readout = readout.strip()
    if isinstance(control, widgets.SelectionSlider):
        labels = dict(zip(control._options_values, control._options_labels, strict=True))
        return labels[value] == readout
    if isinstance(control, widgets.IntSlider):
        return int(readout) == value
    decimals = len(readout.split(".")[1]) if "." in readout else 0
    # Half a unit of the last decimal, inclusive: JavaScript and Python round ties apart.
    return abs(float(readout) - value) <= 0.5 * 10.0**-decimals * (1 + 1e-9)


def neighbour_value(control: widgets.ValueWidget, value: Any) -> Any:
    """The slider's stop next to ``value``: the one above, or below at the top end.

    Examples
    --------
    >>> control = widgets.IntSlider(min=0, max=5)
    >>> neighbour_value(control, 2), neighbour_value(control, 5)
    (3, 4)
    """
    stops = slider_stops(control)
    index = stops.index(nearest_stop(control, value))
    return stops[index + 1] if index + 1 < len(stops) else stops[index - 1]
