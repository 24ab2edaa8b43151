"""Lesson 01's still pictures: the numbers their captions print, checked independently."""

import re

import numpy as np

from course.bezier_handouts import HANDOUT_LOOPS, yellow_check
from course.images import SEED_000_CUBIC
from course.widgets import de_casteljau_figures as figures


def last_t(step, dtype):
    """The last t a C++ ``for (t = 0; t <= 1; t += step)`` loop of ``dtype`` takes."""
    t, step, last = dtype(0), dtype(step), None
    while t <= dtype(1):
        last, t = t, dtype(t + step)
    return float(last)


def test_the_end_of_curve_caption_gives_each_loop_s_last_t_and_whether_b1_s_pixel_is_painted():
    caption = figures.end_of_curve_figure(SEED_000_CUBIC).caption
    assert "B(1) = (690, 690) in pixel (690, 690)" in caption
    games101, vs2022 = re.findall(r"last t ([\d.]+)", caption)
    assert float(games101) == float(f"{last_t(0.001, np.float32):.7g}")
    assert float(vs2022) == float(f"{last_t(0.001, np.float64):.7g}") == 0.999
    # Rounding the float loop's last point reaches B(1)'s pixel; truncating 0.999's does not.
    assert "the GAMES101 report paints it" in caption and "the VS2022 report does not" in caption


def test_the_yellow_check_caption_counts_the_pixels_each_curve_paints_alone():
    for seed in ("000", "002"):
        check = yellow_check(SEED_000_CUBIC, HANDOUT_LOOPS[seed])
        red = check.image[..., 0] > 0
        green = check.image[..., 1] > 0
        caption = figures.yellow_check_figure(SEED_000_CUBIC, seed).caption
        assert (
            f"{np.count_nonzero(red & green) / np.count_nonzero(red | green):.1%} yellow" in caption
        )
        assert f"{np.count_nonzero(red & ~green)} pixels only red" in caption
        assert f"{np.count_nonzero(green & ~red)} only green" in caption
