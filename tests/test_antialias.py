"""course.antialias: every splat against its definition, render at the edges, bad input."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from course.antialias import (
    ONE_SAMPLE,
    RENDER_METHODS,
    SPLATS,
    STROKES,
    arc_length_step,
    arc_length_weights,
    bilinear_centres,
    bilinear_corners,
    curve_samples,
    nearest_round,
    nearest_truncate,
    normalised_centres,
    render,
    splat,
    stroke_area,
    stroke_linear,
    stroke_polyline,
    subsample_falloff,
    wang_segments,
)
from course.antialias.coverage import reference
from course.curves.bezier import de_casteljau
from course.curves.flattening import uniform_parameters
from course.images import SEED_000_CUBIC
from course.raster import nearest_pixels

# Coordinates that are exact binary fractions, so sums and floors are exact.
coordinate = st.integers(-4096, 4096).map(lambda n: n / 64)
sample_arrays = st.lists(st.tuples(coordinate, coordinate), min_size=1, max_size=30).map(
    lambda rows: np.array(rows, dtype=float)
)
# Arbitrary floats too: the loop and vectorized forms must agree on those as well.
any_samples = st.lists(
    st.tuples(
        st.floats(-50, 50, allow_nan=False, allow_infinity=False),
        st.floats(-50, 50, allow_nan=False, allow_infinity=False),
    ),
    min_size=1,
    max_size=30,
).map(lambda rows: np.array(rows, dtype=float))

NORMALISED = ("nearest_truncate", "nearest_round", "bilinear_zero_offset", "bilinear_corners")
NORMALISED += ("bilinear_centres", "normalised_centres")


@pytest.mark.parametrize("kind", SPLATS)
@given(samples=any_samples)
def test_the_vectorized_splat_matches_the_one_sample_loop(kind, samples):
    pixels, weights = splat(samples, kind)
    loop_pixels, loop_weights = splat(samples, kind, method="loop")
    np.testing.assert_array_equal(pixels, loop_pixels)
    np.testing.assert_allclose(weights, loop_weights, rtol=0, atol=1e-12)


@pytest.mark.parametrize("method", SPLATS)
@given(samples=any_samples)
def test_weights_lie_in_zero_one(method, samples):
    _, weights = splat(samples, method)
    assert weights.min() >= -1e-12 and weights.max() <= 1 + 1e-12


@pytest.mark.parametrize("method", NORMALISED)
@given(samples=any_samples)
def test_normalised_splats_share_each_sample_exactly_once(method, samples):
    _, weights = splat(samples, method)
    per_sample = weights.reshape(len(samples), -1).sum(axis=1)
    np.testing.assert_allclose(per_sample, 1.0, rtol=0, atol=1e-12)


@given(samples=sample_arrays)
def test_nearest_methods_are_the_raster_modules_roundings(samples):
    np.testing.assert_array_equal(
        nearest_truncate(samples)[0], nearest_pixels(samples, rounding="trunc")
    )
    np.testing.assert_array_equal(nearest_round(samples)[0], nearest_pixels(samples, "round"))


@given(samples=any_samples)
def test_bilinear_centres_put_the_mass_centre_on_the_point(samples):
    # First moment: sum of weight * pixel centre is the point itself.
    pixels, weights = bilinear_centres(samples)
    centres = (pixels + 0.5).reshape(len(samples), 4, 2)
    mean = np.einsum("sk,skd->sd", weights.reshape(len(samples), 4), centres)
    np.testing.assert_allclose(mean, samples, atol=1e-9)


@given(samples=any_samples)
def test_bilinear_corners_put_the_mass_centre_half_a_pixel_off(samples):
    # Seed 000 "middle" is bilinear about pixel corners: centred on the point
    # in corner coordinates, so half a pixel up-left of it in centre terms.
    pixels, weights = bilinear_corners(samples)
    corners = pixels.reshape(len(samples), 4, 2)
    mean = np.einsum("sk,skd->sd", weights.reshape(len(samples), 4), corners)
    np.testing.assert_allclose(mean, samples, atol=1e-9)


@given(samples=sample_arrays)
def test_seed_000_left_is_pixel_for_pixel_the_unsmoothed_curve(samples):
    pixels, weights = splat(samples, "bilinear_zero_offset")
    assert weights.reshape(-1, 4).tolist() == [[1.0, 0.0, 0.0, 0.0]] * len(samples)
    np.testing.assert_array_equal(pixels[::4], nearest_round(samples)[0])


@given(samples=any_samples)
def test_seed_003_splats_the_2x2_pixel_centres_around_the_point(samples):
    pixels, weights = normalised_centres(samples)
    for point, block, share in zip(
        samples, pixels.reshape(-1, 4, 2), weights.reshape(-1, 4), strict=True
    ):
        centres = block + 0.5
        # A 2 x 2 block of pixels ...
        assert np.ptp(block, axis=0).tolist() == [1, 1]
        assert len({tuple(pixel) for pixel in block.tolist()}) == 4
        # ... whose four centres enclose the point.
        assert np.all(centres.min(axis=0) <= point) and np.all(point <= centres.max(axis=0))
        distance = np.hypot(*(centres - point).T)
        expected = (math.sqrt(2) - distance) / (math.sqrt(2) - distance).sum()
        np.testing.assert_allclose(share, expected, atol=1e-12)


def test_seed_002_weight_is_the_mean_of_four_falloffs():
    points = np.array([[3.5, 2.5], [3.0, 2.0], [3.9, 2.1], [3.25, 2.75]])
    _, weights = subsample_falloff(points)
    max_distance = math.sqrt(1.125)
    for (x, y), weight in zip(points, weights, strict=True):
        subs = [(3.25, 2.25), (3.75, 2.25), (3.25, 2.75), (3.75, 2.75)]
        falloff = [(max_distance - math.hypot(x - sx, y - sy)) / max_distance for sx, sy in subs]
        assert weight == pytest.approx(sum(falloff) / 4, abs=1e-12)
    # Brightest at the centre (2/3), dimmest at a corner, never 1.
    assert weights[0] == pytest.approx(2 / 3)
    assert weights[1] == pytest.approx(weights.min())
    assert subsample_falloff(points)[0].tolist() == [[3, 2]] * 4


def test_arc_length_weights_add_up_to_the_polyline_length():
    points = de_casteljau([[0, 0], [30, 40], [60, 0]], np.linspace(0, 1, 50))
    total = np.hypot(*np.diff(points, axis=0).T).sum()
    assert arc_length_weights(points).sum() == pytest.approx(total)


def test_wang_segments_keep_the_chords_within_tolerance():
    control = SEED_000_CUBIC
    count = wang_segments(control, 0.05)
    chords = de_casteljau(control, np.linspace(0, 1, count + 1))
    # Each chord's midpoint parameter is where a chord strays most, roughly;
    # check many points of every piece against the chord.
    fine = np.linspace(0, 1, 40 * count + 1)
    curve = de_casteljau(control, fine)
    piece = np.minimum((fine * count).astype(int), count - 1)
    start, end = chords[piece], chords[piece + 1]
    direction = end - start
    u = np.clip(np.sum((curve - start) * direction, axis=1) / np.sum(direction**2, axis=1), 0, 1)
    gap = np.hypot(*(curve - start - u[:, None] * direction).T)
    assert gap.max() <= 0.05


# --- render: the canvas edges ---------------------------------------------------

SHAPE = (24, 32)
# A curve that starts left of the canvas, dips below it, and leaves past the
# right edge near the top: it crosses every edge, with negative coordinates.
EDGE_CURVE = np.array([[-6.0, 12.0], [10.0, 40.0], [20.0, -18.0], [40.0, 3.0]])


def _accumulate_by_loop(method, step):
    """The readable definition: samples, the one-sample splat, a bounds check, a sum."""
    samples = curve_samples(EDGE_CURVE, step)
    np.testing.assert_allclose(samples, de_casteljau(EDGE_CURVE, uniform_parameters(step)))
    image = np.zeros(SHAPE)
    for x, y in samples:
        for (column, row), weight in ONE_SAMPLE[method](x, y):
            if 0 <= row < SHAPE[0] and 0 <= column < SHAPE[1]:
                image[row, column] = min(1.0, image[row, column] + weight)
    return image


@pytest.mark.parametrize("method", SPLATS)
def test_render_at_every_edge_equals_the_loop_that_skips_off_canvas_pixels(method):
    expected = _accumulate_by_loop(method, 0.005)
    np.testing.assert_allclose(render(EDGE_CURVE, SHAPE, method, step=0.005), expected, atol=1e-12)


@pytest.mark.parametrize("method", RENDER_METHODS)
@pytest.mark.parametrize("offset", [0.25, 0.75, 1.5])
def test_nothing_wraps_around_to_the_far_side(method, offset):
    # Lines just outside each edge, running past both ends of it: a negative
    # index would wrap the left and top ones onto the last columns and rows.
    height, width = SHAPE
    left = [[-offset, -3.0], [-offset, height + 3.0]]
    top = [[-3.0, -offset], [width + 3.0, -offset]]
    right = [[width + offset, -3.0], [width + offset, height + 3.0]]
    bottom = [[-3.0, height + offset], [width + 3.0, height + offset]]
    assert render(left, SHAPE, method, step=0.002)[:, 2:].sum() == 0.0
    assert render(top, SHAPE, method, step=0.002)[2:, :].sum() == 0.0
    assert render(right, SHAPE, method, step=0.002)[:, :-2].sum() == 0.0
    assert render(bottom, SHAPE, method, step=0.002)[:-2, :].sum() == 0.0


def test_truncation_folds_the_strip_left_of_the_canvas_onto_column_0():
    # C++ int() truncates: x in (-1, 0) lands in column 0, x <= -1 nowhere.
    image = render([[-0.5, 2.5], [-0.5, 9.5]], SHAPE, "nearest_truncate", step=0.01)
    assert image[3:9, 0].tolist() == [1.0] * 6
    # Off the rounding boundary at exactly -1, where curve evaluation may give -1 + 1 ulp.
    assert render([[-1.5, 2.5], [-1.5, 9.5]], SHAPE, "nearest_truncate").sum() == 0.0


@pytest.mark.parametrize("method", [*SPLATS, "stroke_linear", "stroke_area"])
def test_splats_with_a_shape_keep_only_pixels_on_the_canvas(method):
    samples = stroke_polyline(EDGE_CURVE)
    if method in SPLATS:
        pixels, weights = splat(samples, method, shape=SHAPE)
        all_pixels, all_weights = splat(samples, method)
    else:
        function = stroke_linear if method == "stroke_linear" else stroke_area
        pixels, weights = function(samples, 1.0, SHAPE)
        all_pixels, all_weights = function(samples, 1.0)
    on_canvas = (
        (all_pixels[:, 0] >= 0)
        & (all_pixels[:, 0] < SHAPE[1])
        & (all_pixels[:, 1] >= 0)
        & (all_pixels[:, 1] < SHAPE[0])
    )
    assert (~on_canvas).any()  # the curve does leave the canvas
    np.testing.assert_array_equal(pixels, all_pixels[on_canvas])
    np.testing.assert_allclose(weights, all_weights[on_canvas])


@pytest.mark.parametrize("method", STROKES)
def test_stroke_methods_match_the_reference_at_the_edges(method):
    exact = reference(EDGE_CURVE, SHAPE, 1.0, k=32)
    image = render(EDGE_CURVE, SHAPE, method)
    # Stated tolerances: the distance formula errs by up to 0.1 at 45 degrees,
    # the band area by the curve's bend and the reference's 1/32 sampling.
    assert np.abs(image - exact).max() <= (0.1 if method == "stroke_linear" else 0.04)


# --- stroke coverage against the exact reference -------------------------------

SEED_CURVE = SEED_000_CUBIC / 5


@pytest.mark.parametrize("width", [1.0, 2.5])
def test_stroke_area_is_within_stated_tolerance_of_the_reference(width):
    exact = reference(SEED_CURVE, (140, 140), width, k=64)
    image = render(SEED_CURVE, (140, 140), "stroke_area", width)
    error = image - exact
    # The seed curve shrunk 5x bends 5x tighter than in the lesson.
    assert np.sqrt(np.mean(error**2)) <= 2e-3
    assert np.abs(error).max() <= 0.05
    # Total ink is the stroke's area: width x length + a disc for the caps.
    assert image.sum() == pytest.approx(exact.sum(), rel=2e-3)


def test_stroke_linear_errs_where_the_formula_says():
    exact = reference(SEED_CURVE, (140, 140), 1.0, k=64)
    error = np.abs(render(SEED_CURVE, (140, 140), "stroke_linear") - exact)
    assert error.max() <= 0.1
    # An axis-aligned line is exact for the distance formula.
    line = [[3.0, 5.3], [27.0, 5.3]]
    pixels, weights = stroke_linear(stroke_polyline(line), 1.0, (12, 30))
    image = np.zeros((12, 30))
    image[pixels[:, 1], pixels[:, 0]] = weights
    np.testing.assert_allclose(image[:, 6:24], reference(line, (12, 30), 1.0, k=80)[:, 6:24])


def test_a_single_point_draws_a_disc():
    image = render([[5.0, 5.0]], (10, 10), "stroke_area", width=4.0)
    assert image.sum() == pytest.approx(math.pi * 4, rel=0.02)
    assert image[5, 5] == 1.0


# --- the arc-length fix ----------------------------------------------------------


def test_arc_length_weighting_puts_one_unit_of_ink_per_unit_of_length():
    line = [[4.5, 6.5], [54.5, 6.5]]
    for step in (0.01, 0.002, 0.0005):
        image = render(line, (12, 60), "bilinear_centres", step=step, weighting="arc_length")
        assert image.sum() == pytest.approx(50.0)
    # The handouts' count grows with the number of samples until it saturates.
    counts = [render(line, (12, 60), "bilinear_corners", step=s).sum() for s in (0.05, 0.02)]
    assert counts[1] > 1.5 * counts[0]


def test_arc_length_default_step_leaves_samples_half_a_pixel_apart():
    control = SEED_000_CUBIC
    samples = curve_samples(control, arc_length_step(control))
    assert np.hypot(*np.diff(samples, axis=0).T).max() <= 0.5
    # Close enough that a finer step changes little.
    shape = (700, 700)
    default = render(control, shape, "bilinear_centres", weighting="arc_length")
    finer = render(control, shape, "bilinear_centres", step=2e-5, weighting="arc_length")
    assert np.sqrt(np.mean((default - finer) ** 2)) <= 1e-3


# --- bad input ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"method": "gaussian"}, ValueError, "method must be one of"),
        ({"width": 0.0}, ValueError, "width must be > 0"),
        ({"width": -1.0}, ValueError, "width must be > 0"),
        ({"width": math.inf}, ValueError, "width must be finite"),
        ({"step": 0.0}, ValueError, "step must be > 0"),
        ({"weighting": "length"}, ValueError, "weighting must be one of"),
        ({"shape": (10,)}, ValueError, "shape must be a pair"),
        ({"shape": (10, 0)}, ValueError, "shape.1. .width. must be >= 1"),
        ({"points": [[0, 0, 0], [1, 1, 1]]}, ValueError, r"points must have shape \(N, 2\)"),
        ({"points": [0, 1, 2, 3]}, ValueError, r"points must be a 2-D array"),
        ({"points": [[0, 0], [np.nan, 1]]}, ValueError, "points must be finite"),
        ({"points": [[0, 0], [np.inf, 1]]}, ValueError, "points must be finite"),
        ({"points": [["a", "b"]]}, TypeError, "points must hold real numbers"),
    ],
)
def test_render_rejects_bad_input_by_name(kwargs, error, words):
    arguments = {"points": [[0, 0], [5, 5]], "shape": (8, 8), "method": "stroke_area"} | kwargs
    with pytest.raises(error, match=words):
        render(**arguments)


@pytest.mark.parametrize("kind", SPLATS)
def test_splats_reject_bad_samples_by_name(kind):
    with pytest.raises(ValueError, match=r"samples must have shape \(M, 2\)"):
        splat(np.zeros((3, 3)), kind)
    with pytest.raises(ValueError, match="samples must be finite"):
        splat([[0.0, np.nan]], kind)
    with pytest.raises(ValueError, match="kind must be one of"):
        splat([[0.0, 0.0]], kind + "_typo")
    with pytest.raises(ValueError, match="method must be one of 'vectorized', 'loop'"):
        splat([[0.0, 0.0]], kind, method="fast")


def test_stroke_functions_reject_bad_polylines_and_widths():
    with pytest.raises(ValueError, match=r"polyline must have shape \(K, 2\)"):
        stroke_area(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="width must be > 0"):
        stroke_linear([[0.0, 0.0], [1.0, 1.0]], width=0)


def test_render_does_not_modify_its_input():
    points = EDGE_CURVE.copy()
    for method in RENDER_METHODS:
        render(points, SHAPE, method)
    np.testing.assert_array_equal(points, EDGE_CURVE)


def test_render_refuses_a_step_that_would_take_too_many_samples():
    from course import limits

    with pytest.raises(ValueError, match="step"):
        render([[0.0, 1.0], [4.0, 1.0]], (4, 4), "bilinear_centres", step=1e-9)
    many = [[[0.0, 1.0], [4.0, 1.0]]] * (limits.MAX_STEP_SAMPLES // 1000)
    with pytest.raises(ValueError, match=r"samples over \d+ curves"):
        render(many, (4, 4), "bilinear_centres", step=0.001)
    long_curve = [[0.0, 0.0], [2.0**20, 0.0]]
    with pytest.raises(ValueError, match="a long curve takes a fine default step"):
        render(long_curve, (4, 4), "bilinear_centres", weighting="arc_length")


def test_curve_samples_refuses_a_step_too_fine():
    from course.antialias import curve_samples

    with pytest.raises(ValueError, match="step must give at most"):
        curve_samples([[0.0, 1.0], [4.0, 1.0]], 1e-9)


@pytest.mark.parametrize("kind", SPLATS)
@given(samples=any_samples, height=st.integers(1, 20), width=st.integers(1, 20))
def test_a_sample_render_leaves_out_paints_nothing_on_the_canvas(kind, samples, height, width):
    from course.antialias._render import _touching
    from course.antialias.splats import splat_points
    from course.raster._paint import on_canvas

    touching = _touching(samples, (height, width))
    left_out = samples[:0] if touching is None else samples[~touching]
    pixels, _weights = splat_points(left_out, kind)
    assert not on_canvas(pixels, (height, width)).any()


@pytest.mark.parametrize("method", SPLATS)
@pytest.mark.parametrize("weighting", ["count", "arc_length"])
def test_a_small_canvas_on_a_long_curve_is_painted_as_by_every_sample(method, weighting):
    from course.antialias import _render

    points = np.array(SEED_000_CUBIC, dtype=float) - (320, 149)  # a 16 x 16 window on it
    drawn = render(points, (16, 16), method, weighting=weighting)
    original = _render._touching
    _render._touching = lambda samples, canvas: None
    try:
        every = render(points, (16, 16), method, weighting=weighting)
    finally:
        _render._touching = original
    assert drawn.any() and np.array_equal(drawn, every)
    samples = _render.evaluate(points, np.linspace(0.0, 1.0, 1001))
    assert original(samples, (16, 16)).sum() < 100  # the rest were left out
