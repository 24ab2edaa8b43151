"""The lessons' figures check their sizes before they draw: bounded work, named errors."""

import numpy as np
import pytest


def test_text_figure_bounds_its_text_before_stroking_it():
    from course.widgets.antialiasing_figures import text_figure

    with pytest.raises(ValueError, match=r"len\(text\) \* size at most 160"):
        text_figure("W" * 200, 16, 2)
    with pytest.raises(ValueError, match="text and size"):
        text_figure(None)


@pytest.mark.parametrize(
    ("steps", "message"),
    [
        ((1e-9,), "at most"),
        ((0.02,) * 9, "1 to 8 t steps"),
        ((), "1 to 8 t steps"),
        ((np.nan,), r"steps\[0\] must be finite"),
        ("abc", "steps must be a sequence"),
    ],
)
def test_brightness_figure_bounds_its_steps(steps, message):
    from course.widgets.antialiasing_figures import brightness_figure

    with pytest.raises((TypeError, ValueError), match=message):
        brightness_figure(steps=steps)


def test_gaps_figure_bounds_its_window_before_drawing():
    from course.widgets.de_casteljau_figures import gaps_figure

    with pytest.raises(ValueError, match="size must be between 1 and 100"):
        gaps_figure([[10, 10], [690, 10], [10, 690], [690, 690]], size=10**6)


def test_colour_figure_names_a_canvas_the_triangle_misses_and_one_too_large():
    from course.widgets.lines_and_triangles_figures import colour_figure

    with pytest.raises(ValueError, match="enclose at least one pixel centre"):
        colour_figure(size=(1, 1))
    with pytest.raises(ValueError, match="size must"):
        colour_figure(size=(1, 10**4))


@pytest.mark.parametrize(
    ("arguments", "name"),
    [({"corner": 10**9}, "corner"), ({"rate": 10**6}, "rate"), ({"corner": "40"}, "corner")],
)
def test_shift_figure_bounds_its_window_and_rate(arguments, name):
    from course.widgets.supersampling_figures import shift_figure

    with pytest.raises((TypeError, ValueError), match=name):
        shift_figure(**arguments)
