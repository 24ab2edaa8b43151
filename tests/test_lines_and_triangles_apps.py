"""Lesson 03's apps: a drag, a typed point or a slider redraws the library."""

import re

import numpy as np
import pytest
from matplotlib.colors import to_rgb

from course.curves.bezier_handouts import bresenham_curve, segments_report
from course.i18n import language
from course.lessons.l03_lines_and_triangles import figures as line_figures
from course.lessons.l03_lines_and_triangles.apps import (
    OWNER_COLORS,
    CurveSegmentsApp,
    LineApp,
    TriangleApp,
)
from course.raster import line, line_4connected, triangle, triangle_coverage
from course.raster.canvas import blank, paint
from course.raster.triangles import EDGE_RULES
from course.widgets.base import parse_points


def set_ends(app, p0, p1):
    app.controls["endpoints"].value = f"{p0[0]}, {p0[1]}; {p1[0]}, {p1[1]}"


def test_line_app_draws_both_lines_where_the_text_puts_them():
    app = LineApp()
    app.refresh()
    before = app.view.image.value
    set_ends(app, (30, 2), (4, 25))
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
        set_ends(app, centre, target)
        seen.add(re.search(r"octant (\d)", app.heading.get_text())[1])
        painted = int(app.panels["bresenham"].get_array().sum())
        assert painted == max(abs(target[0] - 16), abs(target[1] - 16)) + 1
    assert seen == {str(k) for k in range(1, 9)}


def test_line_app_says_how_far_each_line_strays_from_the_red_one():
    app = LineApp()
    app.update()
    # Bresenham's farthest centre: pixel (15, 11), half a row from the line through the end
    # centres, which is at y = 6.5 + 11 * 12 / 24 = 12 at x = 15.5.
    bresenham = 0.5 * 24 / np.hypot(24, 11)
    assert f"Bresenham {bresenham:.2f} px, the report's loop 1.10 px" in app.heading.get_text()


def test_line_app_shows_the_pixels_on_screen():
    app = LineApp(p0=(0, 0), p1=(31, 0))
    app.refresh()
    rgba = app.view.pixels()
    # The Bresenham panel: dark pixels in a horizontal band at the top of the grid.
    dark = (rgba[..., :3] < 60).all(axis=2)
    panel = dark[:, : rgba.shape[1] // 3]
    rows = np.flatnonzero(panel.sum(axis=1) > 100)
    assert len(rows) > 0
    set_ends(app, (0, 31), (31, 31))
    moved = (app.view.pixels()[..., :3] < 60).all(axis=2)[:, : rgba.shape[1] // 3]
    assert np.flatnonzero(moved.sum(axis=1) > 100).mean() > rows.mean() + 100


def test_dragging_an_end_in_any_panel_snaps_it_to_the_pixel_under_the_pointer():
    app = LineApp()
    app.refresh()
    wu = app.panels["wu"].axes
    start = app.picture_point(wu, (27.5, 17.5))  # the centre of p1's pixel, in the Wu panel
    app.pointer("down", *start)
    assert app.grabbed == "p1" and app.highlight_ring(wu)[0].get_xydata().tolist() == [[27.5, 17.5]]
    target = app.picture_point(wu, (10.7, 29.2))
    app.pointer("move", *target)
    app.pointer("up", *target)
    assert app.endpoints() == ((3, 6), (10, 29)) and app.value("endpoints") == "3, 6; 10, 29"
    expected = paint(blank((32, 32)), line((3, 6), (10, 29)), 1.0)
    np.testing.assert_array_equal(app.panels["bresenham"].get_array(), expected)
    app.drag_along("p0", [(-5000, -5000)])  # far past the grid: the corner pixel
    assert app.endpoints()[0] == (0, 0)


def test_line_app_keeps_the_last_line_on_bad_text():
    app = LineApp()
    for text, words in (
        ("1, 2", "expected 2 points; got 1"),
        ("1.5, 2; 3, 4", "expected whole pixels"),
        ("0, 0; 40, 3", "x must lie from 0 to 31, y from 0 to 31"),
    ):
        app.controls["endpoints"].value = text
        assert words in app.status.value and app.endpoints() == ((3, 6), (27, 17))


# A square split along its diagonal, which passes through 8 pixel centres
# strictly between its ends: (1.5, 1.5) to (8.5, 8.5).
SQUARE = ((1.0, 1.0), (9.0, 1.0), (9.0, 9.0), (1.0, 9.0))


@pytest.mark.parametrize(
    ("rule", "twice", "missed"), [("top-left", 0, 0), ("closed", 8, 0), ("open", 0, 8)]
)
def test_triangle_app_counts_what_the_rule_does_to_the_shared_edge(rule, twice, missed):
    app = TriangleApp(vertices=SQUARE, rule="closed" if rule == "top-left" else "top-left")
    app.controls["rule"].value = rule
    title = app.left.get_title()
    assert f"{twice} painted twice, {missed} missed" in title
    first = triangle(*SQUARE[:3], shape=(16, 16), rule=rule)
    second = triangle(SQUARE[0], SQUARE[2], SQUARE[3], shape=(16, 16), rule=rule)
    assert f"{len(first)} + {len(second)} pixels" in title
    owners = np.asarray(app.owners.get_array())
    assert int((owners == 3).sum()) == twice
    assert int((owners > 0).sum()) == 64 - missed


def test_triangle_app_moves_a_dragged_vertex_and_shows_the_coverage_at_the_rate():
    app = TriangleApp()
    app.refresh()
    before = app.view.image.value
    start = app.picture_point(app.right, (13.5, 3.0))  # B, grabbed in the coverage panel
    app.pointer("down", *start)
    assert app.grabbed == "B"
    app.pointer("up", *app.picture_point(app.right, (15.3, 0.6)))  # snaps to quarter pixels
    app.controls["rate"].value = 7
    assert app.view.image.value != before
    a, b, c, d = app.vertices()
    assert tuple(b) == (15.25, 0.5)
    assert parse_points(app.value("vertices"))[1].tolist() == [15.25, 0.5]
    expected = blank((16, 16))
    for triple in ((a, b, c), (a, c, d)):
        pixels, weights = triangle_coverage(*triple, (16, 16), 7)
        paint(expected, pixels, 1.0, weight=weights)
    np.testing.assert_allclose(app.coverage.get_array(), expected)
    assert "7 x 7 samples" in app.right.get_title()


def test_curve_segments_app_draws_the_lab_s_lines_and_counts_them():
    app = CurveSegmentsApp(segments=4)
    app.refresh()
    control = app.control.copy()
    report = segments_report(control, 4)
    picture = np.asarray(app.pixels.get_array())
    drawn = np.unique(bresenham_curve(control, 4), axis=0)
    assert set(map(tuple, np.argwhere(picture == 1)[:, ::-1].tolist())) == {
        tuple(p)
        for p in drawn.tolist()
        if tuple(p) not in set(map(tuple, report["off_pixels"].tolist()))
    }
    assert (picture == 2).sum() == report["off"] and (picture == 3).sum() == report["missed"]
    assert f"{report['off']} off the curve" in app.grid_axes.get_title()
    assert list(app.counts["twice"].get_ydata())[:3] == [
        segments_report(control, n)["twice"] for n in (1, 2, 4)
    ]
    app.controls["segments"].value = 16
    assert "16 segments" in app.grid_axes.get_title()
    assert list(app.now.get_xdata()) == [16, 16]


def test_dragging_a_control_point_of_the_segments_app_redraws_them():
    app = CurveSegmentsApp(segments=8)
    app.refresh()
    start = app.drag_along("P2", [(10, 10), (-40, 30)])
    moved = parse_points(app.value("points"))
    expected = np.round(app.data_point(app.grid_axes, *np.add(start, (-40, 30))), 1)
    np.testing.assert_allclose(moved[2], expected)
    # Ten screen pixels per grid pixel: a whole zoom.
    box = app.grid_axes.get_window_extent()
    assert (round(box.width, 6), round(box.height, 6)) == (400, 400)
    assert (round(box.x0, 6), round(box.y0, 6)) == (40, 60)
    report = segments_report(moved, 8)
    assert (np.asarray(app.pixels.get_array()) == 2).sum() == report["off"]


def test_every_colour_and_mark_of_the_pixel_panels_has_a_legend_entry():
    segments = CurveSegmentsApp()
    labels = [text.get_text() for text in segments.grid_axes.get_legend().get_texts()]
    assert labels == [
        "drawn, on the curve",
        "drawn, off the curve",
        "curve missed (> 1 px away)",
        "drawn twice",
        "the curve",
    ]
    # One legend patch per colour the panel paints (white, the background, needs none).
    patches = segments.grid_axes.get_legend().get_patches()
    colours = [tuple(np.round(patch.get_facecolor()[:3], 3)) for patch in patches]
    painted = [tuple(np.round(to_rgb(c), 3)) for c in segments.pixels.colormap.colors[1:]]
    assert colours == painted
    triangles = TriangleApp()
    patches = triangles.left.get_legend().get_patches()
    colours = [tuple(np.round(patch.get_facecolor()[:3], 3)) for patch in patches]
    assert colours == [tuple(np.round(to_rgb(c), 3)) for c in OWNER_COLORS[1:]]
    # The course map shows the left panel alone: its legend must be inside that picture.
    triangles.refresh()
    renderer = triangles.view.canvas.get_renderer()
    panel = triangles.left.get_tightbbox(renderer)
    legend = triangles.left.get_legend().get_window_extent(renderer)
    assert panel.x0 <= legend.x0 and legend.x1 <= panel.x1 and panel.y0 <= legend.y0


def test_the_coverage_panel_has_a_key_for_black_grey_and_white():
    app = TriangleApp()
    key = app.right.get_legend()
    labels = [text.get_text() for text in key.get_texts()]
    assert labels == ["fully inside: 1", "grey: the share of its samples inside", "outside: 0"]
    # Each entry is the colour the panel itself gives that coverage.
    for patch, coverage in zip(key.get_patches(), (1.0, 0.5, 0.0), strict=True):
        shown = app.coverage.colormap(coverage)
        np.testing.assert_allclose(patch.get_facecolor(), shown)


# --- issue 36: the rules and Wu's line said in the student's language ---------------


def test_the_rule_toggle_names_the_rules_in_the_students_language_and_keeps_the_values():
    with language("zh-CN"):
        app = TriangleApp(rule="closed")
        app.refresh()
        toggle = app.controls["rule"]
        assert toggle.options == (
            ("左上规则", "top-left"),
            ("闭合规则", "closed"),
            ("开放规则", "open"),
        )
        assert app.value("rule") == "closed"
        assert app.left.get_title().startswith("闭合规则：")
    english = TriangleApp()
    english.refresh()
    assert english.controls["rule"].options == tuple((rule, rule) for rule in EDGE_RULES)
    assert english.left.get_title().startswith("rule top-left: ")


def test_wus_line_is_named_in_chinese_in_the_line_app():
    with language("zh-CN"):
        app = LineApp()
        app.refresh()
        assert app.panels["wu"].axes.get_title().startswith("吴小林直线：")
    assert line_figures.rule_name("open") == "open"
