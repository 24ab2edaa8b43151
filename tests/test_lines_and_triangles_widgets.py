"""course.widgets.lines_and_triangles: moving a slider redraws what the library computes."""

import numpy as np
import pytest

from course.canvas import blank, paint
from course.raster import line, line_4connected, triangle, triangle_coverage
from course.widgets.lines_and_triangles import LineApp, TriangleApp


def set_values(app, **values):
    for name, value in values.items():
        app.controls[name].value = value


def test_line_app_draws_both_lines_where_the_sliders_put_them():
    app = LineApp()
    app.refresh()
    before = app.view.image.value
    set_values(app, x0=30, y0=2, x1=4, y1=25)
    assert app.view.image.value != before
    expected = paint(blank((32, 32)), line((30, 2), (4, 25)), 1.0)
    np.testing.assert_array_equal(app.panels["bresenham"].get_array(), expected)
    staircase = paint(blank((32, 32)), line_4connected((30, 2), (4, 25)), 1.0)
    np.testing.assert_array_equal(app.panels["report"].get_array(), staircase)
    assert app.panels["bresenham"].axes.get_title().startswith("Bresenham: 27 px")
    assert app.panels["report"].axes.get_title().startswith("report's loop: 50 px")
    np.testing.assert_array_equal(app.ideal["wu"].get_xdata(), [30.5, 4.5])


def test_line_app_reaches_every_octant():
    app = LineApp()
    centre = (16, 16)
    seen = set()
    for target in [(28, 20), (20, 28), (12, 28), (4, 20), (4, 12), (12, 4), (20, 4), (28, 12)]:
        set_values(app, x0=centre[0], y0=centre[1], x1=target[0], y1=target[1])
        seen.add(app.heading.get_text().rsplit(" ", 1)[1])
        painted = int(app.panels["bresenham"].get_array().sum())
        assert painted == max(abs(target[0] - 16), abs(target[1] - 16)) + 1
    assert seen == {str(k) for k in range(8)}


def test_line_app_shows_the_pixels_on_screen():
    app = LineApp(p0=(0, 0), p1=(31, 0))
    app.refresh()
    rgba = app.view.pixels()
    # The Bresenham panel: dark pixels in a horizontal band at the top of the grid.
    dark = (rgba[..., :3] < 60).all(axis=2)
    panel = dark[:, : rgba.shape[1] // 3]
    rows = np.flatnonzero(panel.sum(axis=1) > 100)
    assert len(rows) > 0
    set_values(app, y0=31, y1=31)
    moved = (app.view.pixels()[..., :3] < 60).all(axis=2)[:, : rgba.shape[1] // 3]
    assert np.flatnonzero(moved.sum(axis=1) > 100).mean() > rows.mean() + 100


# A square split along its diagonal, which passes through 8 pixel centres
# strictly between its ends: (1.5, 1.5) to (8.5, 8.5).
SQUARE = ((1.0, 1.0), (9.0, 1.0), (9.0, 9.0), (1.0, 9.0))


@pytest.mark.parametrize(
    ("rule", "twice", "missed"), [("top-left", 0, 0), ("closed", 8, 0), ("open", 0, 8)]
)
def test_triangle_app_counts_what_the_rule_does_to_the_shared_edge(rule, twice, missed):
    app = TriangleApp(vertices=SQUARE, rule="closed" if rule == "top-left" else "top-left")
    set_values(app, rule=rule)
    title = app.left.get_title()
    assert f"{twice} painted twice, {missed} missed" in title
    first = triangle(*SQUARE[:3], shape=(16, 16), rule=rule)
    second = triangle(SQUARE[0], SQUARE[2], SQUARE[3], shape=(16, 16), rule=rule)
    assert f"{len(first)} + {len(second)} pixels" in title
    owners = np.asarray(app.owners.get_array())
    assert int((owners == 3).sum()) == twice
    assert int((owners > 0).sum()) == 64 - missed


def test_triangle_app_moves_a_vertex_and_shows_the_coverage_at_the_rate():
    app = TriangleApp()
    app.refresh()
    before = app.view.image.value
    set_values(app, bx=15.25, by=0.5, rate=7)
    assert app.view.image.value != before
    a, b, c, d = app.vertices()
    assert tuple(b) == (15.25, 0.5)
    expected = blank((16, 16))
    for triple in ((a, b, c), (a, c, d)):
        pixels, weights = triangle_coverage(*triple, (16, 16), 7)
        paint(expected, pixels, 1.0, weight=weights)
    np.testing.assert_allclose(app.coverage.get_array(), expected)
    assert "7 x 7 samples" in app.right.get_title()
