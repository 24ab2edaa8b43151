"""course.widgets.de_casteljau: moving a control redraws what the library computes."""

import io

import numpy as np
from PIL import Image

from course.bezier import de_casteljau, de_casteljau_levels
from course.images import EXAMPLE_POINTS
from course.widgets.de_casteljau import DeCasteljauApp, parse_points

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


def test_edited_points_are_drawn_and_bad_text_keeps_the_last_curve():
    app = DeCasteljauApp(t=0.5)
    app.controls["points"].value = "0, 0; 100, 200; 200, 0"
    assert app.value("count") == 3
    np.testing.assert_allclose(app.point_marker.get_xydata()[0], [100, 100])
    shown = app.view.image.value
    app.controls["points"].value = "0, 0; 100"
    assert "Kept the last points" in app.status.value
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
