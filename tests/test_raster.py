"""course.raster lines: Bresenham in two forms, the report's 4-connected pitfall, Wu."""

import itertools
import re

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from course.raster import distance_from_line, line, line_4connected, wu_line


def bresenham_violations(p0, p1, pixels):
    """Every way ``pixels`` fails to be the Bresenham line from p0 to p1, in integers."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = x1 - x0, y1 - y0
    n = max(abs(dx), abs(dy))
    problems = []
    if len(pixels) != n + 1:
        problems.append(f"{len(pixels)} pixels, expected {n + 1}")
        return problems
    if tuple(pixels[0]) != (x0, y0) or tuple(pixels[-1]) != (x1, y1):
        problems.append("endpoints")
    x_major = abs(dx) >= abs(dy)
    for i, (x, y) in enumerate(pixels):
        # Along the major axis pixel i is i steps from p0 toward p1 (order).
        major, start, delta = (x, x0, dx) if x_major else (y, y0, dy)
        if major != start + i * (1 if delta >= 0 else -1):
            problems.append(f"pixel {i} out of order")
        if i and max(abs(x - pixels[i - 1][0]), abs(y - pixels[i - 1][1])) != 1:
            problems.append(f"pixel {i} not 8-connected to pixel {i - 1}")
        if n == 0:
            continue
        # Distance along the minor axis to the ideal line, times |major delta|:
        # |offset| <= n / 2 means within half a pixel; = n / 2 is a tie,
        # which Bresenham gives to the pixel toward p0.
        if x_major:
            offset = (y - y0) * dx - (x - x0) * dy
            toward_start = -offset * dy * dx >= 0
        else:
            offset = (x - x0) * dy - (y - y0) * dx
            toward_start = -offset * dx * dy >= 0
        if 2 * abs(offset) > n:
            problems.append(f"pixel {i} more than half a pixel from the line")
        elif 2 * abs(offset) == n and not toward_start:
            problems.append(f"pixel {i} breaks the tie away from p0")
    return problems


def test_both_forms_equal_and_correct_for_every_pair_in_a_16x16_box():
    box = list(itertools.product(range(16), range(16)))
    for p0, p1 in itertools.product(box, box):
        loop = line(p0, p1, method="loop").tolist()
        assert line(p0, p1).tolist() == loop, (p0, p1)
        assert bresenham_violations(p0, p1, loop) == [], (p0, p1)


far = st.integers(-(10**6), 10**6)
delta = st.integers(-3000, 3000)


@given(far, far, delta, delta)
def test_lines_far_from_the_origin_keep_every_property(x0, y0, dx, dy):
    pixels = line((x0, y0), (x0 + dx, y0 + dy))
    assert pixels.dtype == np.int64
    assert bresenham_violations((x0, y0), (x0 + dx, y0 + dy), pixels.tolist()) == []


def test_a_very_long_line_stays_within_half_a_pixel():
    (x0, y0), (x1, y1) = (-(2**20), 5), (2**20, 2**19 + 1)
    pixels = line((x0, y0), (x1, y1))
    assert len(pixels) == 2**21 + 1
    assert tuple(pixels[0]) == (x0, y0) and tuple(pixels[-1]) == (x1, y1)
    np.testing.assert_array_equal(pixels[:, 0], np.arange(x0, x1 + 1))
    # Minor-axis offset from the ideal line times dx, exact in int64 (< 2**41).
    offset = (pixels[:, 1] - y0) * (x1 - x0) - (pixels[:, 0] - x0) * (y1 - y0)
    assert 2 * np.abs(offset).max() <= x1 - x0


@given(st.integers(-40, 40), st.integers(-40, 40), st.integers(-40, 40), st.integers(-40, 40))
def test_loop_and_vectorized_agree_beyond_the_box(x0, y0, x1, y1):
    np.testing.assert_array_equal(line((x0, y0), (x1, y1)), line((x0, y0), (x1, y1), method="loop"))


def test_whole_floats_and_numpy_ints_are_pixels_too():
    expected = line((0, 0), (5, 3))
    np.testing.assert_array_equal(line((0.0, 0.0), np.array([5, 3])), expected)
    np.testing.assert_array_equal(line(np.int32([0, 0]), [np.int64(5), 3]), expected)


def test_shape_clips_without_wrapping():
    full = line((-5, -3), (20, 6))
    clipped = line((-5, -3), (20, 6), shape=(4, 8))
    assert (clipped >= 0).all() and (clipped[:, 0] < 8).all() and (clipped[:, 1] < 4).all()
    keep = (full[:, 0] >= 0) & (full[:, 0] < 8) & (full[:, 1] >= 0) & (full[:, 1] < 4)
    np.testing.assert_array_equal(clipped, full[keep])


def test_a_single_pixel_line():
    np.testing.assert_array_equal(line((3, 4), (3, 4)), [[3, 4]])
    np.testing.assert_array_equal(line((3, 4), (3, 4), method="loop"), [[3, 4]])


@pytest.mark.parametrize(
    ("p0", "p1", "error", "words"),
    [
        ((0.5, 0), (3, 3), ValueError, "p0 must be an integer pixel"),
        ((0, 0), (np.nan, 3), ValueError, "p1 must be finite"),
        ((0, 0), (np.inf, 3), ValueError, "p1 must be finite"),
        ((0, 0, 0), (1, 1), ValueError, "p0 must be one point of shape (2,)"),
        ((0, 0), "ab", TypeError, "p1 must hold real numbers"),
        ((0, 0), (2**30, 0), ValueError, "p1 coordinates must lie within"),
    ],
)
def test_bad_endpoints_are_named(p0, p1, error, words):
    with pytest.raises(error, match=words.replace("(", r"\(").replace(")", r"\)")):
        line(p0, p1)


def test_bad_method_and_shape_are_named():
    with pytest.raises(ValueError, match="method must be one of"):
        line((0, 0), (1, 1), method="fast")
    with pytest.raises(ValueError, match=r"shape\[0\] \(height\) must be >= 1"):
        line((0, 0), (1, 1), shape=(0, 4))


# --- the report's 4-connected line -----------------------------------------


@given(st.integers(-20, 20), st.integers(-20, 20), st.integers(-20, 20), st.integers(-20, 20))
def test_report_line_is_a_4_connected_staircase(x0, y0, x1, y1):
    pixels = line_4connected((x0, y0), (x1, y1))
    assert len(pixels) == abs(x1 - x0) + abs(y1 - y0) + 1
    assert tuple(pixels[0]) == (x0, y0) and tuple(pixels[-1]) == (x1, y1)
    # Every step moves exactly one pixel in x or in y, never both.
    assert (np.abs(np.diff(pixels, axis=0)).sum(axis=1) == 1).all()
    if x0 != x1 and y0 != y1:
        assert len(pixels) > len(line((x0, y0), (x1, y1)))


def test_report_line_doubles_a_diagonal():
    assert len(line_4connected((0, 0), (10, 10))) == 2 * len(line((0, 0), (10, 10))) - 1
    np.testing.assert_array_equal(line_4connected((0, 0), (6, 0)), line((0, 0), (6, 0)))


# --- Wu's anti-aliased line --------------------------------------------------


points = st.integers(-16 * 20, 16 * 20).map(lambda v: v / 16)


@given(points, points, points, points)
def test_wu_splits_one_unit_of_ink_per_column_around_the_ideal_line(x0, y0, x1, y1):
    pixels, weights = wu_line((x0, y0), (x1, y1))
    steep = abs(y1 - y0) > abs(x1 - x0)
    if steep:  # look at it with x as the major axis
        pixels, (x0, y0, x1, y1) = pixels[:, ::-1], (y0, x0, y1, x1)
    if x0 == x1:
        assert len(pixels) == 0
        return
    assert ((weights > 0) & (weights <= 1)).all()
    # Total ink is the length along the major axis.
    np.testing.assert_allclose(weights.sum(), abs(x1 - x0), rtol=1e-12)
    low, high = min(x0, x1), max(x0, x1)
    columns = np.unique(pixels[:, 0])
    for column in columns[(columns >= low) & (columns + 1 <= high)]:
        here = pixels[:, 0] == column
        np.testing.assert_allclose(weights[here].sum(), 1.0, rtol=1e-12)
        # The ink's centre of mass sits on the ideal line at the column centre.
        ideal = y0 + (y1 - y0) / (x1 - x0) * (column + 0.5 - x0)
        centre = (weights[here] * (pixels[here, 1] + 0.5)).sum()
        assert abs(centre - ideal) < 1e-9
    # Ordered from p0 to p1 along the major axis.
    direction = 1 if x1 > x0 else -1
    assert (np.diff(pixels[:, 0]) * direction >= 0).all()


@given(st.integers(-30, 30), st.integers(-30, 30), st.integers(-30, 30), st.integers(-30, 30))
def test_wu_between_pixel_centres_darkest_where_bresenham_draws(x0, y0, x1, y1):
    pixels, weights = wu_line((x0 + 0.5, y0 + 0.5), (x1 + 0.5, y1 + 0.5))
    major = 0 if abs(x1 - x0) >= abs(y1 - y0) else 1
    bresenham = {int(p[major]): tuple(p) for p in line((x0, y0), (x1, y1))}
    for position in np.unique(pixels[:, major]):
        here = pixels[:, major] == position
        # A tie (the line midway between two centres) has two equally dark
        # pixels, up to rounding.
        best = np.flatnonzero(weights[here] > weights[here].max() - 1e-9)
        if len(best) == 1:
            assert tuple(pixels[here][best[0]]) == bresenham[int(position)]


def test_wu_shape_clips_and_bad_input_is_named():
    pixels, weights = wu_line((-3.2, 1.7), (9.5, 2.4), shape=(4, 5))
    assert len(pixels) == len(weights)
    assert (pixels >= 0).all() and (pixels[:, 0] < 5).all() and (pixels[:, 1] < 4).all()
    with pytest.raises(ValueError, match="p1 must be finite"):
        wu_line((0, 0), (1, np.nan))


small = st.integers(-30, 30)


@given(small, small, small, small)
def test_bresenham_stays_within_half_a_pixel_of_the_line_by_projection(x0, y0, x1, y1):
    pixels = line((x0, y0), (x1, y1))
    distances = distance_from_line(pixels, (x0, y0), (x1, y1))
    # Independently: the centre minus its projection on the line through the end centres.
    start, direction = np.array([x0, y0]) + 0.5, np.array([x1 - x0, y1 - y0], dtype=float)
    relative = pixels + 0.5 - start
    if direction.any():
        along = relative @ direction / (direction @ direction)
        relative = relative - along[:, None] * direction
    np.testing.assert_allclose(distances, np.hypot(*relative.T), atol=1e-12)
    assert distances.max() <= 0.5 + 1e-12
    np.testing.assert_allclose(distance_from_line(pixels, (x1, y1), (x0, y0)), distances)


def test_the_reports_loop_strays_past_a_pixel_where_bresenham_keeps_half():
    report = distance_from_line(line_4connected((3, 6), (27, 17)), (3, 6), (27, 17))
    bresenham = distance_from_line(line((3, 6), (27, 17)), (3, 6), (27, 17))
    # Pixel (10, 8): the line is at y = 6 + 7 * 11 / 24 there, 1.21 rows below it.
    assert report.max() == pytest.approx((6 + 7 * 11 / 24 - 8) * 24 / np.hypot(24, 11))
    assert bresenham.max() < 0.5 < 1 < report.max()


@pytest.mark.parametrize(
    ("pixels", "p0", "said"),
    [
        ([[0, 0], [1, np.nan]], (0, 0), "pixels"),
        ([[0, 0, 0]], (0, 0), "shape (K, 2)"),
        ([[0, 0]], (0.5, 0), "p0 must be an integer pixel"),
    ],
)
def test_distance_from_line_names_a_bad_argument(pixels, p0, said):
    with pytest.raises(ValueError, match=re.escape(said)):
        distance_from_line(pixels, p0, (4, 2))
