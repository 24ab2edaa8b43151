"""course.widgets.base: a control or a drag redraws the picture; the text repr is stable."""

import base64

import ipywidgets as widgets
import numpy as np
import pytest

from course.widgets.base import Handle, SliderApp, format_points, parse_points


class LineApp(SliderApp):
    """A minimal app: a horizontal line at height y."""

    def __init__(self) -> None:
        super().__init__({"y": widgets.FloatSlider(value=0.5, min=0, max=1)}, shape=(100, 200))
        axes = self.figure.add_axes((0, 0, 1, 1))
        axes.set_xlim(0, 1)
        axes.set_ylim(0, 1)
        axes.set_axis_off()
        (self.line,) = axes.plot([0, 1], [0.5, 0.5], color="black", linewidth=4)

    def update(self) -> None:
        y = self.value("y")
        self.line.set_ydata([y, y])


def dark_rows(app: LineApp) -> np.ndarray:
    rgba = app.view.pixels()
    return np.flatnonzero((rgba[..., :3] < 100).all(axis=2).any(axis=1))


def test_moving_a_slider_redraws_the_picture_where_the_value_says():
    app = LineApp()
    app.refresh()
    before = app.view.image.value
    rows = dark_rows(app)
    assert abs(rows.mean() - 50) < 2
    app.controls["y"].value = 0.9
    assert app.renders == 2
    assert app.view.image.value != before
    assert abs(dark_rows(app).mean() - 10) < 2


def test_repr_is_stable_text_plus_a_still_picture():
    app = LineApp()
    bundle = app._repr_mimebundle_()
    assert bundle["text/plain"] == "LineApp(y=0.5)"
    assert base64.b64decode(bundle["image/png"]).startswith(b"\x89PNG")
    assert "application/vnd.jupyter.widget-view+json" in bundle


class BoxApp(LineApp):
    """The line, a draggable point on it, and a draggable box: the base machinery alone."""

    def __init__(self) -> None:
        super().__init__()
        self.axes = self.line.axes
        self.point = np.array([0.25, 0.5])
        self.box = np.array([0.6, 0.3])  # lower-left corner of a 0.2 x 0.2 box
        self.clicks = []
        self.doubles = []

    def handles(self):
        x, y = self.box
        return [
            Handle("point", self.axes, tuple(self.point)),
            Handle("box", self.axes, (x, y), box=(x, y, x + 0.2, y + 0.2)),
        ]

    def drag(self, name, point):
        if name == "point":
            self.point = point
        else:
            self.box = point
        self.controls["y"].value = float(np.clip(point[1], 0, 1))

    def click(self, axes, point):
        self.clicks.append(tuple(np.round(point, 3)))
        return True

    def double_click(self, name):
        self.doubles.append(name)
        return True


def test_the_pointer_maps_picture_pixels_through_the_axes_both_ways():
    app = BoxApp()
    app.refresh()
    # Picture 200 x 100, axes filling it, data 0..1 both ways, y up in data.
    np.testing.assert_allclose(app.picture_point(app.axes, (0.25, 0.5)), [50, 50])
    np.testing.assert_allclose(app.data_point(app.axes, 50, 50), [0.25, 0.5])
    np.testing.assert_allclose(app.data_point(app.axes, 0, 100), [0, 0])
    assert app.axes_at(10, 10) is app.axes and app.axes_at(-5, 10) is None


def test_a_drag_keeps_the_grab_offset_and_redraws_once_per_move():
    app = BoxApp()
    app.refresh()
    app.pointer("down", 53, 50)  # 3 px right of the point, within the grab radius
    assert app.grabbed == "point" and app.renders == 2  # the highlight
    app.pointer("move", 103, 30)
    assert app.renders == 3  # one redraw, though drag() changed a control
    np.testing.assert_allclose(app.point, [0.5, 0.7])  # the point, not the pointer
    app.pointer("up", 403, -170)  # far outside the picture: data beyond the axes
    np.testing.assert_allclose(app.point, [2.0, 2.7])
    assert app.grabbed is None and app.value("y") == 1.0
    assert app.highlight_ring(app.axes)[0].get_xydata().size == 0


def test_boxes_are_grabbed_inside_points_win_ties_and_clicks_hit_empty_space():
    app = BoxApp()
    app.refresh()
    assert app.handle_at(140, 60).name == "box"  # inside (0.6..0.8, 0.3..0.5)
    assert app.handle_at(50 + app.GRAB_RADIUS + 1, 50) is None
    app.pointer("down", 150, 55)
    assert app.grabbed == "box"
    _, outline = app.highlight_ring(app.axes)
    assert outline.get_visible() and tuple(outline.get_xy()) == (0.6, 0.3)
    app.pointer("up", 150, 55)
    assert not outline.get_visible()
    app.pointer("down", 20, 80)
    app.pointer("up", 20 + app.CLICK_SLOP, 80)
    assert app.clicks == [(0.12, 0.2)]
    app.pointer("down", 20, 80)
    app.pointer("up", 40, 80)  # moved too far: not a click
    assert len(app.clicks) == 1
    app.pointer("double", 50, 50)
    app.pointer("double", 20, 80)  # on nothing: ignored
    assert app.doubles == ["point"]


def test_bad_pointer_events_are_refused_by_name_and_messages_are_answered():
    app = BoxApp()
    app.refresh()
    with pytest.raises(ValueError, match="kind must be one of 'down', 'move', 'up', 'double'"):
        app.pointer("hover", 1, 1)
    with pytest.raises(ValueError, match="x and y must be finite"):
        app.pointer("down", float("nan"), 1)
    sent = []
    app.view.image.send = sent.append
    app._on_message(app.view.image, {"kind": "down", "x": "oops"}, [])
    assert "Ignored a pointer message" in app.status.value
    app._on_message(app.view.image, {"kind": "down", "x": 50, "y": 50}, [])
    assert sent == [{"kind": "drawn"}, {"kind": "drawn"}] and app.grabbed == "point"


def test_the_browser_learns_where_the_handles_are():
    app = BoxApp()
    app.refresh()
    point, box = app.view.image.handles
    assert point == [50.0, 50.0, app.GRAB_RADIUS, 0, 0, 0, 0]
    assert box == [0, 0, 0, 120.0, 50.0, 160.0, 70.0]
    with pytest.raises(KeyError, match=r"expected one of the handles \['box', 'point'\]"):
        app.handle_named("P7")


def test_drag_along_presses_moves_and_releases_like_the_browser():
    app = BoxApp()
    app.refresh()
    start = app.drag_along("box", [(10, 0), (20, -10)])
    np.testing.assert_allclose(start, [140, 60])
    np.testing.assert_allclose(app.box, [0.7, 0.4])
    assert app.grabbed is None


def test_points_as_text_both_ways():
    points = parse_points("(1, 2.5); 3,4 ; -5e-1 6")
    np.testing.assert_array_equal(points, [[1, 2.5], [3, 4], [-0.5, 6]])
    assert parse_points(format_points(points)).tolist() == points.tolist()
    for text in ("1, 2, 3", "", "nothing"):
        with pytest.raises(ValueError, match="an x and a y each"):
            parse_points(text)
