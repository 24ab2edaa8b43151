"""course.widgets.de_casteljau: moving a control redraws what the library computes."""

import io

import numpy as np
from PIL import Image

from course.bezier import de_casteljau, de_casteljau_levels
from course.images import EXAMPLE_POINTS
from course.widgets.base import parse_points
from course.widgets.de_casteljau import MAX_POINTS, DeCasteljauApp

CRIMSON = np.array([220, 20, 60])


def picture(app):
    return np.asarray(Image.open(io.BytesIO(app.view.image.value)).convert("RGB")).astype(int)


def pixel_of(app, point):
    """Row and column of the PNG where data point (x, y) is drawn."""
    x, y = app.axes.transData.transform(point)
    height = picture(app).shape[0]
    return round(float(height - y)), round(float(x))


def drawn_levels(app):
    return [line.get_xydata() for line in app.level_lines if len(line.get_xdata())]


def test_moving_t_redraws_the_levels_and_the_point_where_de_casteljau_puts_them():
    app = DeCasteljauApp()
    app.refresh()
    before = app.view.image.value
    app.controls["t"].value = 0.3
    assert app.view.image.value != before
    points = parse_points(app.value("points"))
    np.testing.assert_array_equal(points, EXAMPLE_POINTS[:4])
    levels = de_casteljau_levels(points, 0.3)
    for drawn, level in zip(drawn_levels(app), levels[:-1], strict=True):
        np.testing.assert_allclose(drawn, level)
    point = de_casteljau(points, 0.3)
    np.testing.assert_allclose(app.point_marker.get_xydata()[0], point)
    np.testing.assert_allclose(app.traced.get_xydata()[-1], point)
    np.testing.assert_allclose(app.traced.get_xydata()[0], points[0])
    row, column = pixel_of(app, point)
    assert np.abs(picture(app)[row, column] - CRIMSON).max() < 40
    assert "t = 0.30" in app.title.get_text()


def test_more_points_extend_the_list_and_draw_every_level():
    app = DeCasteljauApp(t=0.7)
    app.controls["count"].value = 10
    points = parse_points(app.value("points"))
    np.testing.assert_array_equal(points, EXAMPLE_POINTS[:10])
    levels = de_casteljau_levels(points, 0.7)
    assert len(drawn_levels(app)) == 9
    for drawn, level in zip(drawn_levels(app), levels[:-1], strict=True):
        np.testing.assert_allclose(drawn, level)
    assert "degree 9" in app.title.get_text()
    app.controls["count"].value = 2
    assert parse_points(app.value("points")).tolist() == EXAMPLE_POINTS[:2].tolist()
    assert len(drawn_levels(app)) == 1


def test_dragging_a_control_point_moves_it_and_every_level_follows():
    app = DeCasteljauApp(t=0.5)
    app.refresh()
    start = app.picture_point(app.axes, EXAMPLE_POINTS[1])
    app.pointer("down", *np.add(start, (3, -2)))  # off-centre: the point does not jump
    assert app.grabbed == "P1"
    ring = app.highlight_ring(app.axes)[0]
    np.testing.assert_allclose(ring.get_xydata()[0], EXAMPLE_POINTS[1])
    app.pointer("move", *np.add(start, (50, 3)))
    app.pointer("up", *np.add(start, (83, 42)))
    assert app.grabbed is None and len(ring.get_xdata()) == 0
    points = parse_points(app.value("points"))
    moved = app.data_point(app.axes, *np.add(start, (80, 44)))
    np.testing.assert_allclose(points[1], moved, atol=0.06)  # rounded to 0.1
    np.testing.assert_array_equal(points[[0, 2, 3]], EXAMPLE_POINTS[[0, 2, 3]])
    for drawn, level in zip(drawn_levels(app), de_casteljau_levels(points, 0.5)[:-1], strict=True):
        np.testing.assert_allclose(drawn, level)
    point = de_casteljau(points, 0.5)
    row, column = pixel_of(app, point)
    assert np.abs(picture(app)[row, column] - CRIMSON).max() < 40


def test_a_drag_past_the_edge_stops_at_it_and_a_press_on_nothing_grabs_nothing():
    app = DeCasteljauApp()
    app.refresh()
    x, y = app.picture_point(app.axes, EXAMPLE_POINTS[0])
    app.pointer("down", x, y)
    app.pointer("move", -400.0, 10_000.0)  # far outside the picture
    app.pointer("up", -400.0, 10_000.0)
    (left, _right), (bottom, _top) = app.axes.get_xlim(), app.axes.get_ylim()
    np.testing.assert_allclose(parse_points(app.value("points"))[0], [left, bottom], atol=0.06)
    before = app.value("points")
    app.pointer("down", 480.0, 20.0)  # empty space, then a drag: not a click
    app.pointer("move", 470.0, 60.0)
    app.pointer("up", 470.0, 60.0)
    assert app.value("points") == before and app.grabbed is None


def test_a_click_adds_a_point_and_a_double_click_removes_one_within_the_limits():
    app = DeCasteljauApp()
    app.refresh()
    app.pointer("down", 250.0, 420.0)
    app.pointer("up", 251.0, 421.0)
    points = parse_points(app.value("points"))
    assert app.value("count") == 5 and len(points) == 5
    np.testing.assert_allclose(points[-1], app.data_point(app.axes, 251.0, 421.0), atol=0.06)
    assert [handle.name for handle in app.handles()] == ["P0", "P1", "P2", "P3", "P4"]
    app.pointer("double", *app.picture_point(app.axes, points[2]))
    np.testing.assert_array_equal(parse_points(app.value("points")), np.delete(points, 2, axis=0))
    app.controls["count"].value = 2
    app.pointer("double", *app.picture_point(app.axes, app.points[0]))
    assert app.value("count") == 2 and "At least 2 points" in app.status.value
    app.controls["count"].value = MAX_POINTS
    app.pointer("down", 250.0, 420.0)
    app.pointer("up", 250.0, 420.0)
    assert app.value("count") == MAX_POINTS and f"At most {MAX_POINTS}" in app.status.value


def test_typed_points_move_the_handles_and_the_cursor_s_targets():
    app = DeCasteljauApp()
    app.controls["points"].value = "100, 100; 600, 100; 600, 600"
    assert [h.at for h in app.handles()] == [(100, 100), (600, 100), (600, 600)]
    expected = [list(app.picture_point(app.axes, p).round(1)) for p in app.points]
    assert [row[:2] for row in app.view.image.handles] == expected


def test_edited_points_are_drawn_and_bad_text_keeps_the_last_curve():
    app = DeCasteljauApp(t=0.5)
    app.controls["points"].value = "0, 0; 100, 200; 200, 0"
    assert app.value("count") == 3
    np.testing.assert_allclose(app.point_marker.get_xydata()[0], [100, 100])
    shown = app.view.image.value
    app.controls["points"].value = "0, 0; 100"
    assert "Kept the last points" in app.status.value
    assert app.value("points") == "0, 0; 100"  # the typed text stays, to be fixed
    np.testing.assert_allclose(app.point_marker.get_xydata()[0], [100, 100])
    app.controls["t"].value = 0.25
    assert app.view.image.value != shown
    np.testing.assert_allclose(app.point_marker.get_xydata()[0], [50, 75])


def test_the_picture_only_changes_where_things_move():
    app = DeCasteljauApp(t=0.2)
    app.refresh()
    first = picture(app)
    app.controls["t"].value = 0.8
    app.controls["t"].value = 0.2
    # Blitting over the cached background gives exactly the same picture back.
    np.testing.assert_array_equal(picture(app), first)
