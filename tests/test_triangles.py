"""course.raster.triangles: both forms against an exact pixel-centre test; watertight tilings."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from scipy.spatial import Delaunay

from course.raster import hit_counts, triangle, triangle_coverage
from course.raster.triangles import EDGE_RULES, TRIANGLE_METHODS, barycentric, interpolate


def reference_pixels(p0, p1, p2, rule):
    """The definition, in exact rationals: centres inside, edge centres by the rule.

    A centre on an edge counts for "closed", never for "open", and for
    "top-left" when the edge is a top edge (horizontal, the third vertex
    below it; y points down) or a left edge (not horizontal, the third vertex
    to its right).
    """
    vertices = [tuple(Fraction(v) for v in p) for p in (p0, p1, p2)]
    (ax, ay), (bx, by), (cx, cy) = vertices
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) == 0:
        return []
    edges = []
    for k in range(3):
        a, b, c = vertices[k], vertices[(k + 1) % 3], vertices[(k + 2) % 3]
        side_of_c = _side(a, b, c)
        if rule == "closed":
            keep_on_edge = True
        elif rule == "open":
            keep_on_edge = False
        elif a[1] == b[1]:
            keep_on_edge = c[1] > a[1]  # a top edge
        else:
            x_of_edge = a[0] + (c[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            keep_on_edge = c[0] > x_of_edge  # a left edge
        edges.append((a, b, side_of_c, keep_on_edge))
    # Pixels whose centres could be inside: the bounding box, one pixel wider.
    columns = range(int(min(ax, bx, cx)) - 2, int(max(ax, bx, cx)) + 2)
    rows = range(int(min(ay, by, cy)) - 2, int(max(ay, by, cy)) + 2)
    found = []
    for row in rows:
        for column in columns:
            centre = (column + Fraction(1, 2), row + Fraction(1, 2))
            sides = [(_side(a, b, centre), s, keep) for a, b, s, keep in edges]
            if all(side * s > 0 or (side == 0 and keep) for side, s, keep in sides):
                found.append((column, row))
    return found


def _side(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


# Exact binary fractions (sixteenths): snapping to 1/256 leaves them unchanged.
sixteenths = st.integers(-8 * 16, 24 * 16).map(lambda v: v / 16)
halves = st.integers(-4, 36).map(lambda v: v / 2)  # vertices on centres and corners
vertex = st.tuples(sixteenths, sixteenths) | st.tuples(halves, halves)


@pytest.mark.parametrize("method", TRIANGLE_METHODS)
@pytest.mark.parametrize("rule", EDGE_RULES)
@given(p0=vertex, p1=vertex, p2=vertex)
def test_each_form_matches_the_exact_definition(method, rule, p0, p1, p2):
    expected = reference_pixels(p0, p1, p2, rule)
    got = triangle(p0, p1, p2, rule=rule, method=method)
    assert [tuple(p) for p in got.tolist()] == expected


@pytest.mark.parametrize("method", TRIANGLE_METHODS)
@given(p0=vertex, p1=vertex, p2=vertex)
def test_shape_keeps_the_canvas_part_without_wrapping(method, p0, p1, p2):
    full = triangle(p0, p1, p2, method=method)
    clipped = triangle(p0, p1, p2, shape=(9, 13), method=method)
    keep = (full[:, 0] >= 0) & (full[:, 0] < 13) & (full[:, 1] >= 0) & (full[:, 1] < 9)
    np.testing.assert_array_equal(clipped, full[keep])


@given(
    st.lists(st.floats(-50, 80, allow_nan=False), min_size=6, max_size=6),
    st.sampled_from(EDGE_RULES),
)
def test_both_forms_agree_on_arbitrary_floats(coordinates, rule):
    p0, p1, p2 = np.reshape(coordinates, (3, 2))
    np.testing.assert_array_equal(
        triangle(p0, p1, p2, rule=rule), triangle(p0, p1, p2, rule=rule, method="loop")
    )


def test_vertices_snap_to_a_256th_of_a_pixel():
    exact = triangle((0.5, 0.5), (8.5, 0.5), (0.5, 6.5))
    np.testing.assert_array_equal(triangle((0.5 + 1e-9, 0.5), (8.5, 0.5 - 1e-9), (0.5, 6.5)), exact)
    assert len(triangle((0.5 + 1 / 256, 0.5), (8.5, 0.5), (0.5, 6.5))) != len(exact)


@pytest.mark.parametrize("method", TRIANGLE_METHODS)
@pytest.mark.parametrize("rule", EDGE_RULES)
@pytest.mark.parametrize(
    "vertices",
    [
        ((1, 1), (5, 1), (9, 1)),  # height zero
        ((1.5, 1.5), (5.5, 1.5), (9.5, 1.5)),  # height zero, through pixel centres
        ((1.5, 1.5), (3.5, 3.5), (6.5, 6.5)),  # a diagonal through centres
        ((2, 3), (2, 3), (7, 9)),  # two vertices equal
        ((4.5, 4.5), (4.5, 4.5), (4.5, 4.5)),  # a point on a centre
        ((3.5, 0), (3.5, 5), (3.5, 9)),  # vertical, through centres
    ],
)
def test_zero_area_triangles_have_no_pixels(method, rule, vertices):
    assert triangle(*vertices, rule=rule, method=method).shape == (0, 2)


@pytest.mark.parametrize("method", TRIANGLE_METHODS)
@pytest.mark.parametrize(
    "vertices",
    [
        ((0, 0), (6, 0), (3, 4)),  # flat top
        ((3, 0), (0, 4), (6, 4)),  # flat bottom
        ((0.5, 0.5), (6.5, 0.5), (0.5, 4.5)),  # flat top through centres
        ((0.5, 4.5), (6.5, 4.5), (3.5, 0.5)),  # flat bottom through centres
        ((0, 0.5), (100, 0.75), (5, 0.25)),  # thinner than a row
    ],
)
def test_horizontal_edges_need_no_special_case(method, vertices):
    got = triangle(*vertices, method=method)
    expected = reference_pixels(*vertices, "top-left")
    assert [tuple(p) for p in got.tolist()] == expected


# --- watertight: every centre covered exactly once ---------------------------

SHAPE = (14, 17)
# A frame around the canvas: triangulating it covers every pixel centre inside.
FRAME = [(-3.0, -2.0), (20.0, -2.0), (20.0, 16.0), (-3.0, 16.0)]
grid_point = st.tuples(
    st.integers(0, 2 * SHAPE[1]).map(lambda v: v / 2),
    st.integers(0, 2 * SHAPE[0]).map(lambda v: v / 2),
)
fine_point = st.tuples(
    st.integers(0, 16 * SHAPE[1]).map(lambda v: v / 16),
    st.integers(0, 16 * SHAPE[0]).map(lambda v: v / 16),
)


def triangulation_area(points, simplices):
    total = Fraction(0)
    for simplex in simplices:
        a, b, c = (tuple(Fraction(v) for v in points[i]) for i in simplex)
        total += abs(_side(a, b, c)) / 2
    return total


@pytest.mark.parametrize("method", TRIANGLE_METHODS)
@given(st.lists(grid_point | fine_point, min_size=1, max_size=25, unique=True))
def test_a_random_triangulation_paints_every_pixel_exactly_once(method, inner):
    points = np.array(FRAME + inner)
    simplices = Delaunay(points).simplices
    # Qhull may drop or flatten simplices for degenerate inputs; use only
    # triangulations that tile the frame exactly.
    assume(triangulation_area(points, simplices) == 23 * 18)
    pixel_sets = [triangle(*points[s], shape=SHAPE, method=method) for s in simplices]
    np.testing.assert_array_equal(hit_counts(pixel_sets, SHAPE), np.ones(SHAPE, dtype=int))


@given(
    grid_point,
    st.lists(st.integers(0, 4 * 82 - 1), min_size=1, max_size=12, unique=True),
    st.sampled_from(TRIANGLE_METHODS),
)
def test_a_fan_around_a_shared_vertex_paints_every_pixel_exactly_once(centre, ticks, method):
    """Triangles fanned around one vertex (often a pixel centre) tile the frame."""
    # Points walked around the frame's boundary (perimeter 82, ticks of 1/4)
    # with its four corners, in order: a fan from the centre covers the frame.
    boundary = sorted({*ticks, 0, 4 * 23, 4 * 41, 4 * 64} - {4 * 82})
    ring = [_on_frame(t / 4) for t in boundary]
    pixel_sets = [
        triangle(centre, ring[k], ring[(k + 1) % len(ring)], shape=SHAPE, method=method)
        for k in range(len(ring))
    ]
    np.testing.assert_array_equal(hit_counts(pixel_sets, SHAPE), np.ones(SHAPE, dtype=int))


def _on_frame(distance):
    """The point ``distance`` along the frame's boundary, clockwise from its top-left corner."""
    (left, top), (right, _), (_, bottom) = FRAME[0], FRAME[1], FRAME[2]
    width, height = right - left, bottom - top
    if distance <= width:
        return (left + distance, top)
    if distance <= width + height:
        return (right, top + distance - width)
    if distance <= 2 * width + height:
        return (right - (distance - width - height), bottom)
    return (left, bottom - (distance - 2 * width - height))


@pytest.mark.parametrize(("rule", "count"), [("closed", 2), ("open", 0)])
def test_without_the_top_left_rule_a_shared_edge_is_painted_twice_or_not_at_all(rule, count):
    upper = triangle((0, 0), (8, 0), (8, 8), rule=rule)
    lower = triangle((0, 0), (8, 8), (0, 8), rule=rule)
    counts = hit_counts([upper, lower], (8, 8))
    np.testing.assert_array_equal(np.diag(counts), np.full(8, count))
    assert (counts[~np.eye(8, dtype=bool)] == 1).all()


# --- supersampled coverage ----------------------------------------------------


@given(p0=vertex, p1=vertex, p2=vertex)
def test_coverage_at_rate_1_is_the_triangle(p0, p1, p2):
    pixels, weights = triangle_coverage(p0, p1, p2, (20, 20), rate=1)
    np.testing.assert_array_equal(pixels, triangle(p0, p1, p2, shape=(20, 20)))
    assert (weights == 1).all()


@pytest.mark.parametrize("rate", [1, 2, 3, 5, 8])
def test_two_halves_of_a_rectangle_cover_exactly_its_samples(rate):
    """Coverage adds up across the shared diagonal, sample for sample."""
    left, top, right, bottom = 0.3, 1.1, 6.7, 4.2
    shape = (6, 8)
    a, b = triangle_coverage((left, top), (right, top), (right, bottom), shape, rate)
    c, d = triangle_coverage((left, top), (right, bottom), (left, bottom), shape, rate)
    total = np.zeros(shape)
    np.add.at(total, (a[:, 1], a[:, 0]), b)
    np.add.at(total, (c[:, 1], c[:, 0]), d)
    # The rectangle's samples, counted per axis: centres in [left, right).
    samples = (np.arange(8 * rate) + 0.5) / rate
    in_x = ((samples >= left) & (samples < right)).reshape(8, rate).sum(axis=1)
    samples = (np.arange(6 * rate) + 0.5) / rate
    in_y = ((samples >= top) & (samples < bottom)).reshape(6, rate).sum(axis=1)
    np.testing.assert_allclose(total, np.outer(in_y, in_x) / rate**2, rtol=0, atol=1e-15)


def test_coverage_converges_to_the_area():
    p0, p1, p2 = (1.3, 0.7), (14.2, 5.9), (4.1, 11.6)
    area = abs(_side(p0, p1, p2)) / 2
    errors = []
    for rate in (1, 2, 4, 8, 16, 32):
        _, weights = triangle_coverage(p0, p1, p2, (16, 16), rate)
        assert ((weights > 0) & (weights <= 1)).all()
        errors.append(abs(weights.sum() - area))
    assert errors[-1] < 0.05 and errors[-1] < errors[0] / 10


@pytest.mark.parametrize(
    ("call", "error", "words"),
    [
        (lambda: triangle((0, 0), (np.nan, 1), (2, 2)), ValueError, "p1 must be finite"),
        (lambda: triangle((0, 0), (1, 1), (np.inf, 2)), ValueError, "p2 must be finite"),
        (lambda: triangle((0, 0, 1), (1, 1), (2, 2)), ValueError, r"p0 must be one point"),
        (lambda: triangle((0, 0), (1, 1), (3e6, 2)), ValueError, "p2 coordinates must lie"),
        (lambda: triangle((0, 0), (1, 1), (2, 0), rule="left"), ValueError, "rule must be"),
        (lambda: triangle((0, 0), (1, 1), (2, 0), method="x"), ValueError, "method must be"),
        (lambda: triangle((0, 0), (1, 1), (2, 0), shape=(3,)), ValueError, "shape must be"),
        (
            lambda: triangle_coverage((0, 0), (1, 1), (2, 0), (4, 4), 0),
            ValueError,
            "rate must be >= 1",
        ),
        (
            lambda: triangle_coverage((0, 0), (1, 1), (2, 0), (4, 4), 2.5),
            TypeError,
            "rate must be an integer",
        ),
        (
            lambda: triangle_coverage((0, 0), (1, 1), (2, 0), (4, -1), 2),
            ValueError,
            r"shape\[1\] \(width\) must be >= 1",
        ),
        (lambda: hit_counts([np.array([[0.5, 1]])], (2, 2)), TypeError, r"pixel_sets\[0\]"),
    ],
)
def test_bad_input_is_named(call, error, words):
    with pytest.raises(error, match=words):
        call()


grid = st.integers(-64, 64).map(lambda n: n / 8)
corners = st.tuples(grid, grid)


@given(p0=corners, p1=corners, p2=corners, point=corners)
def test_barycentric_weights_sum_to_one_and_rebuild_the_point(p0, p1, p2, point):
    twice_area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0])
    assume(abs(twice_area) > 1)
    weights = barycentric(p0, p1, p2, [point])[0]
    assert weights.sum() == pytest.approx(1.0, abs=1e-12)
    rebuilt = weights @ np.array([p0, p1, p2], dtype=float)
    np.testing.assert_allclose(rebuilt, point, atol=1e-9)
    np.testing.assert_allclose(barycentric(p0, p1, p2, [p0, p1, p2]), np.eye(3), atol=1e-12)


@given(p0=corners, p1=corners, p2=corners)
def test_interpolation_reproduces_an_affine_function_at_every_centre_inside(p0, p1, p2):
    twice_area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0])
    assume(abs(twice_area) > 1)

    def affine(x, y):
        return np.stack([2.0 * x - 3.0 * y + 1.0, 0.5 * x + 0.25 * y], axis=-1)

    vertices = np.array([p0, p1, p2], dtype=float)
    pixels, values = interpolate(p0, p1, p2, affine(vertices[:, 0], vertices[:, 1]))
    np.testing.assert_array_equal(pixels, triangle(p0, p1, p2))
    centres = pixels + 0.5
    np.testing.assert_allclose(values, affine(centres[:, 0], centres[:, 1]), atol=1e-9)
    # Centres inside have weights in [0, 1] (to rounding): the triangle's own test.
    weights = barycentric(p0, p1, p2, centres)
    assert (weights > -1e-12).all() and (weights < 1 + 1e-12).all()


def test_barycentric_and_interpolate_refuse_bad_input_by_name():
    with pytest.raises(ValueError, match=r"p0, p1, p2 must span a triangle of non-zero area"):
        barycentric((0, 0), (1, 1), (2, 2), [[0, 0]])
    with pytest.raises(ValueError, match=r"values must be finite numbers, one row per vertex"):
        interpolate((0, 0), (4, 0), (0, 4), [1.0, 2.0])
    with pytest.raises(ValueError, match=r"points must have shape \(K, 2\)"):
        barycentric((0, 0), (4, 0), (0, 4), [[0, 0, 0]])
    empty_pixels, empty_values = interpolate((0, 0), (0.2, 0), (0, 0.2), np.eye(3))
    assert empty_pixels.shape == (0, 2) and empty_values.shape == (0, 3)
