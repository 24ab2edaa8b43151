"""Lesson 04's app: the supersampled result and its error, as the library computes them."""

import numpy as np
import pytest

from course.images import zone_plate, zone_plate_box
from course.lessons.l04_supersampling.apps import SupersampleApp
from course.metrics import rmse
from course.sampling.resample import supersample, supersample_without_offset


def set_values(app, **values):
    for name, value in values.items():
        app.controls[name].value = value


@pytest.fixture(scope="module")
def small_supersample_app():
    # The lab's ratio at a fifth of the size keeps the test quick.
    return SupersampleApp(size=500, out_size=64, max_rate=6, reference_rate=8)


def test_supersample_app_shows_the_result_and_its_error_at_each_rate(small_supersample_app):
    app = small_supersample_app
    set_values(app, image="zone plate", version="centred", rate=1)
    plate, exact = zone_plate((500, 500)), zone_plate_box((500, 500), (64, 64))
    set_values(app, rate=4)
    result = supersample(plate, (64, 64), 4)
    np.testing.assert_allclose(app.result.get_array(), result)
    assert f"RMS {rmse(result, exact):.4f}" in app.difference_axes.get_title()
    curve = app.curves["centred"].get_ydata()
    assert curve[3] == pytest.approx(rmse(result, exact))
    assert curve[0] > 0.25 > 0.01 > curve[3]
    set_values(app, version="report's")
    shifted = supersample_without_offset(plate, (64, 64), 4)
    np.testing.assert_allclose(app.result.get_array(), shifted)
    assert tuple(app.current.get_ydata()) == (pytest.approx(rmse(shifted, exact)),)


def test_supersample_app_switches_to_the_photograph(small_supersample_app):
    app = small_supersample_app
    before = app.view.image.value
    set_values(app, image="photograph", version="centred", rate=2)
    assert app.view.image.value != before
    assert app.result.get_array().shape == (64, 64, 3)
    np.testing.assert_allclose(
        app.result.get_array(), supersample(app.sources["photograph"], (64, 64), 2)
    )
    assert "rate 8" in app.difference_axes.get_title()


def test_the_difference_s_colour_scale_follows_the_error(small_supersample_app):
    app = small_supersample_app
    for rate, version in ((1, "centred"), (4, "report's"), (6, "centred")):
        set_values(app, image="zone plate", version=version, rate=rate)
        app.refresh()  # drawn even when the controls already held these values
        low, high = app.difference.get_clim()
        largest = np.abs(app.difference.get_array()).max()
        assert low == -high and (largest <= high or high == 0.5)  # 0.5 at most: clipped past it
        smaller = [step for step in (0.5, 0.2, 0.1, 0.05, 0.02, 0.01) if step < high]
        assert not smaller or largest > smaller[0]  # the tightest scale that holds it
    set_values(app, rate=1)
    app.refresh()
    assert app.difference.get_clim() == (-0.5, 0.5)  # aliasing at rate 1 fills the scale
