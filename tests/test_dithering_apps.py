"""course.lessons.l06_dithering.apps, driven through its sliders: the picture shows the library."""

import numpy as np
import pytest

from course.halftone import dither
from course.halftone.blue_noise_masks import cluster_energy
from course.images import ramp
from course.lessons.l06_dithering.apps import (
    DitherComparisonApp,
    GrayLevelApp,
    VoidAndClusterApp,
)


def test_comparison_app_crops_follow_the_window_and_show_each_method():
    gray = ramp((40, 96))
    app = DitherComparisonApp(gray, size=8)
    before = app.refresh()
    app.controls["window"].value = "20, 30"
    assert app.view.image.value != before
    # Window of 8 around (20.5, 30.5), shifted to stay on the 40-row image.
    rows, columns = slice(26, 34), slice(16, 24)
    expected = dither.error_diffusion(gray)[rows, columns]
    assert np.array_equal(app.crops["Floyd-Steinberg"].get_array(), expected)
    ordered = dither.ordered(gray)[3 * 26 : 3 * 34, 3 * 16 : 3 * 24]
    assert np.array_equal(app.crops["ordered 3x3"].get_array(), ordered)
    assert app.window.get_x() == 16 and app.window.get_y() == 26
    assert app.describe() == "DitherComparisonApp(window='20, 30')"


def test_dragging_the_window_moves_it_by_the_pointer_and_stops_at_the_edge():
    gray = ramp((40, 96))
    app = DitherComparisonApp(gray, size=8)
    app.refresh()
    start = app.press_point("window")
    app.pointer("down", *np.add(start, (3, 0)))  # anywhere inside the window grabs it
    assert app.grabbed == "window"
    app.pointer("move", *np.add(start, (3 + 20, 10)))
    app.pointer("up", *np.add(start, (3 + 20, 10)))
    shift = app.data_point(app.overview, *np.add(start, (20, 10))) - app.data_point(
        app.overview, *start
    )
    expected = np.floor(np.array([48.5, 20.5]) + shift).astype(int)
    assert app.value("window") == f"{expected[0]}, {expected[1]}"
    app.drag_along("window", [(10_000, 10_000)])
    assert app.value("window") == "95, 39"
    app.controls["window"].value = "200, 3"
    assert "x must lie from 0 to 95, y from 0 to 39" in app.status.value
    assert app.value("window") == "200, 3"  # as typed, to be fixed


@pytest.mark.parametrize("lit", [0, 4, 9])
def test_gray_level_app_shows_each_method_on_the_flat_patch(lit):
    app = GrayLevelApp(level=0.5, size=12)
    before = app.refresh()
    app.controls["level"].value = lit / 9
    assert app.renders == 2 and app.view.image.value != before
    patch = np.full((12, 12), lit / 9)
    assert np.array_equal(app.panels["Floyd-Steinberg"].get_array(), dither.error_diffusion(patch))
    assert np.array_equal(app.panels["Bayer 8x8"].get_array(), dither.bayer(patch, 8))
    cells = np.asarray(app.panels["ordered 3x3"].get_array()).reshape(12, 3, 12, 3)
    assert np.all(cells.sum(axis=(1, 3)) == lit)
    assert app.highlight.get_x() == pytest.approx(4 * lit - 0.1)
    assert f"lit {lit / 9 if lit else 0:.3f}" in app.titles["ordered 3x3"].get_text()


def test_gray_level_strip_holds_the_ten_patterns():
    strip = GrayLevelApp.ordered_patterns()
    for k in range(10):
        assert strip[:, 4 * k : 4 * k + 3].sum() == k


def test_void_and_cluster_app_shows_the_first_dots_and_the_next_at_the_largest_void():
    app = VoidAndClusterApp(size=16, dots=10)
    before = app.refresh()
    app.controls["dots"].value = 100
    assert app.view.image.value != before
    pattern = app.ranks < 100
    overlay = np.asarray(app.dots.get_array())
    assert np.array_equal(overlay[..., 3] == 1, pattern)
    assert np.allclose(app.energy.get_array(), cluster_energy(pattern))
    x, y = app.next_dot.get_data()
    energy = cluster_energy(pattern)
    assert app.ranks[y[0], x[0]] == 100
    assert energy[y[0], x[0]] <= energy[~pattern].min() + 1e-9
    assert "phase 2" in app.heading.get_text()
    app.controls["dots"].value = 5
    assert "phase 1" in app.heading.get_text()
    assert "x white noise" in app.ratio.get_text()
