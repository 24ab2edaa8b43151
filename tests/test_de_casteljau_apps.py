"""course.lessons.l01_de_casteljau.apps: moving a control redraws what the library computes."""

import io
import json

import numpy as np
from PIL import Image

from course.curves.bezier import de_casteljau, de_casteljau_levels
from course.images import EXAMPLE_POINTS
from course.lessons.l01_de_casteljau.apps import MAX_POINTS, DeCasteljauApp
from course.widgets.base import parse_points

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


def test_points_typed_beyond_the_most_the_app_draws_are_cut_and_the_app_says_so():
    app = DeCasteljauApp()
    typed = [(10.0 * i, 5.0 * (i % 3)) for i in range(MAX_POINTS + 3)]
    app.controls["points"].value = "; ".join(f"{x:g}, {y:g}" for x, y in typed)
    assert app.status.value == (
        f"Kept the first {MAX_POINTS} of the {MAX_POINTS + 3} points typed: "
        f"the app draws at most {MAX_POINTS} (degree {MAX_POINTS - 1})."
    )
    assert app.value("count") == MAX_POINTS
    np.testing.assert_array_equal(parse_points(app.value("points")), typed[:MAX_POINTS])
    np.testing.assert_array_equal(app.points, typed[:MAX_POINTS])


def test_decimal_commas_are_refused_not_read_as_more_points():
    app = DeCasteljauApp()
    app.controls["points"].value = "90,5 610,5; 170, 130"
    assert "decimal comma" in app.status.value and "Kept the last points" in app.status.value
    np.testing.assert_array_equal(app.points, EXAMPLE_POINTS[:4])
    assert app.value("count") == 4


def test_a_drag_redraws_only_b_of_t_s_numbers_and_the_release_brings_the_title_back():
    app = DeCasteljauApp(t=0.5)
    patches = []
    app.view.image.send = lambda content, buffers=None: patches.append(
        {**content, "buffers": buffers}
    )
    app.refresh()
    before = picture(app)
    start = app.picture_point(app.axes, EXAMPLE_POINTS[1])
    title = app.title.get_window_extent(app.view.canvas.get_renderer())
    app.pointer("down", *start)
    # The title's start stands where the whole title stood, its numbers beside it.
    first = app.title_start.get_window_extent(app.view.canvas.get_renderer())
    numbers = app.title_numbers.get_window_extent(app.view.canvas.get_renderer())
    assert abs(first.x0 - title.x0) < 0.5 and abs(first.y0 - title.y0) < 0.5
    assert abs(numbers.x0 - first.x1) < 0.5 and abs(numbers.x1 - title.x1) < 2
    assert not app.title.get_visible() and app.title_start.get_text().endswith("B(t) = ")
    typed = app.value("points")
    for step in range(1, 4):
        app.pointer("move", *np.add(start, (7 * step, -5 * step)))
        moved = app.data_point(app.axes, *np.add(start, (7 * step, -5 * step)))
        np.testing.assert_allclose(app.points[1], moved, atol=0.06)  # rounded to 0.1
        point = de_casteljau(app.points, 0.5)
        assert app.title_numbers.get_text() == f"({point[0]:.1f}, {point[1]:.1f})"
        assert app.title.get_text() == app.title_start.get_text() + app.title_numbers.get_text()
    # The browser draws each step: B(t)'s numbers are one text of the step's drawing.
    assert patches and all(patch["kind"] == "drawing" for patch in patches)
    texts = [command.get("text") for command in json.loads(patches[-1]["buffers"][-3])]
    assert app.title_numbers.get_text() in texts and app.title.get_text() not in texts
    assert np.array_equal(picture(app), before)  # the whole picture waits for the release
    assert app.value("points") == typed  # the controls get the points at the release
    app.pointer("up", *np.add(start, (21, -15)))
    np.testing.assert_array_equal(parse_points(app.value("points")), app.points)
    assert app.title.get_visible() and not app.title_numbers.get_visible()
    # Released, the picture is the one a fresh app draws for the same points.
    fresh = DeCasteljauApp(points=parse_points(app.value("points")), t=0.5)
    fresh.refresh()
    np.testing.assert_array_equal(picture(app), picture(fresh))


def composed(whole: bytes, messages: list) -> np.ndarray:
    """The browser's picture, as picture.js composes it: the whole PNG, then each patch."""
    shown = np.asarray(Image.open(io.BytesIO(whole)).convert("RGB")).copy()
    for content, buffers in messages:
        for (left, top, width, height), data in zip(content["rectangles"], buffers, strict=True):
            shown[top : top + height, left : left + width] = np.asarray(
                Image.open(io.BytesIO(data)).convert("RGB")
            )
    return shown


def drawn_in_full(points: np.ndarray, t: float, held: int) -> np.ndarray:
    """A fresh app with the same points and P``held`` held, drawn whole by matplotlib alone.

    No blitting, no patches, none of the drag's shortcuts (cached layouts and
    glyphs, replayed lines, the title in two parts): Agg draws every artist.
    """
    fresh = DeCasteljauApp(points=points, t=t)
    fresh.BLIT = False
    for artist in fresh.moving:
        artist.set_animated(False)  # an animated artist is left out of a full draw
    fresh.refresh()
    fresh.pointer("down", *fresh.picture_point(fresh.axes, points[held]))
    assert fresh.grabbed == f"P{held}"
    return np.asarray(fresh.view.canvas.buffer_rgba())[..., :3]


def test_every_step_of_a_drag_shows_what_a_full_redraw_draws():
    # Cost: about 1.5 s (a fresh app drawn whole for each of four steps).
    app = DeCasteljauApp(t=0.35)
    app.view.draw_in_browser = False  # Agg's pixels, patched (tests/test_browser_drawing.py)
    messages = []
    app.view.image.send = lambda content, buffers=None: (
        messages.append((content, buffers)) if content.get("kind") == "patch" else None
    )
    app.refresh()
    whole = app.view.image.value
    start = app.picture_point(app.axes, EXAMPLE_POINTS[2])
    app.pointer("down", *start)
    # Moves of whole and fractional pixels, far and near, and back past the start.
    for step, offset in enumerate([(0, 0), (13.4, -7.3), (-41, 22.5), (60, 5)]):
        app.pointer("move", *np.add(start, offset))
        points = app.points  # the controls get them at the release
        expected = drawn_in_full(points, 0.35, held=2)
        np.testing.assert_array_equal(composed(whole, messages), expected, err_msg=f"step {step}")
    assert all(content["kind"] == "patch" for content, _ in messages)


def test_a_drag_step_through_the_comm_is_answered_by_its_drawing_alone():
    app = DeCasteljauApp(t=0.5)
    app.refresh()
    sent = []
    app.view.image.send = lambda content, buffers=None: sent.append(content)
    start = app.picture_point(app.axes, app.points[1])
    app._on_message(app.view.image, {"kind": "down", "x": start[0], "y": start[1]}, [])
    sent.clear()
    for step in range(1, 4):
        app._on_message(app.view.image, {"kind": "move", "x": start[0] + step, "y": start[1]}, [])
        assert [message["kind"] for message in sent] == ["drawing"] and sent[0]["drawn"] is True
        sent.clear()
    # A move that changes nothing sends no drawing: a lone "drawn" answers it.
    app._on_message(app.view.image, {"kind": "move", "x": start[0] + 3, "y": start[1]}, [])
    assert sent == [{"kind": "drawn"}] and not app.view.awaited
    # Moves made from Python code wait for no answer: their drawings say nothing of one.
    app.pointer("move", start[0] + 9, start[1])
    assert sent[-1]["kind"] == "drawing" and "drawn" not in sent[-1]


def test_the_points_text_reaches_the_browser_once_at_the_release_not_at_every_step():
    app = DeCasteljauApp(t=0.5)
    app.refresh()
    control = app.controls["points"]
    synced = []
    control._send = lambda message, buffers=None: synced.append(message["state"])
    start = app.picture_point(app.axes, app.points[1])
    app.pointer("down", *start)
    for step in range(1, 4):
        app.pointer("move", start[0] + 5 * step, start[1])
    assert synced == []  # the picture showed each step; the text waits
    app.pointer("up", start[0] + 20, start[1])
    assert synced == [{"value": control.value}] and app.points[1][0] > EXAMPLE_POINTS[1][0]
    control.value = "1, 2; 3, 4"  # not held once released
    assert synced[-1] == {"value": "1, 2; 3, 4"}
