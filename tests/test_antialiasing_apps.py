"""Lesson 05's apps: the sliders move the picture to what the library computes."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.figure import Figure
from scipy.spatial import cKDTree

from course.antialias import render
from course.antialias.coverage import reference
from course.antialias.curve_quality import REFERENCE, intensity_along
from course.antialias.windows import render_window
from course.i18n import language
from course.images import SEED_000_CUBIC
from course.lessons.l05_antialiasing.apps import StepApp, ZoomApp, label_of
from course.lessons.l05_antialiasing.zoom_panel import CurveWalk, ZoomPanel, zoom_figure
from course.raster.canvas import crop

CURVE = SEED_000_CUBIC / 5
SHAPE = (140, 140)


@pytest.fixture(scope="module")
def images():
    return {
        name: render(CURVE, SHAPE, name)
        for name in ("nearest_round", "bilinear_corners", "bilinear_centres", "stroke_area")
    }


@pytest.fixture(scope="module")
def exact():
    return reference(CURVE, SHAPE, 1.0, k=16)


PICKS = ("nearest_round", "bilinear_corners", "stroke_area")


def test_zoom_app_moves_its_window_along_the_curve(images, exact):
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=16)
    before = app.refresh()
    centre = app.centre()
    # The window shows exactly the crop of the whole rendering around the curve point.
    window, extent = crop(images["nearest_round"], centre, 16)
    np.testing.assert_allclose(app.windows[0], window, atol=1e-9)
    # The panels' data are the window's pixels from its corner, where the curve is drawn.
    left, top = extent[0], extent[3]
    assert app.panels[0].axes.get_xlim() == (0, 16) and app.panels[0].axes.get_ylim() == (16, 0)
    x, y = app.panels[0].curve.get_data()
    drawn = np.column_stack([x, y])[~np.isnan(x)] + (left, top)
    walk = CurveWalk(CURVE).polyline
    assert len(drawn) > 16 and all((walk == vertex).all(axis=1).any() for vertex in drawn)
    assert (np.abs(drawn - (left + 8, top + 8)) <= 8 + 3).all()
    app.controls["position"].value = 0.5
    assert app.renders == 2 and app.view.image.value != before
    middle = CurveWalk(CURVE).at(0.5)
    np.testing.assert_allclose(app.centre(), middle)
    np.testing.assert_allclose(middle, [70.0, 70.0], atol=1e-6)  # the S's centre
    np.testing.assert_allclose(
        app.windows[2], crop(images["stroke_area"], middle, 16)[0], atol=1e-9
    )
    np.testing.assert_allclose(app.windows[3], crop(exact, middle, 16)[0], atol=1e-9)


def test_zoom_app_picks_variants_and_sizes(images):
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=16)
    app.refresh()
    app.controls["middle"].value = "bilinear_centres"
    window, _ = crop(images["bilinear_centres"], app.centre(), 16)
    np.testing.assert_allclose(app.windows[1], window, atol=1e-9)
    assert app.panels[1].title.get_text() == label_of("bilinear_centres")
    app.controls["size"].value = 32
    assert app.windows[1].shape == (32, 32)
    # The grid has one line per pixel edge: 33 columns and 33 rows.
    assert len(app.panels[1].grid.get_segments()) == 66
    # Every window size fills its 192-pixel panel at a whole zoom.
    assert all(ZoomApp.PANEL % size == 0 for size in ZoomApp.SIZES)
    assert app.describe().startswith("ZoomApp(position=0.1, size=32, left='nearest_round'")


def test_dragging_a_control_point_redraws_every_window_for_the_new_curve():
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=16)
    app.refresh()
    start = app.picture_point(app.overview, CURVE[1])
    app.pointer("down", *start)
    assert app.grabbed == "P1"
    app.pointer("move", *np.add(start, (-20, 15)))
    dragging_note = app.panels[3].note.get_text()
    app.pointer("up", *np.add(start, (-40, 30)))
    moved = np.asarray(app.points)
    expected = app.data_point(app.overview, *np.add(start, (-40, 30)))
    np.testing.assert_allclose(moved[1], np.round(expected, 1))
    np.testing.assert_array_equal(moved[[0, 2, 3]], CURVE[[0, 2, 3]])
    assert app.value("points").startswith("2, 2; ")
    centre = CurveWalk(moved).at(app.value("position"))
    for index, name in enumerate(PICKS):
        whole = render(moved, SHAPE, name)
        np.testing.assert_allclose(app.windows[index], crop(whole, centre, 16)[0], atol=1e-9)
    exact = reference(moved, SHAPE, 1.0, 16)
    np.testing.assert_allclose(app.windows[3], crop(exact, centre, 16)[0], atol=1e-9)
    assert app.panels[3].title.get_text() == "exact coverage"
    assert [panel.title.get_text() for panel in app.panels[:3]] == [label_of(p) for p in PICKS]
    assert dragging_note == app.panels[3].note.get_text() == "16 x 16 samples a pixel"


def test_while_dragging_the_reference_takes_fewer_samples():
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=32)
    app.refresh()
    start = app.picture_point(app.overview, CURVE[2])
    app.pointer("down", *start)
    app.pointer("move", *np.add(start, (5, 0)))
    assert app.panels[3].note.get_text() == "16 x 16 samples a pixel"
    app.pointer("up", *np.add(start, (5, 0)))
    assert app.panels[3].note.get_text() == "32 x 32 samples a pixel"


@settings(max_examples=25, deadline=None)
@given(
    offsets=st.lists(st.tuples(st.floats(-60, 60), st.floats(-60, 60)), min_size=1, max_size=3),
    position=st.integers(0, 200),
    size=st.sampled_from(ZoomApp.SIZES),
)
def test_a_drags_reference_lies_between_the_references_of_a_stroke_a_hair_thinner_and_thicker(
    offsets, position, size
):
    # During a drag the reference comes from the app's own polyline (within 1e-3 px of
    # the curve), cut near the window: a sample it counts lies within 0.5 + 1e-3 of the
    # curve, one it leaves out beyond 0.5 - 1e-3. The release draws the reference itself.
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=16)
    app.controls["position"].value = position * 0.005
    app.controls["size"].value = size
    app.refresh()
    start = app.picture_point(app.overview, CURVE[1])
    app.pointer("down", *start)
    for offset in offsets:
        app.pointer("move", *np.add(start, offset))
        points, centre = app.points, app.centre()
        thinner, _ = render_window(REFERENCE, points, SHAPE, centre, size, 1 - 2.5e-3, 16)
        thicker, _ = render_window(REFERENCE, points, SHAPE, centre, size, 1 + 2.5e-3, 16)
        assert (thinner <= app.windows[3]).all() and (app.windows[3] <= thicker).all()
        assert app.panels[3].note.get_text() == "16 x 16 samples a pixel" and app.walk.quick
    app.pointer("up", *np.add(start, offsets[-1]))
    assert not app.walk.quick  # walked the usual way, even where the release did not move
    window, _extent = render_window(REFERENCE, app.points, SHAPE, app.centre(), size, 1.0, 16)
    np.testing.assert_array_equal(app.windows[3], window)


def test_zoom_app_rejects_unknown_picks_and_keeps_points_on_bad_text():
    with pytest.raises(ValueError, match="picks must be three names"):
        ZoomApp(CURVE, SHAPE, picks=("nearest_round", "gaussian", "stroke_area"))
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=16)
    app.controls["points"].value = "1, 2; 3, 4"
    assert "expected 4 points" in app.status.value
    np.testing.assert_array_equal(app.points, CURVE)


def test_step_app_shows_gaps_saturation_and_the_fix():
    app = StepApp(CURVE, SHAPE)
    app.refresh()
    fine = app.image.copy()
    np.testing.assert_array_equal(fine, render(CURVE, SHAPE, "bilinear_centres", step=0.001))
    _positions, density = intensity_along(fine, CURVE)
    np.testing.assert_allclose(app.profile.get_ydata(), density)
    # Step 0.001 on a 5x smaller curve: several samples per pixel, saturated.
    assert fine.max() == 1.0 and density.max() > 1.5
    app.controls["step"].value = 0.04
    coarse = app.image
    assert coarse.sum() < fine.sum() / 4
    assert "CV" in app.profile_title.get_text()
    app.controls["weighting"].value = "arc_length"
    # Samples 6 px apart: each splat is clipped at 1, the gaps lose ink.
    assert app.profile.get_ydata().mean() < 0.8
    app.controls["step"].value = 0.001
    assert np.abs(app.profile.get_ydata() - 1.0).max() < 0.05
    app.controls["method"].value = "nearest_truncate"
    np.testing.assert_array_equal(
        app.image, render(CURVE, SHAPE, "nearest_truncate", step=0.001, weighting="arc_length")
    )


def test_the_step_apps_weighting_toggle_is_labelled_and_says_its_options_in_chinese():
    app = StepApp(CURVE, SHAPE)
    toggle = app.controls["weighting"]
    assert toggle.description == "weighting"
    assert list(toggle.options) == [("count", "count"), ("arc length", "arc_length")]
    with language("zh-CN"):
        chinese = StepApp(CURVE, SHAPE)
        chinese.controls["weighting"].value = "arc_length"
        chinese.refresh()
        title = chinese.profile_title.get_text()
    toggle = chinese.controls["weighting"]
    # The names the lesson's prose gives them, and the values the library takes.
    assert toggle.description == "加权方式"
    assert list(toggle.options) == [("按计数", "count"), ("按弧长", "arc_length")]
    assert "按弧长" in title and "arc" not in title


def test_zoom_figure_has_one_panel_per_image(images):
    figure = zoom_figure(images, CURVE, (70, 70), size=12, columns=2)
    assert len(figure.axes) == 4
    assert [axes.get_title() for axes in figure.axes] == list(images)


def test_zoom_windows_are_shown_pixel_for_pixel_and_new_titles_reach_the_picture():
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=16)
    app.refresh()
    axes = app.panels[1].axes
    box = axes.get_window_extent()
    left, top = round(box.x0), round(app.view.figure.bbox.height - box.y1)
    zoom = ZoomApp.PANEL // 16
    shown = app.view.pixels()[top : top + ZoomApp.PANEL, left : left + ZoomApp.PANEL]
    # The centre of each zoomed pixel: away from the grid lines drawn on top.
    centres = shown[zoom // 2 :: zoom, zoom // 2 :: zoom, 0].astype(float)
    expected = np.floor(np.clip(app.windows[1], 0, 1) * 255)
    off_curve = np.abs(centres - expected) > 1
    assert off_curve.mean() < 0.1  # only where the true curve is drawn across
    title_rows = slice(0, top)
    before = app.view.pixels()[title_rows, left : left + ZoomApp.PANEL].copy()
    app.controls["middle"].value = "bilinear_centres"
    after = app.view.pixels()[title_rows, left : left + ZoomApp.PANEL]
    assert not np.array_equal(before, after)
    assert app.panels[1].title.get_text() == label_of("bilinear_centres")


def test_points_typed_far_off_the_canvas_are_drawn_clipped_to_it_and_the_app_says_so():
    app = ZoomApp(CURVE, SHAPE, picks=PICKS, k=8)
    app.refresh()
    # Before, this curve millions of pixels long took 38 s and 3.4 GB to draw.
    app.controls["points"].value = "-1e6, -1e6; 1e6, 1e6; 5, 5; 7, 7"
    np.testing.assert_array_equal(app.points, [[0, 0], [140, 140], [5, 5], [7, 7]])
    assert app.status.value == (
        "Clipped P0, P1 to the 140 x 140 canvas (x from 0 to 140, y from 0 to 140), "
        "where the app draws: 0, 0; 140, 140"
    )
    assert app.value("points") == "-1e6, -1e6; 1e6, 1e6; 5, 5; 7, 7"  # as typed
    # The work is bounded by the canvas: the curve is no longer than its control polygon.
    polygon = np.hypot(*np.diff(app.points, axis=0).T).sum()
    assert app.walk.lengths[-1] <= polygon
    assert len(app.walk.polyline) <= 2 * polygon + 2  # segments of at most one pixel
    assert all(window.shape == (16, 16) for window in app.windows)
    app.controls["points"].value = "10, 10; 130, 10; 10, 130; 130, 130"
    assert app.status.value == ""
    np.testing.assert_array_equal(app.points, [[10, 10], [130, 10], [10, 130], [130, 130]])


def test_zoom_app_clips_points_given_off_its_canvas_too():
    app = ZoomApp(CURVE * [1, -1], SHAPE, picks=PICKS, k=8)
    assert app.status.value.startswith("Clipped P0, P1, P2, P3 to the 140 x 140 canvas")
    assert (app.points[:, 1] == 0).all()


@pytest.mark.parametrize("points", [CURVE, SEED_000_CUBIC, [[0, 0], [300, 40], [10, 60]]])
def test_a_quick_walk_keeps_within_1e_3_of_the_curve_in_pieces_of_at_most_a_pixel(points):
    control = np.asarray(points, dtype=float)
    quick, usual = CurveWalk(control, quick=True), CurveWalk(control)
    assert quick.quick and not usual.quick
    line = quick.polyline
    np.testing.assert_array_equal(line[[0, -1]], control[[0, -1]])
    assert np.hypot(*np.diff(line, axis=0).T).max() <= 1.0 + 1e-9
    # The curve, sampled densely by its Bernstein form, next to every vertex.
    t = np.linspace(0.0, 1.0, 2_000_001)[:, None]
    degree = len(control) - 1
    curve = sum(
        math.comb(degree, i) * t**i * (1 - t) ** (degree - i) * control[i]
        for i in range(degree + 1)
    )
    distance, _index = cKDTree(curve).query(line)
    assert distance.max() <= 1.1e-3
    assert abs(quick.lengths[-1] - usual.lengths[-1]) <= 1e-3
    np.testing.assert_allclose(quick.at(0.37), usual.at(0.37), atol=2e-3)


def test_curve_walk_and_zoom_panel_refuse_what_they_cannot_draw():
    walk = CurveWalk(CURVE)
    np.testing.assert_array_equal(walk.at(1.5), walk.at(1.0))  # past the end: the end
    with pytest.raises(TypeError, match="fraction must hold real numbers"):
        walk.at("abc")
    with pytest.raises(ValueError, match="fraction must be finite"):
        walk.at(float("nan"))
    axes = Figure().add_subplot()
    with pytest.raises(TypeError, match="axes must be a matplotlib Axes"):
        ZoomPanel(None, walk.polyline)
    with pytest.raises(ValueError, match="curve must be a 2-D array"):
        ZoomPanel(axes, np.zeros(0))
    with pytest.raises(ValueError, match="curve must be finite"):
        ZoomPanel(axes, [[0.0, 0.0], [np.nan, 1.0]])


def test_a_zoom_panels_window_is_refused_when_not_finite_or_its_extent_does_not_span_it():
    app = ZoomApp()
    panel = app.panels[0]
    window = np.zeros((4, 5))
    with pytest.raises(ValueError, match="window"):
        panel.show_window(np.full((4, 5), np.nan), (0, 5, 4, 0), "t")
    with pytest.raises(ValueError, match="extent must be"):
        panel.show_window(window, (0, 5, 4), "t")
    with pytest.raises(ValueError, match="span the window's 5 columns and 4 rows"):
        panel.show_window(window, (0, 6, 4, 0), "t")
    with pytest.raises(TypeError, match=r"extent\[0\]"):
        panel.show_window(window, (0.5, 5, 4, 0), "t")
    assert panel.show_window(window, (10, 15, 24, 20), "t") is not None
