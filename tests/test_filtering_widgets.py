"""Lesson 07's app: repeated blurs under each border rule, as course.filters computes them."""

import numpy as np

from course import filters
from course.widgets.filtering import RepeatedBlurApp, border_ring_mean


def test_repeated_blur_app_applies_each_border_rule_n_times():
    image = np.random.default_rng(0).random((20, 24, 3))
    app = RepeatedBlurApp(image, repeats=0, corner=6)
    before = app.refresh()
    assert np.array_equal(app.wholes["zero"].get_array(), image)
    app.controls["repeats"].value = 3
    assert app.view.image.value != before
    handout = filters.blur(filters.blur(filters.blur(image)))
    assert np.allclose(app.wholes["handout"].get_array(), handout, atol=1e-15)
    zero = image
    for _ in range(3):
        zero = filters.convolve(zero, filters.BOX, "zero")
    assert np.allclose(app.wholes["zero"].get_array(), zero, atol=1e-15)
    assert np.allclose(app.crops["zero"].get_array(), zero[:6, -6:], atol=1e-15)
    # Back to fewer blurs: recomputed from the original.
    app.controls["repeats"].value = 1
    assert np.allclose(
        app.wholes["replicate"].get_array(), filters.convolve(image, filters.BOX, "replicate")
    )
    assert app.describe() == "RepeatedBlurApp(repeats=1)"


def test_repeated_blur_app_measures_the_dark_frame_of_zero_padding():
    app = RepeatedBlurApp(np.full((16, 16), 0.5), repeats=4)
    assert "at 1.00 x" in app.titles["handout"].get_text()
    assert "at 1.00 x" in app.titles["reflect"].get_text()
    ratio = border_ring_mean(app.wholes["zero"].get_array()) / 0.5
    assert ratio < 0.8 and f"at {ratio:.2f} x" in app.titles["zero"].get_text()
