"""course.curves.bezier_handouts: the handouts' own code, pitfalls measured; the GAMES101 check."""

import itertools
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from course.curves.bezier import bezier_bernstein, de_casteljau, sample_uniform
from course.curves.bezier_handouts import (
    comb_recursive,
    comb_recursive_calls,
    de_casteljau_reversed,
    pascal_row_int32,
    step_report,
    trace_iterative,
    trace_recursive,
)
from course.curves.flattening import uniform_parameters
from course.curves.handout_loops import HANDOUT_LOOPS, loop_pixels, yellow_check
from course.images import SEED_000_CUBIC
from course.raster import nearest_pixels
from course.raster.canvas import blank, paint, yellow_fraction

SEED_000 = SEED_000_CUBIC


def test_recursive_comb_values_and_call_counts():
    for m in range(12):
        for n in range(m + 2):
            value, calls = comb_recursive(m, n)
            assert value == math.comb(m, n)
            assert calls == comb_recursive_calls(m, n)
    assert comb_recursive(20, 10) == (184756, 184755)
    # Exponential: each step of 5 in n multiplies the calls by about 30.
    assert comb_recursive_calls(25, 12) > 25 * comb_recursive_calls(20, 10)


def test_int32_pascal_row_wraps_exactly_where_cpp_int_would():
    for n in range(34):
        assert pascal_row_int32(n).tolist() == [math.comb(n, k) for k in range(n + 1)]
    row = pascal_row_int32(34)
    assert row[17] == math.comb(34, 17) - 2**32


def test_reversed_convention_runs_the_curve_backwards():
    t = np.linspace(0, 1, 9)
    np.testing.assert_allclose(de_casteljau_reversed(SEED_000, t), de_casteljau(SEED_000, 1 - t))
    np.testing.assert_array_equal(de_casteljau_reversed(SEED_000, 0.0), SEED_000[-1])
    assert de_casteljau_reversed(SEED_000, [0.5]).shape == (1, 2)


@pytest.mark.parametrize("count", [1, 2, 4, 10, 30])
def test_recursion_holds_quadratically_many_points_iteration_linearly(count):
    points = np.random.default_rng(count).uniform(0, 1, (count, 2))
    recursive, iterative = trace_recursive(points, 0.3), trace_iterative(points, 0.3)
    np.testing.assert_allclose(recursive.point, de_casteljau(points, 0.3))
    np.testing.assert_allclose(iterative.point, de_casteljau(points, 0.3))
    assert recursive.interpolations == iterative.interpolations == count * (count - 1) // 2
    assert recursive.calls == count
    assert recursive.peak_points_held == count * (count + 1) // 2
    assert iterative.peak_points_held == max(2 * count - 1, 1)


# --- the GAMES101 check: red Bernstein + green de Casteljau = yellow ------------------


def games101_picture(green_points, accumulate="exact"):
    image = blank((700, 700), (0, 0, 0))
    t = uniform_parameters(0.001, accumulate)
    red = nearest_pixels(bezier_bernstein(SEED_000, t, method="loop"), shape=(700, 700))
    paint(image, red, (1, 0, 0))
    paint(image, nearest_pixels(green_points(t), shape=(700, 700)), (0, 1, 0))
    return image


def test_yellow_check_passes_when_both_curves_are_right():
    image = games101_picture(lambda t: de_casteljau(SEED_000, t))
    assert yellow_fraction(image) == 1.0


def test_yellow_check_fails_for_a_wrong_formula():
    # Forgetting the binomial coefficients: a different curve.
    def no_binomials(t):
        t = t[:, None]
        return sum((1 - t) ** (3 - i) * t**i * SEED_000[i] for i in range(4)) / (
            sum((1 - t) ** (3 - i) * t**i for i in range(4))
        )

    assert yellow_fraction(games101_picture(no_binomials)) < 0.2


def test_yellow_check_cannot_see_a_reversed_curve_but_the_float_loop_shows_its_ends():
    backwards = games101_picture(lambda t: de_casteljau_reversed(SEED_000, t))
    assert yellow_fraction(backwards) == 1.0
    # With the C++ float loop, the reversed curve misses the start instead of the end.
    backwards_float = games101_picture(lambda t: de_casteljau_reversed(SEED_000, t), "float64")
    assert yellow_fraction(backwards_float) < 1.0
    pixels = nearest_pixels(sample_uniform(SEED_000, 0.001, "float64"))
    assert [690, 690] not in pixels.tolist()
    assert [690, 690] in nearest_pixels(sample_uniform(SEED_000, 0.001)).tolist()


def test_nearest_pixels_conventions_on_the_curve_end():
    end = de_casteljau(SEED_000, [1.0])
    assert nearest_pixels(end).tolist() == [[690, 690]]
    assert nearest_pixels(end, shape=(690, 690)).tolist() == []
    assert nearest_pixels([[689.5, 0.5]], rounding="round").tolist() == [[690, 0]]


def test_step_report_counts_gaps_and_overdraw_by_their_definition():
    report = step_report(SEED_000, 0.001, "float32")
    t = uniform_parameters(0.001, "float32")
    pixels = [tuple(int(v) for v in np.floor(p)) for p in de_casteljau(SEED_000, t)]
    gaps = sum(max(abs(a[0] - b[0]), abs(a[1] - b[1])) > 1 for a, b in itertools.pairwise(pixels))
    assert (report["samples"], report["pixels"], report["gaps"]) == (1001, len(set(pixels)), gaps)
    assert report["gaps"] > 100 and report["last_t"] < 1
    assert report["overdraw"] == 1001 / len(set(pixels))
    fine = step_report(SEED_000, 0.0001)
    assert fine["gaps"] == 0 and fine["overdraw"] > 5


def test_the_yellow_check_agrees_with_painting_both_curves_by_hand():
    for loop in HANDOUT_LOOPS.values():
        image = np.zeros((700, 700, 3))
        red_t = uniform_parameters(0.001, "float64")
        red = nearest_pixels(bezier_bernstein(SEED_000_CUBIC, red_t), rounding="trunc")
        paint(image, red, (1.0, 0.0, 0.0))
        green_t = uniform_parameters(0.001, loop.accumulate)
        curve = de_casteljau(SEED_000_CUBIC, 1 - green_t if loop.reversed else green_t)
        paint(image, nearest_pixels(curve, rounding=loop.rounding), (0.0, 1.0, 0.0))
        check = yellow_check(SEED_000_CUBIC, loop)
        assert check.fraction == pytest.approx(yellow_fraction(image), abs=0.002)
        assert len(loop_pixels(SEED_000_CUBIC, loop)) == len(green_t)
    # The float loops stop short of t = 1; the double one stops a whole step short.
    assert yellow_check(SEED_000_CUBIC, HANDOUT_LOOPS["003"]).fraction == 1.0
    assert yellow_check(SEED_000_CUBIC, HANDOUT_LOOPS["000"]).fraction < 0.5


def test_trace_recursive_refuses_a_curve_deeper_than_the_recursion_allows():
    import sys

    from course.curves.bezier_handouts import trace_recursive

    points = np.zeros((1501, 2))
    with pytest.raises(ValueError, match="points must hold at most"):
        trace_recursive(points, 0.5)
    depth = sys.getrecursionlimit() // 2
    assert trace_recursive(np.zeros((depth, 2)), 0.5).calls == depth


@given(st.lists(st.tuples(st.integers(-40, 40), st.integers(-40, 40)), min_size=2, max_size=6))
def test_step_report_counts_the_distinct_pixels_of_its_samples(control):
    from course.curves.bezier_handouts import step_report

    report = step_report(np.array(control, dtype=float), 0.01)
    assert report["pixels"] == len({tuple(p) for p in report["pixel_list"].tolist()})


def test_trace_iterative_bounds_the_handout_loop():
    from course import limits
    from course.curves.bezier_handouts import trace_iterative

    with pytest.raises(ValueError, match=f"at most {limits.MAX_HANDOUT_POINTS} control points"):
        trace_iterative(np.zeros((limits.MAX_HANDOUT_POINTS + 1, 2)), 0.5)
