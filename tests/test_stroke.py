"""stroke_area: the exact coverage of a stroked polyline or path, round joins and caps.

Every property is checked against the exact reference (k x k point samples
against the exact distance), whose own error is at most about 1 / k per
pixel; the stroke's integrated pixels (where parts of the path overlap) err
by at most 1 / 32 (16 rows, exact along each).
"""

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from matplotlib.path import Path

from course.antialias import _fill as fill
from course.antialias import render, stroke_area, stroke_linear
from course.antialias._fill import accumulate
from course.antialias._integrate import ROWS, row_coverage
from course.antialias.coverage import reference
from course.curves.paths import text_curves

K = 48
# Stated tolerance against the reference: its 1 / K plus 1 / 32 where the
# stroke integrates, plus the polygons of the round joins (1e-4).
TOLERANCE = 1 / K + 1 / ROWS + 1e-3
# RMSE over a 16 x 16 canvas: the reference's 1 / K on every pixel of a
# near-horizontal edge dominates it.
RMSE_TOLERANCE = 6e-3

coordinate = st.integers(16, 240).map(lambda n: n / 16)
polylines = st.lists(st.tuples(coordinate, coordinate), min_size=2, max_size=6).map(np.array)
widths = st.sampled_from([0.5, 1.0, 2.0, 3.0])


def as_image(pixels, weights, shape):
    image = np.zeros(shape)
    image[pixels[:, 1], pixels[:, 0]] = weights
    return image


def pieces(line):
    return [line[i : i + 2] for i in range(len(line) - 1)]


ISSUE_CORNER = np.array([[10.5, 10.5], [20.5, 10.5], [10.5, 12.5]])


def test_the_issues_sharp_corner_covers_nothing_past_the_vertex():
    pixels, weights = stroke_area(ISSUE_CORNER, 1.0, (30, 30))
    image = as_image(pixels, weights, (30, 30))
    assert image[10, 21] == 0.0  # a mitre would give 1.0 here
    exact = reference(pieces(ISSUE_CORNER), (30, 30), 1.0, k=64)
    assert exact[10, 21] == 0.0
    assert np.abs(image - exact).max() <= 1 / ROWS + 1e-3


@settings(max_examples=40, deadline=None)
@given(line=polylines, width=widths)
@example(line=ISSUE_CORNER - 5, width=1.0)
@example(line=np.array([[2.0, 5.0], [12.0, 5.0], [4.0, 5.0]]), width=1.0)  # a cusp
@example(line=np.array([[3.0, 3.0], [12.0, 3.0], [12.0, 12.0], [3.0, 3.0]]), width=2.0)  # closed
@example(line=np.array([[8.0, 8.0], [8.0, 8.0]]), width=3.0)  # a dot
def test_stroke_area_is_the_reference_within_the_stated_tolerance(line, width):
    shape = (16, 16)
    copy = line.copy()
    image = as_image(*stroke_area(line, width, shape), shape)
    np.testing.assert_array_equal(line, copy)  # the input is not modified
    exact = reference(pieces(line), shape, width, k=K)
    assert np.all((image >= 0) & (image <= 1))
    error = image - exact
    assert np.abs(error).max() <= TOLERANCE
    assert np.sqrt(np.mean(error**2)) <= RMSE_TOLERANCE


@settings(max_examples=25, deadline=None)
@given(
    start=st.tuples(coordinate, coordinate),
    end=st.tuples(coordinate, coordinate),
    cuts=st.lists(st.floats(0.01, 0.99), min_size=1, max_size=5),
    width=widths,
)
def test_a_straight_polyline_split_in_pieces_covers_what_it_did_whole(start, end, cuts, width):
    start, end = np.array(start), np.array(end)
    t = np.sort(np.array(cuts))
    split = np.vstack([start, start + t[:, None] * (end - start), end])
    shape = (16, 16)
    whole = render([start, end], shape, "stroke_area", width)
    as_polyline = as_image(*stroke_area(split, width, shape), shape)
    as_path = render(pieces(split), shape, "stroke_area", width)
    np.testing.assert_allclose(as_polyline, whole, atol=1e-9)
    np.testing.assert_allclose(as_path, whole, atol=1e-9)


@settings(max_examples=25, deadline=None)
@given(line=polylines, width=widths)
def test_a_path_covers_at_least_each_piece_and_at_most_their_sum(line, width):
    shape = (16, 16)
    whole = render(pieces(line), shape, "stroke_area", width)
    each = [render(piece, shape, "stroke_area", width) for piece in pieces(line)]
    # Exact areas obey both exactly; the integrated pixels err by 1 / 32.
    slack = 1 / ROWS + 1e-6
    assert np.all(whole >= np.max(each, axis=0) - slack)
    assert np.all(whole <= np.sum(each, axis=0) + slack)


def test_joined_curves_are_one_stroke_not_the_max_of_their_strokes():
    # Before: each curve stroked alone and combined with max, which misses
    # the pixels both strokes half cover at the join.
    corner = [[[2.0, 2.5], [9.5, 2.5]], [[9.5, 2.5], [9.5, 10.0]]]
    joined = render(corner, (12, 12), "stroke_area")
    maximum = np.maximum(*(render(curve, (12, 12), "stroke_area") for curve in corner))
    exact = reference(corner, (12, 12), k=64)
    assert np.abs(joined - exact).max() <= 1 / 64
    assert np.abs(maximum - exact).max() >= 0.05  # 0.054 at the corner pixel


def test_a_whole_line_of_text_is_within_tolerance_of_the_reference():
    curves = text_curves("Bé", size=24)
    shape = (24, 34)
    exact = reference(curves, shape, 1.0, k=K)
    image = render(curves, shape, "stroke_area")
    error = image - exact
    assert np.abs(error).max() <= TOLERANCE
    assert np.sqrt(np.mean(error**2)) <= RMSE_TOLERANCE
    linear = render(curves, shape, "stroke_linear")
    assert np.sqrt(np.mean(error**2)) < np.sqrt(np.mean((linear - exact) ** 2))


def test_a_single_point_draws_a_disc():
    image = render([[5.0, 5.0]], (10, 10), "stroke_area", width=4.0)
    assert image.sum() == pytest.approx(math.pi * 4, rel=1e-3)
    assert image[5, 5] == 1.0


def test_a_closed_square_has_no_caps():
    square = Path([[2.5, 2.5], [8.5, 2.5], [8.5, 8.5], [2.5, 8.5], [0, 0]], closed=True)
    image = render(square, (12, 12), "stroke_area")
    # The 7 x 7 square with quarter discs of radius 1/2 at its corners, less
    # the 5 x 5 hole: no caps, each corner counted once.
    assert image.sum() == pytest.approx(49 - (1 - math.pi / 4) - 25, abs=1e-3)


def test_stroke_area_without_a_canvas_returns_every_pixel():
    line = np.array([[-3.0, 2.5], [5.0, 2.5]])
    pixels, weights = stroke_area(line)
    assert pixels[:, 0].min() == -4 and weights.sum() == pytest.approx(8 + math.pi / 4, abs=1e-3)
    on, on_weights = stroke_area(line, 1.0, (6, 6))
    keep = (pixels >= 0).all(axis=1) & (pixels < 6).all(axis=1)
    np.testing.assert_array_equal(on, pixels[keep])
    np.testing.assert_allclose(on_weights, weights[keep], atol=1e-12)


def test_gaps_are_not_drawn():
    line = np.array([[2.0, 2.5], [6.0, 2.5], [2.0, 8.5], [6.0, 8.5]])
    gaps = np.array([False, True, False])
    for function in (stroke_area, stroke_linear):
        image = as_image(*function(line, 1.0, (12, 12), gaps), (12, 12))
        assert image[5].sum() == 0.0
        assert image[2, 3] == pytest.approx(1.0) and image[8, 3] == pytest.approx(1.0)


def test_gaps_of_the_wrong_shape_are_refused_by_name():
    with pytest.raises(ValueError, match=r"gaps must be a bool array of shape \(2,\)"):
        stroke_area([[0, 0], [1, 1], [2, 0]], gaps=[True])


def test_accumulate_gives_the_area_of_a_polygon_inside_each_pixel():
    # A unit square from (0.5, 0.5), counter-clockwise in image space.
    square = np.array([[0.5, 0.5], [0.5, 1.5], [1.5, 1.5], [1.5, 0.5]])
    image = accumulate(square, np.roll(square, -1, axis=0), (3, 3))
    np.testing.assert_allclose(np.abs(image)[:2, :2], 0.25)
    assert np.abs(image).sum() == pytest.approx(1.0)


@settings(max_examples=30, deadline=None)
@given(
    points=st.lists(st.tuples(coordinate, coordinate), min_size=1, max_size=4),
    half=st.sampled_from([0.25, 0.5, 1.0]),
)
def test_row_coverage_is_dense_sampling_of_the_rows(points, half):
    # Exact along each row: against 4000 samples per row, the same rows.
    segments = np.array(points)
    start, end = segments, np.roll(segments, -1, axis=0)
    x, y = np.floor(segments[0]) - 1
    rows = 8
    count = len(segments)
    got = row_coverage(
        np.full(count, x), np.full(count, y), start, end, np.zeros(count), half, rows
    )[0]
    sample_x = x + (np.arange(4000) + 0.5) / 4000
    sample_y = y + (np.arange(rows) + 0.5) / rows
    px, py = np.meshgrid(sample_x, sample_y)
    inside = np.zeros(px.shape, dtype=bool)
    for a, b in zip(start, end, strict=True):
        d = b - a
        t = np.clip(((px - a[0]) * d[0] + (py - a[1]) * d[1]) / max(d @ d, 1e-300), 0, 1)
        inside |= np.hypot(px - a[0] - t * d[0], py - a[1] - t * d[1]) <= half
    assert got == pytest.approx(inside.mean(), abs=2 / 4000)


curve_lists = st.lists(
    st.lists(st.tuples(coordinate, coordinate), min_size=1, max_size=4).map(np.array),
    min_size=1,
    max_size=4,
)


@settings(max_examples=30, deadline=None)
@given(curves=curve_lists, width=widths)
@example(curves=[np.array([[3.0, 3.0], [9.0, 3.0]]), np.array([[9.0, 4.0]])], width=1.0)
def test_a_path_of_curves_is_the_reference_within_the_stated_tolerance(curves, width):
    # Lines, quadratics, cubics and dots, joined or not. The curves are
    # flattened within 0.01 px, which moves an edge by as much.
    shape = (16, 16)
    image = render(curves, shape, "stroke_area", width)
    exact = reference(curves, shape, width, k=K)
    error = image - exact
    assert np.abs(error).max() <= TOLERANCE + 0.01
    assert np.sqrt(np.mean(error**2)) <= RMSE_TOLERANCE


@pytest.mark.parametrize("centre", [(3.2, 2.7), (1.1, 4.6)])
def test_accumulate_fills_polylines_as_it_fills_their_edges(centre):
    # Two circles of short chords, one crossing the canvas's sides: the runs
    # of chords within one pixel are filled as one edge and the area between.
    angle = np.linspace(0.0, 2 * np.pi, 301)[:, None]
    circle = np.hstack([np.cos(angle), np.sin(angle)])
    points = np.vstack([np.add(centre, 2.3 * circle), np.add(centre, 1.2 * circle[::-1])])
    last = np.zeros(len(points), dtype=bool)
    last[[300, 601]] = True
    edges = (points[:-1][~last[:-1]], points[1:][~last[:-1]])
    empty = np.zeros((0, 2))
    chained = accumulate(empty, empty, (5, 6), chains=(points, last))
    np.testing.assert_allclose(chained, accumulate(*edges, (5, 6)), atol=1e-12)


@settings(max_examples=30, deadline=None)
@given(
    corners=st.lists(
        st.tuples(st.floats(-5, 70, allow_nan=False), st.floats(-5, 45, allow_nan=False)),
        min_size=3,
        max_size=8,
    ),
    width=st.sampled_from([31, 32, 33, 64]),
)
def test_accumulate_sums_by_blocks_as_it_sums_whole_rows(corners, width):
    # The running sums of a large canvas run block by block; a small one's
    # whole rows. Both give the same areas, off-canvas parts included.
    polygon = np.array(corners)
    edges = (polygon, np.roll(polygon, -1, axis=0))
    dense = fill._DENSE
    try:
        fill._DENSE = 0
        blocks = accumulate(*edges, (40, width))
        fill._DENSE = 10**9
        rows = accumulate(*edges, (40, width))
    finally:
        fill._DENSE = dense
    np.testing.assert_allclose(blocks, rows, atol=1e-9)


def test_a_point_crowding_a_segment_is_found_past_a_nearer_point():
    # The segment's nearest point lies 1.13 away, a second one 2.69 away, both
    # within the width 3: the second's overlap must be integrated too (it was
    # missed when only the nearest point was asked for: pixel (2, 0) got 1.0).
    curves = [
        np.array([(1.0, 2.125)]),
        np.array([(3.875, 1.125)]),
        np.array([(1.0, 1.0), (1.1875, 1.0)]),
    ]
    image = render(curves, (6, 8), "stroke_area", 3.0)
    exact = reference(curves, (6, 8), 3.0, k=K)
    assert image[0, 2] == pytest.approx(0.898, abs=0.01)
    assert np.abs(image - exact).max() <= TOLERANCE


def test_a_path_running_over_itself_thousands_of_times_is_refused_not_integrated():
    from course import limits
    from course.antialias import stroke_area

    zigzag = np.resize([[2.0, 3.0], [14.0, 1.0], [3.0, 13.0], [13.0, 14.0]], (1501, 2))
    with pytest.raises(ValueError, match=f"more than the {limits.MAX_OVERLAP_PAIRS}"):
        stroke_area(zigzag)
    assert stroke_area(zigzag[:101])[1].max() <= 1.0
