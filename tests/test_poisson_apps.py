"""course.lessons.l08_poisson.apps: the sweep slider shows the library's iterate and its error."""

import re

import numpy as np
import pytest
import scipy.ndimage

from course import poisson
from course.lessons.l08_poisson.apps import CloneApp, PoissonIterationApp, half_size

RNG = np.random.default_rng(4)
BACKGROUND = scipy.ndimage.gaussian_filter(RNG.random((40, 60, 3)), (3, 3, 0)) * 0.5 + 0.25
FOREGROUND = RNG.random((20, 30, 3)) * 0.3 + 0.6
OFFSET = (15, 10)


@pytest.fixture
def app():
    app = PoissonIterationApp(BACKGROUND, FOREGROUND, OFFSET, stops=(0, 1, 10, 50))
    app.refresh()
    return app


def test_moving_the_sweep_slider_shows_the_library_iterate(app):
    before = app.view.image.value
    app.controls["sweeps"].value = 50
    assert app.view.image.value != before
    expected = poisson.seamless_clone(
        BACKGROUND, FOREGROUND, OFFSET, method="jacobi", iterations=50, clip=False
    )
    shown = np.asarray(app.picture.get_array())
    assert np.allclose(shown, np.clip(expected, 0, 1)[app.window], atol=1e-12)
    assert "Jacobi, 50 sweeps" in app.caption.get_text()


def test_the_error_panel_is_the_distance_to_the_exact_solution(app):
    app.controls["method"].value = "sor"
    app.controls["sweeps"].value = 10
    iterate = poisson.seamless_clone(
        BACKGROUND, FOREGROUND, OFFSET, method="sor", iterations=10, clip=False
    )
    exact = poisson.seamless_clone(BACKGROUND, FOREGROUND, OFFSET, clip=False)
    error = np.abs(iterate - exact).max(axis=2) * 255
    assert np.allclose(np.asarray(app.error_image.get_array()), error[app.window], atol=1e-9)
    assert f"error up to {error.max():.1f} grey levels" in app.caption.get_text()


def test_more_sweeps_leave_less_error_and_going_back_reuses_the_iterate(app):
    errors = []
    for sweeps in (1, 10, 50):
        app.controls["sweeps"].value = sweeps
        errors.append(np.asarray(app.error_image.get_array()).max())
    assert errors[0] > errors[1] > errors[2]
    kept = app.iterate("jacobi", 10)
    app.controls["sweeps"].value = 10
    assert app.iterate("jacobi", 10) is kept


def test_the_default_scene_is_the_lab_scene():
    app = PoissonIterationApp(stops=(0, 1))
    assert app.problem.corner == (500, 300)
    assert app.problem.region.shape == (111, 280)
    assert app.describe() == "PoissonIterationApp(method='jacobi', sweeps=0)"


def test_the_clone_app_follows_a_drag_with_the_library_s_paste_and_clone():
    background = np.tile(np.linspace(0.2, 0.8, 40), (30, 1))
    foreground = np.full((10, 12), 0.9)
    foreground[3:7, 4:8] = 0.1  # a dark spot on a light patch
    app = CloneApp(background, foreground, offset=(4, 6))
    app.refresh()
    start = app.drag_along("foreground", [(5, 5), (3.0, 2.0)])
    x, y = app.offset
    # Grabbed at the patch's middle, (4 + 6, 6 + 5); a screen pixel is 2 image pixels.
    pointer = app.data_point(app.panels["naive paste"], *np.add(start, (3, 2)))
    np.testing.assert_allclose(pointer, (10 + 6, 11 + 4))
    assert (x, y) == (10, 10) and app.value("offset") == "10, 10"
    clone = half_size(poisson.seamless_clone(background, foreground, (x, y)))
    naive = half_size(poisson.naive_paste(background, foreground, (x, y)))
    np.testing.assert_allclose(app.shown["seamless clone"], clone, atol=1e-12)
    np.testing.assert_array_equal(app.shown["naive paste"], naive)
    # Pixel for pixel in the picture, where the panel is, as imshow would draw it.
    box = app.panels["naive paste"].get_window_extent()
    left, top = round(box.x0), round(app.figure.bbox.height - box.y1)
    drawn = app.view.pixels()[top : top + 15, left : left + 20, :3]
    expected = np.repeat((np.clip(naive, 0, 1) * 255).astype(np.uint8)[..., None], 3, axis=2)
    np.testing.assert_array_equal(drawn, expected)
    app.drag_along("foreground", [(-10_000, 10_000)])  # beyond the image: the corner it fits
    assert tuple(app.offset) == (0, 30 - 10)
    app.controls["offset"].value = "35, 0"
    assert "x must lie from 0 to 28" in app.status.value and tuple(app.offset) == (0, 20)
    assert app.view.image.format == "jpeg" and bytes(app.view.image.value)[:2] == b"\xff\xd8"


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("abc", "'abc' is not x, y: there is no number in it (type one point as x, y"),
        ("420", "'420' is not x, y: a point is two numbers; got 1 (type one point as x, y"),
        ("", "expected one point such as '10, 20'; got ''"),
    ],
)
def test_the_offset_box_says_what_is_wrong_with_the_one_point_typed(text, said):
    app = CloneApp(np.tile(np.linspace(0.2, 0.8, 40), (30, 1)), np.full((10, 12), 0.9), (4, 6))
    app.refresh()
    app.controls["offset"].value = text
    assert said in app.status.value
    assert app.status.value.startswith("Kept the last offset: ")
    assert "point 1" not in app.status.value and "separate points" not in app.status.value
    assert tuple(app.offset) == (4, 6)


@pytest.mark.parametrize(
    ("shape", "said"),
    [
        ((2, 5), "foreground must be at least 3 x 3 pixels"),
        ((30, 5), "foreground of shape (30, 5) at offset (x, y) = (0, 0) does not fit inside"),
    ],
)
def test_the_clone_app_refuses_a_foreground_without_an_inside_or_larger_than_the_background(
    shape, said
):
    with pytest.raises(ValueError, match=re.escape(said)):
        CloneApp(np.zeros((20, 20)), np.ones(shape), (1, 1))
