"""Lesson 02's still pictures: the numbers their captions print, checked independently."""

import re

import numpy as np

from course.lessons.l02_bernstein import figures


def test_the_hodograph_caption_names_the_slowest_and_fastest_point_of_the_curve():
    """Speed is the hodograph's distance from the origin; checked on a finer grid."""
    points = np.array([[90.0, 610.0], [170.0, 130.0], [540.0, 80.0], [620.0, 470.0]])
    caption = figures.hodograph_figure(points).caption
    slow_t, slow_speed = re.search(r"slowest at t = ([\d.]+), (\d+) px", caption).groups()
    fast_t, fast_speed = re.search(r"fastest at t = ([\d.]+), (\d+)", caption).groups()
    fine = np.linspace(0.0, 1.0, 100001)
    # B'(t) of a cubic by hand: 3 [(1-t)^2 (P1-P0) + 2 t (1-t) (P2-P1) + t^2 (P3-P2)].
    d0, d1, d2 = 3 * np.diff(points, axis=0)
    velocity = (
        ((1 - fine) ** 2)[:, None] * d0
        + (2 * fine * (1 - fine))[:, None] * d1
        + (fine**2)[:, None] * d2
    )
    speed = np.hypot(*velocity.T)
    assert abs(float(slow_t) - fine[np.argmin(speed)]) <= 1e-3
    assert abs(int(slow_speed) - speed.min()) <= 1
    assert abs(float(fast_t) - fine[np.argmax(speed)]) <= 1e-3
    assert abs(int(fast_speed) - speed.max()) <= 1
