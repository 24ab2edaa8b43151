"""FigureView's held background: a drag's press and release draw what the whole figure draws.

A press holds the handles it does not move still (``FigureView.hold``): they are
drawn over the background kept without them, unless something the figure
draws later overlaps them. Either way the background must be, pixel for pixel,
the figure drawn anew; and the release's picture the one a fresh render shows.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from course.lessons.l01_de_casteljau.apps import DeCasteljauApp
from course.widgets.base import format_points


def quiet_app(points) -> DeCasteljauApp:
    app = DeCasteljauApp()
    app.view.image.send = lambda content, buffers=None: None  # no browser in a test
    app.controls["points"].value = format_points(points)  # the count follows
    app.refresh()
    np.testing.assert_allclose(app.points, points, atol=0.05)  # as typed, to 2 decimals
    return app


def held_background(app: DeCasteljauApp) -> np.ndarray:
    view = app.view
    view.canvas.restore_region(view._background)
    return np.asarray(view.canvas.buffer_rgba()).copy()


def figure_drawn_anew(app: DeCasteljauApp) -> np.ndarray:
    app.view.canvas.draw()  # every artist not animated, as the figure draws them
    return np.asarray(app.view.canvas.buffer_rgba()).copy()


def pressed(app: DeCasteljauApp, name: str) -> None:
    app.pointer("down", *app.press_point(name))


# Points inside lesson 01's 700 x 700 view: labels anywhere, on each other, on the
# legend in the lower right.
points_in_view = st.lists(
    st.tuples(st.integers(10, 690), st.integers(10, 690)), min_size=3, max_size=6
)


@settings(max_examples=12, deadline=None)
@given(points=points_in_view, grabbed=st.integers(0, 5), moves=st.integers(0, 3))
def test_a_press_holds_the_other_handles_as_the_whole_figure_draws_them(points, grabbed, moves):
    app = quiet_app(points)
    name = f"P{grabbed % len(points)}"
    start = app.press_point(name)
    app.pointer("down", *start)
    for step in range(moves):
        app.pointer("move", *(start + np.array([3.0, -2.0]) * step))
    assert app.view._background is not None
    np.testing.assert_array_equal(held_background(app), figure_drawn_anew(app))


@settings(max_examples=8, deadline=None)
@given(points=points_in_view, grabbed=st.integers(0, 5))
def test_a_release_shows_the_picture_a_fresh_render_shows(points, grabbed):
    app = quiet_app(points)
    app.drag_along(f"P{grabbed % len(points)}", [(4, 3), (9, -5)])
    released = app.view.pixels()
    app.view.invalidate()
    app.refresh()
    np.testing.assert_array_equal(released, app.view.pixels())


def test_a_label_over_the_legend_is_drawn_with_the_whole_figure():
    # P2's label on the legend (lower right): drawn over the kept background it would
    # cover the legend the figure draws after it, so the press draws the figure anew.
    app = quiet_app([(100.0, 100.0), (400.0, 200.0), (600.0, 100.0)])
    legend = app.axes.get_legend().get_window_extent()
    inside = app.axes.transData.inverted().transform((legend.x0 + 12, legend.y0 + 6))
    app.controls["points"].value = format_points([(100.0, 100.0), (400.0, 200.0), tuple(inside)])
    label = app.labels[2].get_window_extent(app.view.canvas.get_renderer())
    assert legend.overlaps(label)
    pressed(app, "P0")
    assert not app.view._drawn_on_top(app.view._in_drawing_order(app.view._held))
    np.testing.assert_array_equal(held_background(app), figure_drawn_anew(app))


def test_labels_clear_of_everything_are_drawn_over_the_kept_background():
    app = quiet_app([(100.0, 100.0), (400.0, 200.0), (600.0, 100.0)])
    pressed(app, "P1")
    assert app.view._still is not None
    assert app.view._drawn_on_top(app.view._in_drawing_order(app.view._held))
    np.testing.assert_array_equal(held_background(app), figure_drawn_anew(app))


def test_labels_on_each_other_are_held_in_the_order_the_figure_draws_them():
    app = quiet_app([(300.0, 300.0), (500.0, 500.0), (303.0, 302.0), (306.0, 298.0)])
    pressed(app, "P1")
    held = app.view._in_drawing_order(app.view._held)
    assert [text.get_text() for text in held[:3]] == ["P0", "P2", "P3"]
    assert app.view._drawn_on_top(held)
    np.testing.assert_array_equal(held_background(app), figure_drawn_anew(app))
