"""What a key pressed on a slider does: the values a browser test predicts.

The browser tests (``tests_browser``) press keys on a focused slider handle
as a student does and check the picture the kernel sends back. These
functions say where the handle then stands, and what its readout may show,
from the slider's own settings.

Classroom tooling for the course's authors and its browser tests: its
inputs come from the lesson registry, never from a student, so this module
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from typing import Any

import ipywidgets as widgets
import numpy as np

from course.i18n import _

__all__ = [
    "KEY_STEPS",
    "nearest_stop",
    "neighbour_value",
    "readout_shows",
    "slider_stops",
    "value_after_keys",
]

UNCHECKED = True  # see the module docstring


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
        _(
            "control: expected an IntSlider, FloatSlider or SelectionSlider; got {control_type}"
        ).format(control_type=type(control).__name__)
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
            raise ValueError(
                _("keys: expected keys among {choices}; got {key}").format(
                    choices=sorted(KEY_STEPS), key=repr(key)
                )
            )
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
