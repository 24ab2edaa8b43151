"""course.classroom.sliders: where a slider's handle stands after keys, what its readout shows."""

import ipywidgets as widgets
import pytest

from course.classroom.sliders import (
    nearest_stop,
    neighbour_value,
    readout_shows,
    slider_stops,
    value_after_keys,
)


def test_slider_stops_and_keys_follow_the_slider():
    control = widgets.FloatSlider(value=0.3, min=0.0, max=1.0, step=1 / 72)
    # Off the grid, a key press snaps to the nearest stop past the step; so does the browser.
    assert nearest_stop(control, 0.3) == pytest.approx(22 / 72)
    assert value_after_keys(control, 0.3, ("ArrowRight",)) == pytest.approx(23 / 72)
    assert value_after_keys(control, 0.3, ("ArrowLeft",)) == pytest.approx(21 / 72)
    assert value_after_keys(control, 0.3, ("ArrowLeft", "Home", "ArrowRight")) == 1 / 72
    assert value_after_keys(control, 0.3, ("End", "ArrowRight")) == 1.0
    assert readout_shows(control, 23 / 72, "0.319") and not readout_shows(control, 0.3, "0.319")
    with pytest.raises(ValueError, match="keys"):
        value_after_keys(control, 0.3, ("PageUp",))
    choice = widgets.SelectionSlider(options=(0, 1, 3, 10), value=3)
    assert value_after_keys(choice, 3, ("ArrowLeft", "ArrowLeft")) == 0
    assert readout_shows(choice, 10, "10") and neighbour_value(choice, 10) == 3
    with pytest.raises(TypeError, match="IntSlider, FloatSlider or SelectionSlider"):
        slider_stops(widgets.FloatLogSlider())
