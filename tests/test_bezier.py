"""course.curves.bezier: values, geometric properties, the two forms agreeing, bad input."""

import itertools
import math
import sys

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from course.curves import _flatten, bezier, flattening
from course.curves.bezier import (
    bernstein_basis,
    bezier_bernstein,
    binomial,
    de_casteljau,
    de_casteljau_levels,
    de_casteljau_recursive,
    derivative,
    elevate,
    sample_uniform,
    split,
)
from course.curves.bezier_accuracy import bezier_exact
from course.curves.flattening import flatten, uniform_parameters
from course.images import SEED_000_CUBIC

# Coordinates and parameters with few bits, so that products stay exact.
coordinate = st.integers(-64, 64).map(lambda k: k / 8)
parameter = st.integers(0, 32).map(lambda k: k / 32)


@st.composite
def polygons(draw, max_points=8, dimension=None):
    count = draw(st.integers(1, max_points))
    d = dimension or draw(st.integers(1, 3))
    values = draw(st.lists(coordinate, min_size=count * d, max_size=count * d))
    return np.array(values).reshape(count, d)


def size(points):
    return max(float(np.abs(points).max()), 1.0)


CUBIC = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])


# --- reference values in exact binary fractions -------------------------------


@pytest.mark.parametrize(
    ("t", "expected"),
    [(0.0, [0, 0]), (0.25, [29 / 32, 27 / 16]), (0.5, [2, 2.25]), (0.75, [3.09375, 1.6875])],
)
@pytest.mark.parametrize(
    "evaluate",
    [
        de_casteljau,
        de_casteljau_recursive,
        lambda p, t: bezier_bernstein(p, t, method="loop"),
    ],
)
def test_cubic_reference_values_are_exact(evaluate, t, expected):
    # (1 - t)^3 P0 + 3 t (1 - t)^2 P1 + 3 t^2 (1 - t) P2 + t^3 P3, by hand.
    np.testing.assert_array_equal(evaluate(CUBIC, t), expected)
    # Horner's rule divides by 1 - t (1/3 at t = 1/4 is not a binary fraction).
    np.testing.assert_allclose(bezier_bernstein(CUBIC, t), expected, rtol=4e-16)


def test_array_t_gives_one_row_per_parameter():
    curve = de_casteljau(CUBIC, [0.0, 0.5, 1.0])
    assert curve.shape == (3, 2)
    np.testing.assert_array_equal(curve, [[0, 0], [2, 2.25], [4, 0]])
    assert de_casteljau(CUBIC, np.array([])).shape == (0, 2)


def test_outside_zero_one_extrapolates_the_same_polynomial():
    # The cubic's y is 9 t (1 - t); at t = 2 that is -18, at t = -1 it is -18.
    for t in (2.0, -1.0):
        exact = [float(v) for v in bezier_exact(CUBIC, t)]
        assert de_casteljau(CUBIC, t)[1] == -18.0
        np.testing.assert_allclose(de_casteljau(CUBIC, t), exact, rtol=1e-15)
        np.testing.assert_allclose(bezier_bernstein(CUBIC, t), exact, rtol=1e-14)


def test_inputs_are_not_modified():
    points = CUBIC.copy()
    t = np.array([0.25, 0.5])
    for function in (de_casteljau, bezier_bernstein):
        function(points, t)
    split(points, 0.5)
    elevate(points)
    flatten(points, 0.1)
    np.testing.assert_array_equal(points, CUBIC)
    np.testing.assert_array_equal(t, [0.25, 0.5])


# --- geometric properties ------------------------------------------------------


@given(polygons())
def test_endpoint_interpolation_is_exact(points):
    for evaluate in (de_casteljau, bezier_bernstein, de_casteljau_recursive):
        np.testing.assert_array_equal(evaluate(points, 0.0), points[0])
        np.testing.assert_array_equal(evaluate(points, 1.0), points[-1])


@given(polygons(dimension=2), st.lists(parameter, min_size=1, max_size=10))
def test_curve_stays_in_the_convex_hull(points, t):
    # A point is in the hull iff in every direction it is no farther than the
    # farthest control point; 64 directions, plus a rounding allowance.
    angles = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    directions = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    curve = de_casteljau(points, t)
    reach = (points @ directions.T).max(axis=0)
    assert np.all(curve @ directions.T <= reach + 1e-12 * size(points))


@given(polygons(dimension=2), st.lists(parameter, min_size=1, max_size=5), st.data())
def test_affine_invariance(points, t, data):
    matrix = np.array(data.draw(st.lists(coordinate, min_size=4, max_size=4))).reshape(2, 2)
    offset = np.array(data.draw(st.lists(coordinate, min_size=2, max_size=2)))
    moved = de_casteljau(points @ matrix.T + offset, t)
    expected = de_casteljau(points, t) @ matrix.T + offset
    np.testing.assert_allclose(moved, expected, atol=1e-12 * size(points) * 64)


@given(polygons(), st.lists(parameter, min_size=1, max_size=5))
def test_reversal_symmetry(points, t):
    t = np.array(t)
    np.testing.assert_allclose(
        de_casteljau(points[::-1], 1 - t), de_casteljau(points, t), atol=1e-13 * size(points)
    )


@given(polygons(), parameter, st.lists(parameter, min_size=1, max_size=5))
def test_split_halves_reproduce_the_curve(points, at, u):
    u = np.array(u)
    left, right = split(points, at)
    tolerance = 1e-13 * size(points)
    np.testing.assert_allclose(de_casteljau(left, u), de_casteljau(points, at * u), atol=tolerance)
    np.testing.assert_allclose(
        de_casteljau(right, u), de_casteljau(points, at + (1 - at) * u), atol=tolerance
    )


@given(polygons(max_points=7), st.floats(0.05, 0.95))
def test_derivative_against_central_differences(points, t):
    h = 1e-5
    # Central differences err by h^2 |B'''| / 6 <= h^2 n^3 2^3 size / 6.
    n = len(points) - 1
    numeric = (de_casteljau(points, t + h) - de_casteljau(points, t - h)) / (2 * h)
    tolerance = (h**2 * n**3 * 8 / 6 + 1e-9) * size(points) * 4
    np.testing.assert_allclose(de_casteljau(derivative(points), t), numeric, atol=tolerance)


@given(polygons(), parameter)
def test_derivative_equals_the_last_de_casteljau_segment(points, t):
    levels = de_casteljau_levels(points, t)
    n = len(points) - 1
    if n == 0:
        np.testing.assert_array_equal(derivative(points), np.zeros_like(points))
        return
    tangent = n * (levels[-2][1] - levels[-2][0])
    np.testing.assert_allclose(
        de_casteljau(derivative(points), t), tangent, atol=1e-12 * size(points)
    )


@given(polygons(), st.lists(parameter, min_size=1, max_size=5))
def test_elevation_keeps_the_curve(points, t):
    raised = elevate(points)
    assert raised.shape == (len(points) + 1, points.shape[1])
    np.testing.assert_allclose(
        de_casteljau(raised, t), de_casteljau(points, t), atol=1e-13 * size(points)
    )


# --- the forms agree -------------------------------------------------------------


@pytest.mark.parametrize("degree", [0, 1, 2, 3, 5, 9, 13, 20])
def test_de_casteljau_bernstein_and_recursion_agree_to_1e_12(degree):
    rng = np.random.default_rng(degree)
    points = rng.uniform(-500, 500, (degree + 1, 2))
    t = np.concatenate([np.linspace(0, 1, 257), rng.uniform(0, 1, 100)])
    reference = de_casteljau(points, t)
    tolerance = 1e-12 * size(points)
    for method in ("horner", "loop"):
        np.testing.assert_allclose(
            bezier_bernstein(points, t, method=method), reference, atol=tolerance
        )
    np.testing.assert_allclose(bernstein_basis(degree, t) @ points, reference, atol=tolerance)
    for value in t[::16]:
        np.testing.assert_allclose(
            de_casteljau_recursive(points, value), de_casteljau(points, value), atol=tolerance
        )


def test_every_level_is_the_textbook_step():
    points = np.random.default_rng(1).uniform(0, 10, (6, 3))
    levels = de_casteljau_levels(points, 0.3)
    assert [len(level) for level in levels] == [6, 5, 4, 3, 2, 1]
    for upper, lower in itertools.pairwise(levels):
        np.testing.assert_array_equal(lower, 0.7 * upper[:-1] + 0.3 * upper[1:])
    np.testing.assert_array_equal(levels[-1][0], de_casteljau(points, 0.3))


@pytest.mark.parametrize("degree", [1, 4, 30])
def test_fast_kernels_agree_with_the_readable_forms_across_chunks(degree):
    # Long, unsorted t crosses many chunks and mixes the t < 1/2 and t >= 1/2 groups.
    rng = np.random.default_rng(degree)
    points = rng.uniform(-1, 1, (degree + 1, 3))
    t = rng.uniform(-0.5, 1.5, 20_000)
    levels_last = np.array([de_casteljau_levels(points, v)[-1][0] for v in t[:50]])
    np.testing.assert_array_equal(de_casteljau(points, t[:50]), levels_last)
    naive = bezier_bernstein(points, t, method="loop")
    scale = np.maximum(1.0, np.abs(t)) ** degree * 2**degree
    assert np.all(np.abs(bezier_bernstein(points, t) - naive) <= 1e-13 * scale[:, None])
    assert np.all(np.abs(de_casteljau(points, t) - naive) <= 1e-13 * scale[:, None])


@pytest.mark.parametrize(
    ("degree", "dimension", "count"), [(3, 2, 20_003), (9, 2, 10_001), (4, 3, 8_197), (1, 1, 3)]
)
def test_de_casteljau_is_the_textbook_step_bit_for_bit_across_chunks(degree, dimension, count):
    # Several chunks and a short last one: every value is still exactly
    # (1 - t) * P[i] + t * P[i + 1], level after level.
    rng = np.random.default_rng(degree)
    points = rng.uniform(-500, 500, (degree + 1, dimension))
    t = rng.uniform(-0.25, 1.25, count)
    level, s = points[:, None, :], (1 - t)[:, None]
    while len(level) > 1:
        level = level[:-1] * s + level[1:] * t[:, None]
    np.testing.assert_array_equal(de_casteljau(points, t), level[0])


@pytest.mark.parametrize("degree", [100, 300])
def test_high_degree_de_casteljau_matches_exact_arithmetic(degree):
    rng = np.random.default_rng(degree)
    points = rng.uniform(-1, 1, (degree + 1, 2))
    t = np.array([0.0, 0.1, 0.37, 0.5, 0.93, 1.0])
    exact = np.array([[float(v) for v in row] for row in bezier_exact(points, t)])
    np.testing.assert_allclose(de_casteljau(points, t), exact, atol=1e-13)
    np.testing.assert_allclose(bezier_bernstein(points, t), exact, atol=1e-13)
    np.testing.assert_array_equal(de_casteljau(points, [0.0, 1.0]), points[[0, -1]])


def test_bernstein_beyond_horner_range_uses_the_basis_and_stays_accurate():
    points = np.random.default_rng(5).uniform(-1, 1, (201, 2))
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(bezier_bernstein(points, t), de_casteljau(points, t), atol=1e-13)


def test_recursion_past_the_limit_fails_early_with_advice():
    points = np.zeros((sys.getrecursionlimit() + 10, 2))
    with pytest.raises(RecursionError, match=r"degree-\d+ curve.*de_casteljau \(iterative\)"):
        de_casteljau_recursive(points, 0.5)
    np.testing.assert_array_equal(de_casteljau(points, 0.5), [0.0, 0.0])
    assert de_casteljau_recursive(np.ones((300, 1)), 0.5)[0] == pytest.approx(1.0)


def test_bernstein_refuses_degrees_whose_binomials_overflow():
    with pytest.raises(ValueError, match=r"points.*de_casteljau"):
        bezier_bernstein(np.zeros((1031, 2)), 0.5)
    with pytest.raises(ValueError, match="n must be <= 1029"):
        bernstein_basis(1030, 0.5)


# --- the Bernstein basis and binomials -------------------------------------------


@pytest.mark.parametrize("n", [0, 1, 2, 7, 30, 60])
def test_binomial_matches_math_comb(n):
    assert [binomial(n, k) for k in range(-1, n + 2)] == [0] + [
        math.comb(n, k) for k in range(n + 1)
    ] + [0]


@given(st.integers(0, 40), st.lists(parameter, min_size=1, max_size=8))
def test_bernstein_basis_partition_of_unity_symmetry_and_sign(n, t):
    t = np.array(t)
    basis = bernstein_basis(n, t)
    assert basis.shape == (len(t), n + 1)
    assert np.all(basis >= 0)
    np.testing.assert_allclose(basis.sum(axis=1), 1.0, rtol=1e-13)
    np.testing.assert_allclose(bernstein_basis(n, 1 - t), basis[:, ::-1], atol=1e-15)
    np.testing.assert_array_equal(bernstein_basis(n, 0.0)[0], np.eye(n + 1)[0])


def test_bernstein_basis_of_degree_one_is_the_two_weights():
    np.testing.assert_array_equal(bernstein_basis(1, [0.25]), [[0.75, 0.25]])


# --- flattening and sampling ----------------------------------------------------


def distance_to_polyline(samples, polyline):
    starts, ends = polyline[:-1], polyline[1:]
    chord = ends - starts
    length2 = np.maximum((chord**2).sum(axis=1), 1e-300)
    offsets = samples[:, None, :] - starts[None]
    u = np.clip((offsets * chord).sum(axis=2) / length2, 0, 1)
    nearest = starts[None] + u[..., None] * chord[None]
    return np.sqrt(((samples[:, None, :] - nearest) ** 2).sum(axis=2)).min(axis=1)


@given(polygons(max_points=6, dimension=2), st.sampled_from([0.01, 0.1, 0.5]))
def test_flatten_keeps_every_curve_point_within_tolerance(points, tolerance):
    polyline, t = flatten(points, tolerance, return_parameters=True)
    np.testing.assert_allclose(polyline, de_casteljau(points, t), atol=1e-12 * size(points))
    assert (t[0] == 0 and t[-1] == 1 and np.all(np.diff(t) > 0)) or len(points) == 1
    if len(polyline) > 1:
        dense = de_casteljau(points, np.linspace(0, 1, 2001))
        assert distance_to_polyline(dense, polyline).max() <= tolerance * (1 + 1e-9)


def fewest_uniform_points(points, tolerance):
    """The smallest uniform step count whose polyline is within tolerance (to 5%)."""
    dense = de_casteljau(points, np.linspace(0, 1, 20001))
    count = 1
    while distance_to_polyline(dense, sample_uniform(points, 1 / count)).max() > tolerance:
        count += max(1, count // 20)
    return count + 1


def test_flatten_uses_far_fewer_points_than_the_handouts_step():
    points = SEED_000_CUBIC
    assert len(flatten(points, 0.25)) < len(sample_uniform(points, 0.001)) / 10
    # Against the best uniform step (unknowable in advance) it is comparable on
    # this evenly bent cubic, and ahead on a degree-9 curve with uneven speed.
    assert len(flatten(points, 0.25)) < 1.2 * fewest_uniform_points(points, 0.25)
    wiggly = np.random.default_rng(2).uniform(0, 700, (10, 2))
    assert len(flatten(wiggly, 0.25)) < 0.8 * fewest_uniform_points(wiggly, 0.25)


@given(polygons(max_points=5, dimension=2), st.sampled_from([0.5, 1.0, 3.0]))
def test_flatten_max_step_bounds_the_gap_between_neighbours(points, max_step):
    polyline = flatten(points * 8, 10.0, max_step=max_step)
    gaps = np.sqrt((np.diff(polyline, axis=0) ** 2).sum(axis=1))
    assert np.all(gaps <= max_step)


def test_flatten_degree_zero_and_straight_lines():
    np.testing.assert_array_equal(flatten([[1.0, 2.0]], 0.1), [[1.0, 2.0]])
    np.testing.assert_array_equal(flatten([[0, 0], [1, 1], [2, 2], [3, 3]], 0.01), [[0, 0], [3, 3]])


# Control points on a grid of exact binary fractions (k / 16), degrees 1 to 6.
grid_coordinate = st.integers(-256, 256).map(lambda k: k / 16)


@st.composite
def grid_curves(draw, dimension=2):
    count = draw(st.integers(2, 7))
    d = dimension or draw(st.integers(1, 3))
    values = draw(st.lists(grid_coordinate, min_size=count * d, max_size=count * d))
    return np.array(values).reshape(count, d)


def piece_errors(points, t, vertices, samples=65):
    """Largest distance from each piece of the curve (sampled in t) to its chord."""
    fraction = np.linspace(0, 1, samples)
    dense_t = (t[:-1, None] + np.diff(t)[:, None] * fraction).ravel()
    dense = de_casteljau(points, dense_t).reshape(len(t) - 1, samples, -1)
    start, chord = vertices[:-1, None], np.diff(vertices, axis=0)[:, None]
    length2 = np.maximum((chord**2).sum(axis=2), 1e-300)
    along = np.clip(((dense - start) * chord).sum(axis=2) / length2, 0, 1)
    return np.sqrt(((dense - start - along[..., None] * chord) ** 2).sum(axis=2)).max(axis=1)


@given(
    grid_curves(dimension=None),
    st.sampled_from([0.01, 0.1, 0.5]),
    st.sampled_from([None, 0.25, 1.0]),
)
def test_flatten_is_a_polyline_on_the_curve_within_tolerance(points, tolerance, max_step):
    original = points.copy()
    vertices, t = flatten(points, tolerance, max_step=max_step, return_parameters=True)
    np.testing.assert_array_equal(points, original)
    assert t[0] == 0 and t[-1] == 1 and np.all(np.diff(t) > 0)
    np.testing.assert_array_equal(vertices[[0, -1]], points[[0, -1]])
    np.testing.assert_allclose(vertices, de_casteljau(points, t), rtol=0, atol=1e-13 * size(points))
    assert piece_errors(points, t, vertices).max() <= tolerance * (1 + 1e-9)
    if max_step is not None:
        assert np.sqrt((np.diff(vertices, axis=0) ** 2).sum(axis=1)).max() <= max_step


def piece_control(points, a, b):
    """Control points of the curve over [a, b] (0 <= a < b <= 1), as a cubic."""
    _, right = split(points, a)
    piece, _ = split(right, (b - a) / (1 - a))
    while len(piece) < 4:
        piece = elevate(piece)
    return piece


@given(grid_curves(), st.lists(parameter, min_size=1, max_size=6, unique=True))
def test_segment_errors_are_exact_for_plane_curves_up_to_degree_3(points, cuts):
    # The check flatten relies on: each piece's distance to its chord, never
    # below the sampled distance, and equal to it when the piece's middle
    # control points project inside the chord (so the piece stays beside it).
    points = points[:4]
    t = np.array(sorted({0.0, 1.0, *cuts}))
    errors = _flatten.chord_errors(points, t)
    sampled = piece_errors(points, t, de_casteljau(points, t), samples=4001)
    assert np.all(errors >= sampled - 1e-12 * size(points))
    for error, exact, a, b in zip(errors, sampled, t[:-1], t[1:], strict=True):
        c0, c1, c2, c3 = piece_control(points, a, b)
        chord = c3 - c0
        along = [np.dot(c - c0, chord) / max(np.dot(chord, chord), 1e-300) for c in (c1, c2)]
        if np.dot(chord, chord) > 1e-9 and all(0.001 <= u <= 0.999 for u in along):
            assert error == pytest.approx(exact, rel=1e-6, abs=1e-9 * size(points))


def levien_count(points, tolerance):
    """Levien's segment count for a quadratic, from his post (kurbo's estimate_subdiv)."""

    def integral(x):
        return x / (0.33 + math.sqrt(math.sqrt(0.67**4 + 0.25 * x * x)))

    p0, p1, p2 = np.asarray(points, float)
    dd = (p1 - p0) - (p2 - p1)
    cross = (p2 - p0)[0] * dd[1] - (p2 - p0)[1] * dd[0]
    x0, x2 = np.dot(p1 - p0, dd) / cross, np.dot(p2 - p1, dd) / cross
    scale = abs(cross / (math.hypot(*dd) * (x2 - x0)))
    sqrt_tol = math.sqrt(tolerance)
    da = abs(integral(x2) - integral(x0))
    if math.copysign(1, x0) == math.copysign(1, x2):
        value = da * math.sqrt(scale)
    else:  # the parabola's vertex inside the curve
        value = sqrt_tol * da / integral(sqrt_tol / math.sqrt(scale))
    return max(1, math.ceil(0.5 * value / sqrt_tol))


def fewest_uniform_segments(points, tolerance):
    """The smallest n whose polyline through B(k / n) is within tolerance (n from 1 up)."""
    count = 1
    while True:
        t = np.linspace(0, 1, count + 1)
        if piece_errors(points, t, de_casteljau(points, t), samples=257).max() <= tolerance:
            return count
        count += 1


@pytest.mark.parametrize(
    ("points", "tolerance", "expected"),
    [
        ([[0, 0], [100, 0], [100, 100]], 0.25, 12),
        ([[0, 0], [30, 80], [100, 0]], 0.25, 12),
        ([[0, 0], [64, 8], [16, 48]], 0.1, 15),
        ([[0, 0], [200, 10], [0, 20]], 0.1, 13),  # a hairpin: the vertex inside
        ([[37.875, -23.03125], [42.0, -19.53125], [46.96875, -6.4375]], 0.1, 4),  # a glyph's
    ],
)
def test_flatten_counts_quadratics_as_levien_does(points, tolerance, expected):
    polyline = flatten(points, tolerance)
    assert len(polyline) - 1 == levien_count(points, tolerance) == expected
    assert expected <= fewest_uniform_segments(np.array(points, float), tolerance)


@pytest.mark.parametrize(
    ("points", "tolerance", "levien", "fewest"),
    [
        # A glyph curve of DejaVu Sans: Levien's estimate, 1.03 rounded up,
        # asks for two segments; the chord alone is 0.94 of the tolerance away.
        ([[90.8125, 70.8125], [88.375, 67.96875], [75.28125, 54.4375]], 0.1, 2, 1),
        # A hairpin: with three segments one straddles the tip, two meet there.
        ([[0, 0], [20, 1], [0, 2]], 0.25, 4, 2),
        ([[0, 0], [50, 100], [100, 0]], 0.25, 13, 12),
    ],
)
def test_flatten_takes_fewer_than_levien_when_his_spacing_passes(points, tolerance, levien, fewest):
    points = np.array(points, float)
    assert levien_count(points, tolerance) == levien
    vertices, t = flatten(points, tolerance, return_parameters=True)
    assert len(vertices) - 1 == fewest <= fewest_uniform_segments(points, tolerance)
    assert 0.5 < piece_errors(points, t, vertices).max() / tolerance <= 1


def test_flatten_splits_kurbos_cubic_segments_that_miss_the_tolerance():
    # Near the seed cubic's inflection the placement through quadratics falls
    # short (up to 2x the tolerance); those segments are split.
    points = np.asarray(SEED_000_CUBIC, float)
    count, place = _flatten.cubic_plan(points, 0.01)
    assert _flatten.chord_errors(points, place(count)).max() > 1.5 * 0.01
    vertices, t = flatten(points, 0.01, return_parameters=True)
    assert len(vertices) - 1 > count
    assert piece_errors(points, t, vertices, samples=257).max() <= 0.01


def loop_parameters(step, dtype):
    """The C++ loop ``for (t = 0; t <= 1; t += step)`` with a float or double t."""
    t, step, values = dtype(0), dtype(step), []
    while t <= 1:
        values.append(float(t))
        t = dtype(t + step)
    return values


@pytest.mark.parametrize("step", [0.001, 0.01, 0.1, 0.002, 0.05])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_uniform_parameters_reproduce_the_cpp_loop(step, dtype):
    name = "float32" if dtype is np.float32 else "float64"
    assert uniform_parameters(step, accumulate=name).tolist() == loop_parameters(step, dtype)


def test_the_cpp_loop_with_step_0001_stops_short_of_one():
    for name in ("float32", "float64"):
        assert uniform_parameters(0.001, accumulate=name)[-1] < 1
    exact = uniform_parameters(0.001)
    assert len(exact) == 1001 and exact[-1] == 1.0
    assert len(uniform_parameters(0.001, accumulate="float64")) == 1000
    np.testing.assert_array_equal(uniform_parameters(2.0), [0.0])


def test_sample_uniform_uses_those_parameters():
    samples = sample_uniform(CUBIC, 0.25)
    np.testing.assert_array_equal(samples, de_casteljau(CUBIC, [0, 0.25, 0.5, 0.75, 1]))


# --- bad input ------------------------------------------------------------------

CURVE_FUNCTIONS = [
    de_casteljau,
    de_casteljau_recursive,
    bezier_bernstein,
    de_casteljau_levels,
    split,
]


@pytest.mark.parametrize("function", CURVE_FUNCTIONS)
@pytest.mark.parametrize(
    ("points", "error", "words"),
    [
        ([], ValueError, "points"),
        (np.zeros((0, 2)), ValueError, "at least one point"),
        ([1.0, 2.0, 3.0, 4.0], ValueError, "second axis"),
        (np.zeros((2, 2, 2)), ValueError, r"shape \(N, d\)"),
        ([[0.0, np.nan], [1.0, 1.0]], ValueError, "points must be finite"),
        ([[0.0, np.inf], [1.0, 1.0]], ValueError, "points must be finite"),
        ([["a", "b"], ["c", "d"]], TypeError, "points must hold real numbers"),
        ([[0, 0], [1]], ValueError, "points must be a rectangular"),
    ],
)
def test_bad_points_are_rejected_by_name(function, points, error, words):
    with pytest.raises(error, match=words):
        function(points, 0.5)


@pytest.mark.parametrize("function", CURVE_FUNCTIONS)
@pytest.mark.parametrize(
    ("t", "error", "words"),
    [
        (np.nan, ValueError, "t must be finite"),
        (np.inf, ValueError, "t must be finite"),
        ("half", TypeError, "t must hold real numbers"),
        (None, TypeError, "t must hold real numbers"),
    ],
)
def test_bad_parameters_are_rejected_by_name(function, t, error, words):
    with pytest.raises(error, match=words):
        function(CUBIC, t)


def test_array_t_where_one_number_is_needed():
    for function in (de_casteljau_recursive, de_casteljau_levels):
        with pytest.raises(ValueError, match="t must be a single number"):
            function(CUBIC, [0.1, 0.2])
    with pytest.raises(ValueError, match="t must be a scalar or a 1-D array"):
        de_casteljau(CUBIC, [[0.1]])


def test_one_point_is_a_degree_zero_curve():
    point = [[3.0, -1.0]]
    for evaluate in (de_casteljau, de_casteljau_recursive, bezier_bernstein):
        np.testing.assert_array_equal(evaluate(point, 0.7), [3.0, -1.0])
    np.testing.assert_array_equal(de_casteljau(point, [0.0, 2.0]), [[3, -1], [3, -1]])
    assert derivative(point).tolist() == [[0.0, 0.0]]
    np.testing.assert_array_equal(elevate(point), [[3, -1], [3, -1]])


@pytest.mark.parametrize(
    ("call", "error", "words"),
    [
        (lambda: binomial(2.0, 1), TypeError, "n must be an integer"),
        (lambda: binomial(-1, 0), ValueError, "n must be >= 0"),
        (lambda: binomial(3, True), TypeError, "k must be an integer"),
        (lambda: bernstein_basis(3, [np.nan]), ValueError, "t must be finite"),
        (lambda: bezier_bernstein(CUBIC, 0.5, method="fast"), ValueError, "method"),
        (lambda: flatten(CUBIC, 0), ValueError, "tolerance must be > 0"),
        (lambda: flatten(CUBIC, np.nan), ValueError, "tolerance must be finite"),
        (lambda: flatten(CUBIC, 0.1, max_step=-1), ValueError, "max_step must be > 0"),
        (lambda: uniform_parameters(0), ValueError, "step must be > 0"),
        (lambda: uniform_parameters("0.1"), TypeError, "step must be a real number"),
        (lambda: uniform_parameters(0.1, "float16"), ValueError, "accumulate"),
        (lambda: derivative([]), ValueError, "points"),
        (lambda: elevate([1, 2]), ValueError, "second axis"),
    ],
)
def test_other_bad_input_is_rejected_by_name(call, error, words):
    with pytest.raises(error, match=words):
        call()


def test_public_names_are_exported():
    assert set(bezier.__all__) >= {"de_casteljau", "bezier_bernstein", "sample_uniform"}
    assert set(flattening.__all__) >= {"flatten", "uniform_parameters"}


@pytest.mark.parametrize("step", [1e-9, 1e-15])
def test_a_step_too_fine_is_refused_before_any_sample_is_made(step):
    from course import limits
    from course.curves.bezier import sample_uniform
    from course.curves.flattening import uniform_parameters

    with pytest.raises(ValueError, match=f"at most {limits.MAX_STEP_SAMPLES} samples"):
        uniform_parameters(step)
    with pytest.raises(ValueError, match="step must give"):
        sample_uniform([[0, 0], [1, 1]], step, accumulate="float32")


def test_the_finest_step_allowed_gives_at_most_the_bound():
    from course import limits
    from course.curves.flattening import uniform_parameters

    step = 1 / (limits.MAX_STEP_SAMPLES - 2)
    assert len(uniform_parameters(step)) <= limits.MAX_STEP_SAMPLES
