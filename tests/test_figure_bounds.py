"""The lessons' figures check their sizes before they draw: bounded work, named errors."""

import numpy as np
import pytest


def test_text_figure_bounds_its_text_before_stroking_it():
    from course.lessons.l05_antialiasing.figures import text_figure

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
    from course.lessons.l05_antialiasing.figures import brightness_figure

    with pytest.raises((TypeError, ValueError), match=message):
        brightness_figure(steps=steps)


def test_gaps_figure_bounds_its_window_before_drawing():
    from course.lessons.l01_de_casteljau.figures import gaps_figure

    with pytest.raises(ValueError, match="size must be between 1 and 100"):
        gaps_figure([[10, 10], [690, 10], [10, 690], [690, 690]], size=10**6)


def test_colour_figure_names_a_canvas_the_triangle_misses_and_one_too_large():
    from course.lessons.l03_lines_and_triangles.figures import colour_figure

    with pytest.raises(ValueError, match="enclose at least one pixel centre"):
        colour_figure(size=(1, 1))
    with pytest.raises(ValueError, match="size must"):
        colour_figure(size=(1, 10**4))


@pytest.mark.parametrize(
    ("arguments", "name"),
    [({"corner": 10**9}, "corner"), ({"rate": 10**6}, "rate"), ({"corner": "40"}, "corner")],
)
def test_shift_figure_bounds_its_window_and_rate(arguments, name):
    from course.lessons.l04_supersampling.figures import shift_figure

    with pytest.raises((TypeError, ValueError), match=name):
        shift_figure(**arguments)


@pytest.mark.parametrize(
    "name",
    ["three_points_figure", "reversed_figure", "end_of_curve_figure", "yellow_check_figure"],
)
def test_de_casteljau_figures_draw_at_most_100_control_points(name):
    from course.lessons.l01_de_casteljau import figures as de_casteljau_figures

    curve = np.resize([[2.0, 3.0], [14.0, 1.0], [3.0, 13.0], [13.0, 14.0]], (1501, 2))
    arguments = {"t": 0.5} if name == "three_points_figure" else {}
    if name == "yellow_check_figure":
        arguments = {"seed": "000"}
    with pytest.raises(ValueError, match="at most 100 control points"):
        getattr(de_casteljau_figures, name)(curve, **arguments)


def test_bernstein_figures_draw_at_most_100_control_points_and_tangents():
    from course.lessons.l02_bernstein.figures import hodograph_figure, tangents_figure

    curve = np.resize([[2.0, 3.0], [14.0, 1.0], [3.0, 13.0], [13.0, 14.0]], (1501, 2))
    with pytest.raises(ValueError, match="at most 100 control points"):
        tangents_figure(curve)
    with pytest.raises(ValueError, match="ts must hold at most 100"):
        hodograph_figure(curve[:4], ts=np.linspace(0, 1, 1501))
