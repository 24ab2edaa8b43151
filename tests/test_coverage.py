"""course.antialias.coverage: the exact reference, Agg's rendering, and the geometry under both."""

import itertools
import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from matplotlib.path import Path

from course.antialias.coverage import (
    agg_draw,
    agg_render,
    curve_polyline,
    pixels_near,
    reference,
    segment_distance,
    slab_coverage,
    subdivide,
)
from course.curves.bezier import de_casteljau
from course.images import SEED_000_CUBIC

SEED_CURVE = SEED_000_CUBIC / 5


def band_by_brute_force(across, normal, width, k=400):
    """Fraction of a k x k grid of points of the pixel inside the band."""
    grid = (np.arange(k) + 0.5) / k - 0.5
    u, v = np.meshgrid(grid, grid)
    return np.mean(np.abs(across + normal[0] * u + normal[1] * v) <= width / 2)


@given(
    angle=st.floats(0, 2 * math.pi),
    across=st.floats(-1.8, 1.8),
    width=st.sampled_from([0.5, 1.0, 1.7, 3.0]),
)
def test_slab_coverage_is_the_area_of_the_pixel_inside_the_band(angle, across, width):
    normal = np.array([math.cos(angle), math.sin(angle)])
    exact = float(slab_coverage([across], [normal], width)[0])
    # A 400 x 400 grid errs by at most about 2 / 400 for a band's two edges.
    assert exact == pytest.approx(band_by_brute_force(across, normal, width), abs=6e-3)


def test_slab_coverage_known_values():
    # Axis-aligned: the overlap of two intervals. 45 degrees through the
    # centre: the square minus two corner triangles of legs 1 - sqrt(2)/2.
    assert slab_coverage([0.3], [[1.0, 0.0]], 1.0)[0] == pytest.approx(0.7)
    assert slab_coverage([0.3], [[0.0, -1.0]], 2.0)[0] == pytest.approx(1.0)
    leg = 1 - math.sqrt(0.5)
    diagonal = [[math.sqrt(0.5), math.sqrt(0.5)]]
    assert slab_coverage([0.0], diagonal, 1.0)[0] == pytest.approx(1 - 2 * leg**2 / 2)


@pytest.mark.parametrize("angle", [0.0, 0.3, math.pi / 4, 1.2])
def test_reference_converges_to_the_exact_area_as_k_grows(angle):
    # A long straight stroke: away from its ends each pixel's exact coverage
    # is slab_coverage, so the supersampling error can be measured.
    direction = np.array([math.cos(angle), math.sin(angle)])
    start = np.array([20.3, 20.1]) - 14 * direction
    line = np.array([start, start + 28 * direction])
    normal = np.array([-direction[1], direction[0]])
    rows, columns = np.mgrid[14:27, 14:27]
    centres = np.stack([columns + 0.5, rows + 0.5], axis=-1)
    across = (centres - start) @ normal
    exact = slab_coverage(-across, np.broadcast_to(normal, centres.shape), 1.0)
    errors = []
    for k in (4, 8, 16, 32, 64):
        image = reference(line, (40, 40), 1.0, k=k)
        error = np.abs(image[14:27, 14:27] - exact)
        # Each band edge crossing a row of k samples misplaces at most one.
        assert error.max() <= 2 / k + 1e-9
        errors.append(np.sqrt(np.mean(error**2)))
    assert all(later <= earlier for earlier, later in itertools.pairwise(errors))
    assert errors[-1] <= errors[0] / 6


def sample_grid(shape, k):
    """The reference's k x k sample points of every pixel: x and y, (H, W, k * k)."""
    grid = (np.arange(k) + 0.5) / k
    ys, xs = np.mgrid[0 : shape[0], 0 : shape[1]]
    size = (*shape, k, k)
    samples_x = np.broadcast_to(xs[..., None, None] + grid, size).reshape(*shape, -1)
    samples_y = np.broadcast_to(ys[..., None, None] + grid[:, None], size).reshape(*shape, -1)
    return samples_x, samples_y


def polyline_distance(samples_x, samples_y, line):
    """Each sample's distance to the nearest segment of ``line``."""
    nearest = np.full(samples_x.shape, np.inf)
    for a, b in itertools.pairwise(line):
        distance, _, _ = segment_distance(samples_x, samples_y, a, b)
        nearest = np.minimum(nearest, distance)
    return nearest


def assert_reference_counts_the_samples_within_half_the_width(control, shape, width, k):
    """The reference against the samples within width / 2 of the flattened curve, by brute force."""
    curve = np.array(control, dtype=float)
    image = reference(curve, shape, width, k=k)
    nearest = polyline_distance(*sample_grid(shape, k), curve_polyline(curve, 1e-4))
    # A sample within rounding of the edge may fall either way.
    surely = np.mean(nearest <= width / 2 - 1e-9, axis=-1)
    maybe = np.mean(nearest <= width / 2 + 1e-9, axis=-1)
    assert np.all(surely - 1e-12 <= image) and np.all(image <= maybe + 1e-12)


def test_reference_holds_the_stroke_area():
    # Width x length plus the two half-disc caps.
    for width in (1.0, 3.0):
        image = reference(SEED_CURVE, (140, 140), width, k=32)
        line = curve_polyline(SEED_CURVE, 1e-4)
        length = np.hypot(*np.diff(line, axis=0).T).sum()
        assert image.sum() == pytest.approx(width * length + math.pi * width**2 / 4, rel=1e-3)


def test_reference_wide_stroke_agrees_with_sampling_every_pixel():
    # The wholly-inside shortcut and the "near the curve" search against
    # testing every sample of every pixel.
    curve = np.array([[2.0, 3.0], [14.0, 1.0], [9.0, 13.0]])
    width, k = 3.0, 8
    image = reference(curve, (16, 18), width, k=k)
    line = curve_polyline(curve, 1e-4)
    nearest = polyline_distance(*sample_grid((16, 18), k), line)
    np.testing.assert_allclose(image, np.mean(nearest <= width / 2, axis=-1), atol=1e-12)
    assert image.max() == 1.0


@settings(max_examples=40, deadline=None)
@given(
    control=st.lists(
        st.tuples(
            st.integers(0, 160).map(lambda n: n / 16), st.integers(0, 160).map(lambda n: n / 16)
        ),
        min_size=2,
        max_size=4,
    ),
    width=st.sampled_from([0.5, 1.0, 2.5]),
    k=st.sampled_from([3, 4]),
)
@example(control=[(3.0, 4.0), (3.0, 4.0)], width=1.0, k=4)  # a single point: a dot
def test_reference_is_the_fraction_of_samples_within_half_the_width(control, width, k):
    assert_reference_counts_the_samples_within_half_the_width(control, (11, 12), width, k)


@settings(max_examples=12, deadline=None)
@given(
    control=st.lists(
        st.tuples(st.floats(-2, 10, allow_nan=False), st.floats(-2, 10, allow_nan=False)),
        min_size=2,
        max_size=3,
    ),
    width=st.sampled_from([0.3, 1.0, 2.0]),
    k=st.sampled_from([63, 64, 65, 130]),
)
def test_reference_counts_the_samples_of_rows_longer_than_a_word(control, width, k):
    # Each row's samples are bits of 64-bit words: at 64 they fill one word, past it two or more.
    assert_reference_counts_the_samples_within_half_the_width(control, (6, 7), width, k)


@given(
    spans=st.lists(st.tuples(st.integers(0, 130), st.integers(0, 130)), min_size=1, max_size=20),
    k=st.integers(1, 130),
)
def test_a_row_s_samples_are_the_bits_of_its_columns(spans, k):
    from course.antialias._reference import _row_words

    first = np.array([min(a, b, k) for a, b in spans])
    stop = np.array([min(max(a, b), k) for a, b in spans])
    words = _row_words(first, stop, k)
    bits = np.unpackbits(words.astype("<u8").view(np.uint8), axis=-1, bitorder="little")
    expected = (np.arange(bits.shape[1]) >= first[:, None]) & (
        np.arange(bits.shape[1]) < stop[:, None]
    )
    assert words.shape == (len(spans), -(-k // 64))
    np.testing.assert_array_equal(bits.astype(bool), expected)


def agg_polyline(line, shape, width=1.0):
    """Agg stroking a fine polyline, matplotlib's simplification off."""
    path = Path(line)
    path.should_simplify = False
    return np.asarray(agg_draw(path, shape, width).buffer_rgba())[..., 3] / 255.0


def test_agg_is_aligned_with_the_reference_by_measurement():
    # A horizontal and a vertical stroke a quarter pixel off the centres:
    # Agg's rows and columns match the reference's to 8-bit precision, so
    # no half-pixel shift and one point of width is one pixel at 72 dpi.
    for line in ([[2.0, 5.25], [14.0, 5.25]], [[5.75, 2.0], [5.75, 14.0]]):
        agg = agg_render(line, (12, 16))
        exact = reference(line, (12, 16), 1.0, k=16)
        assert np.abs(agg - exact)[3:9, 3:9].max() <= 2 / 255
    # The seed curve drawn by Agg from a fine polyline matches the reference
    # everywhere but the round caps, which Agg approximates by a polygon.
    line = curve_polyline(SEED_CURVE, 1e-3)
    agg = agg_polyline(line, (140, 140))
    exact = reference(SEED_CURVE, (140, 140), 1.0, k=64)
    away_from_caps = np.ones((140, 140), bool)
    away_from_caps[:4, :4] = away_from_caps[-4:, -4:] = False
    error = np.abs(agg - exact)[away_from_caps]
    assert error.max() <= 0.025
    assert np.sqrt(np.mean(error**2)) <= 1e-3


def test_agg_flattens_the_cubic_itself_more_coarsely():
    # The production path: CURVE4 codes, flattened by Agg. Its error is
    # larger than the polyline's: Agg's own subdivision, not the alignment.
    curve_error = np.abs(
        agg_render(SEED_CURVE * 5, (700, 700)) - reference(SEED_CURVE * 5, (700, 700), k=16)
    )
    assert 0.05 <= curve_error.max() <= 0.25


def test_agg_render_draws_lines_and_quadratics_and_refuses_higher_degrees():
    assert agg_render([[1.0, 1.5], [6.0, 1.5]], (3, 8))[1, 2:6].tolist() == [1.0] * 4
    assert agg_render([[1.0, 1.0], [4.0, 6.0], [7.0, 1.0]], (8, 8)).sum() > 0
    with pytest.raises(ValueError, match="degree 1 to 3"):
        agg_render(np.zeros((5, 2)), (8, 8))


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"width": 0.0}, ValueError, "width must be > 0"),
        ({"k": 0}, ValueError, "k must be >= 1"),
        ({"k": 2.5}, TypeError, "k must be an integer"),
        ({"shape": (4, 4, 3)}, ValueError, "shape must be a pair"),
        ({"points": [[0.0, np.nan]]}, ValueError, "points must be finite"),
    ],
)
def test_reference_rejects_bad_input_by_name(kwargs, error, words):
    with pytest.raises(error, match=words):
        reference(**({"points": [[0, 0], [3, 3]], "shape": (4, 4)} | kwargs))


polylines = st.lists(
    st.tuples(
        st.integers(-40, 360).map(lambda n: n / 16), st.integers(-40, 360).map(lambda n: n / 16)
    ),
    min_size=2,
    max_size=6,
).map(lambda rows: np.array(rows, dtype=float))


@given(line=polylines, reach=st.sampled_from([0.5, 1.0, 1.2071, 2.5]))
def test_pixels_near_finds_exactly_the_pairs_within_reach(line, reach):
    shape = (20, 22)
    near = pixels_near(line, shape, reach)
    pieces = near.polyline
    np.testing.assert_allclose(subdivide(line, 10.0)[[0, -1]], line[[0, -1]])
    found = set(zip(near.x.tolist(), near.y.tolist(), near.segment.tolist(), strict=True))
    ys, xs = np.mgrid[0 : shape[0], 0 : shape[1]]
    surely, maybe = set(), set()  # within reach; within reach up to rounding
    for index, (a, b) in enumerate(itertools.pairwise(pieces)):
        distance, _, _ = segment_distance(xs + 0.5, ys + 0.5, a, b)
        for y, x in zip(*np.nonzero(distance <= reach + 1e-9), strict=True):
            maybe.add((int(x), int(y), index))
            if distance[y, x] <= reach - 1e-9:
                surely.add((int(x), int(y), index))
    assert surely <= found <= maybe
    # Sorted by pixel, nearest segment first.
    keys = near.flat * 10.0 + near.distance
    assert np.all(np.diff(keys) >= -1e-9)  # ties may come in either order


@given(
    point=st.tuples(st.floats(-5, 5), st.floats(-5, 5)),
    a=st.tuples(st.floats(-5, 5), st.floats(-5, 5)),
    b=st.tuples(st.floats(-5, 5), st.floats(-5, 5)),
)
# A segment so short that its squared length is subnormal.
@example(point=(0.0, 0.0), a=(1.0, 0.0), b=(1.0, 1.160787573581926e-159))
def test_segment_distance_is_the_distance_to_the_nearest_point(point, a, b):
    a, b = np.array(a), np.array(b)
    distance, along, across = segment_distance(
        np.array([point[0]]), np.array([point[1]]), a[None], b[None]
    )
    samples = a + np.linspace(0, 1, 20001)[:, None] * (b - a)
    brute = np.hypot(*(samples - point).T).min()
    assert distance[0] == pytest.approx(brute, abs=1e-3 * max(1.0, np.hypot(*(b - a))))
    nearest = a + along[0] * (b - a)
    assert np.hypot(*(nearest - point)) == pytest.approx(distance[0], abs=1e-9)
    assert abs(across[0]) <= distance[0] + 1e-9


# --- whole paths ---------------------------------------------------------------------

coarse = st.integers(0, 96).map(lambda n: n / 8)
curve_lists = st.lists(
    st.lists(st.tuples(coarse, coarse), min_size=1, max_size=4).map(np.array),
    min_size=1,
    max_size=4,
)


def dense_distance(samples_x, samples_y, curves, per_curve=4000):
    """Distance from the samples to the curves, each drawn as 4000 chords of t.

    Independent of the reference's flattening: de Casteljau at uniform t,
    then the exact distance to every chord.
    """
    nearest = np.full(samples_x.shape, np.inf)
    for curve in curves:
        points = de_casteljau(np.asarray(curve, dtype=float), np.linspace(0, 1, per_curve + 1))
        start, end = points[:-1], points[1:]
        for a, b in zip(start, end, strict=True):
            distance, _, _ = segment_distance(samples_x, samples_y, a, b)
            nearest = np.minimum(nearest, distance)
    return nearest


@settings(max_examples=15, deadline=None)
@given(curves=curve_lists, width=st.sampled_from([0.5, 1.0, 2.0]))
def test_a_path_reference_is_dense_sampling_of_the_union_of_its_curves(curves, width):
    # Brute force on the reference's own sample grid (k = 3): a sample is in
    # the stroke when it lies within width / 2 of any curve of the path.
    k, shape = 3, (13, 13)
    image = reference(curves, shape, width, k=k)
    samples_x, samples_y = sample_grid(shape, k)
    nearest = dense_distance(samples_x, samples_y, [c for c in curves if len(c) > 1], 400)
    for dot in (c for c in curves if len(c) == 1):
        nearest = np.minimum(nearest, np.hypot(samples_x - dot[0, 0], samples_y - dot[0, 1]))
    # 400 chords per curve stray by at most ~1e-3 px here: a sample that
    # close to the edge may fall either way.
    surely = np.mean(nearest <= width / 2 - 2e-3, axis=-1)
    maybe = np.mean(nearest <= width / 2 + 2e-3, axis=-1)
    assert np.all(surely - 1e-12 <= image) and np.all(image <= maybe + 1e-12)


@settings(max_examples=25, deadline=None)
@given(curves=curve_lists, width=st.sampled_from([0.5, 1.0, 2.0]))
def test_a_path_covers_at_least_each_piece_and_at_most_their_sum(curves, width):
    shape = (13, 13)
    whole = reference(curves, shape, width, k=4)
    pieces = [reference(curve, shape, width, k=4) for curve in curves]
    assert np.all((whole >= 0) & (whole <= 1))
    # Same samples: a sample is in the union iff it is in some piece.
    assert np.all(whole >= np.max(pieces, axis=0))
    assert np.all(whole <= np.sum(pieces, axis=0) + 1e-12)


def test_a_path_reference_accepts_a_matplotlib_path_and_closes_it():
    square = Path([[2.5, 2.5], [8.5, 2.5], [8.5, 8.5], [2.5, 8.5], [0, 0]], [1, 2, 2, 2, 79])
    lines = [[[2.5, 2.5], [8.5, 2.5]], [[8.5, 2.5], [8.5, 8.5]]]
    lines += [[[8.5, 8.5], [2.5, 8.5]], [[2.5, 8.5], [2.5, 2.5]]]
    image = reference(square, (12, 12), 1.0, k=8)
    np.testing.assert_array_equal(image, reference(lines, (12, 12), 1.0, k=8))
    # Pixel (2, 2) holds the corner's quarter disc and three quarter squares.
    assert image[2, 2] == pytest.approx(0.75 + math.pi / 16, abs=0.02)
    assert image[5, 5] == 0.0 and image[2, 5] == 1.0


def test_agg_render_draws_a_whole_path():
    corner = [[[1.0, 1.5], [6.5, 1.5]], [[6.5, 1.5], [6.5, 7.0]]]
    agg = agg_render(corner, (9, 9))
    exact = reference(corner, (9, 9), k=32)
    # Agg's round join is a coarse polygon: 0.07 off at the corner pixel.
    assert np.abs(agg - exact).max() <= 0.1
    assert np.abs(agg - exact).mean() <= 0.01


@pytest.mark.parametrize(
    ("points", "error", "words"),
    [
        ([np.zeros((2, 2)), np.zeros((2, 3))], ValueError, r"points\[1\] must have shape \(N, 2\)"),
        ([[[0, 0], [1, 1]], [[0, 0], [np.nan, 1]]], ValueError, r"points\[1\] must be finite"),
        ([], ValueError, "points must be a 2-D array"),
        (Path([[0, 0], [1, 1]], [1, 7]), ValueError, "points.codes must hold only MOVETO"),
        (Path([[0, 0], [np.inf, 1]]), ValueError, "points.vertices must be finite"),
    ],
)
def test_reference_rejects_bad_paths_by_name(points, error, words):
    with pytest.raises(error, match=words):
        reference(points, (4, 4))


def test_reference_does_not_modify_its_input():
    curves = [np.array([[0.0, 0.0], [3.0, 3.0]]), np.array([[3.0, 3.0], [5.0, 1.0], [6.0, 4.0]])]
    copies = [curve.copy() for curve in curves]
    path = Path(np.array([[0.0, 0.0], [3.0, 3.0], [5.0, 1.0]]), [1, 3, 3])
    vertices = path.vertices.copy()
    reference(curves, (6, 6))
    reference(path, (6, 6))
    for curve, copy in zip(curves, copies, strict=True):
        np.testing.assert_array_equal(curve, copy)
    np.testing.assert_array_equal(path.vertices, vertices)
