"""Where the outline of a stroke is not its boundary: overlaps, settled by integration.

The outline :mod:`course.antialias.stroke` draws is the boundary of the stroke where
the path does not come back on itself. Two parts of the path that come
within w of each other without being neighbours along it (a loop, two
subpaths, a hairpin) overlap, and the outline counts the overlap twice.
:func:`overlapping` finds those segments (pairs within w of each other,
except neighbours and pairs the path turns less than ``TURNING_LIMIT``
between), and :func:`integrate` recomputes the pixels near them: the exact
length of each of ``ROWS`` rows of the pixel inside the union of the
segments' stadiums, averaged (the midpoint rule in y, exact in x).
"""

from __future__ import annotations

import itertools

import numpy as np
from scipy.spatial import cKDTree

from course import limits
from course.antialias._segments import Segments
from course.antialias.near_pixels import HALF_DIAGONAL, first_of_runs, pixels_near
from course.i18n import _

__all__ = [
    "ROWS",
    "TURNING_LIMIT",
    "crowded_dots",
    "distance_to",
    "integrate",
    "overlapping",
    "row_coverage",
]

#: Rows per pixel where parts of the path overlap.
ROWS = 16
#: A path that turns less than this between two segments cannot bring them
#: within w of each other except through the joins between them, which the
#: outline settles (a hairpin or a loop turns by half a turn or more).
TURNING_LIMIT = 0.75 * np.pi


def overlapping(segments: Segments, half: float) -> np.ndarray:
    """Segments within 2 half of a segment that is not a neighbour along the path."""
    s = segments
    doubtful = np.zeros(len(s.length), dtype=bool)
    if len(s.length) < 2:
        return doubtful
    first, second = _candidate_pairs(s, 2 * half)
    if len(first) > limits.MAX_OVERLAP_PAIRS:
        raise ValueError(
            _(
                "polyline: {first_count} pairs of its segments come within the stroke's width of "
                "each other, more than the {most} the exact stroke examines; a path "
                "that runs over itself this often is better drawn in pieces"
            ).format(first_count=len(first), most=limits.MAX_OVERLAP_PAIRS)
        )
    # Neighbours meet at a join the outline draws.
    neighbours = (s.next[first] == second) | (s.next[second] == first)
    first, second = first[~neighbours], second[~neighbours]
    # Along one subpath, a path turning less than TURNING_LIMIT cannot come back.
    keep = _turning_between(s, first, second) >= TURNING_LIMIT
    first, second = first[keep], second[keep]
    # Segments whose middles lie farther apart than their half lengths and
    # the reach cannot be that close: a cheap test before the exact one.
    middle = 0.5 * (s.start + s.end)
    apart = np.hypot(*(middle[first] - middle[second]).T)
    keep = apart - 0.5 * (s.length[first] + s.length[second]) <= 2 * half * (1 + 1e-9)
    first, second = first[keep], second[keep]
    close = _segment_gap(s.start[first], s.end[first], s.start[second], s.end[second])
    keep = close <= 2 * half * (1 + 1e-9)
    doubtful[first[keep]] = doubtful[second[keep]] = True
    return doubtful


def crowded_dots(segments: Segments, half: float) -> np.ndarray:
    """Isolated points within 2 half of another point or of a segment."""
    s = segments
    crowded = np.zeros(len(s.dots), dtype=bool)
    if len(s.dots) == 0:
        return crowded
    tree = cKDTree(s.dots)
    pairs = tree.query_pairs(2 * half * (1 + 1e-9), output_type="ndarray")
    crowded[pairs.ravel()] = True
    if len(s.length):
        # Pieces of the segments no longer than 2: their middles lie within
        # 2 half + 1 of a point the segment passes within 2 half of.
        owner, middle = _pieces(s.start, s.end, 2.0)
        # Every point near a piece, not only the nearest: a segment can have
        # one point close by and another just within 2 half farther along.
        near = tree.query_ball_point(middle, 2 * half + 1.0 + 1e-9, return_sorted=False)
        counts = np.fromiter(map(len, near), dtype=np.int64, count=len(near))
        dot = np.fromiter(itertools.chain.from_iterable(near), dtype=np.int64, count=counts.sum())
        segment = np.repeat(owner, counts)
        gap = distance_to(s.dots[dot], s.start[segment], s.end[segment])
        crowded[dot[gap <= 2 * half * (1 + 1e-9)]] = True
    return crowded


def _pieces(start: np.ndarray, end: np.ndarray, piece: float) -> tuple[np.ndarray, np.ndarray]:
    """Segments cut into pieces no longer than ``piece``: each piece's owner and middle."""
    pieces = np.maximum(np.ceil(np.hypot(*(end - start).T) / piece), 1).astype(np.int64)
    owner = np.repeat(np.arange(len(pieces)), pieces)
    step = np.arange(len(owner)) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    fraction = ((step + 0.5) / pieces[owner])[:, None]
    return owner, start[owner] + fraction * (end[owner] - start[owner])


def _candidate_pairs(s: Segments, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (i, j), i != j, that include every pair of segments ``reach`` apart or less.

    Segments are cut into pieces no longer than p; two segments within reach
    have pieces whose middles lie within ``reach + p``. A k-d tree of the
    middles finds those (scipy's, compiled: a glyph's thousand pieces cost
    a fraction of a millisecond). Pairs may repeat.
    """
    piece = max(reach, 2.0)
    owner, middle = _pieces(s.start, s.end, piece)
    pairs = cKDTree(middle).query_pairs(reach + piece, output_type="ndarray")
    first, second = owner[pairs[:, 0]], owner[pairs[:, 1]]
    different = first != second
    return first[different], second[different]


def _turning_between(s: Segments, first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """Total |turn| of the path between two segments of one subpath (inf otherwise)."""
    count = len(s.length)
    turn = np.zeros(count)
    joined = np.flatnonzero(s.next >= 0)
    later = s.next[joined]
    cross = s.unit[joined, 0] * s.unit[later, 1] - s.unit[joined, 1] * s.unit[later, 0]
    dot = np.einsum("ij,ij->i", s.unit[joined], s.unit[later])
    turn[later] = np.abs(np.arctan2(cross, dot))  # the turn into each segment
    # Cumulative turning along each subpath, from its first segment in storage order.
    head = np.r_[True, s.subpath[1:] != s.subpath[:-1]]
    total = np.cumsum(np.where(head, 0.0, turn))
    base = total[np.flatnonzero(head)][s.subpath]
    along = total - base
    low, high = np.minimum(first, second), np.maximum(first, second)
    between = along[high] - along[low]
    # A closed subpath can also be walked the other way round.
    closing = s.prev[np.flatnonzero(head)][s.subpath]  # last segment, joined to the first
    closed = closing >= 0
    first_turn = turn[np.flatnonzero(head)][s.subpath]  # the closing join's turn
    whole = np.where(closed, along[np.maximum(closing, 0)] + first_turn, np.inf)
    between = np.where(closed[low], np.minimum(between, whole[low] - between), between)
    return np.where(s.subpath[first] == s.subpath[second], between, np.inf)


def distance_to(points: np.ndarray, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """Distance from each point to its segment."""
    direction = end - start
    length2 = np.einsum("ij,ij->i", direction, direction)
    offset = points - start
    along = np.clip(np.einsum("ij,ij->i", offset, direction) / np.maximum(length2, 1e-300), 0, 1)
    return np.hypot(*(offset - along[:, None] * direction).T)


def _segment_gap(a0: np.ndarray, a1: np.ndarray, b0: np.ndarray, b1: np.ndarray) -> np.ndarray:
    """Distance between segments a0-a1 and b0-b1, elementwise (0 where they cross)."""
    gap = np.minimum.reduce(
        [
            distance_to(a0, b0, b1),
            distance_to(a1, b0, b1),
            distance_to(b0, a0, a1),
            distance_to(b1, a0, a1),
        ]
    )

    def side(p: np.ndarray, q0: np.ndarray, q1: np.ndarray) -> np.ndarray:
        d, e = q1 - q0, p - q0
        return d[:, 0] * e[:, 1] - d[:, 1] * e[:, 0]

    crossing = (side(a0, b0, b1) * side(a1, b0, b1) < 0) & (side(b0, a0, a1) * side(b1, a0, a1) < 0)
    return np.where(crossing, 0.0, gap)


# --- integration where parts overlap ---------------------------------------------


def integrate(
    image: np.ndarray, s: Segments, doubtful: np.ndarray, dots: np.ndarray, half: float
) -> None:
    """Overwrite the pixels near doubtful segments and dots with their coverage, in place.

    Every segment that reaches such a pixel takes part (not only the
    doubtful ones), and so do isolated points: the coverage is of the whole
    stroke.
    """
    reach = half + HALF_DIAGONAL
    line, gaps = _soup(
        np.concatenate([s.start[doubtful], s.dots[dots]]),
        np.concatenate([s.end[doubtful], s.dots[dots]]),
    )
    near = pixels_near(line, image.shape, reach, gaps=gaps)
    if len(near.flat) == 0:  # all off the canvas
        return
    flagged = np.zeros(image.size, dtype=bool)
    flagged[near.flat] = True
    # Every segment (and dot) that can reach them: a piece of it (no longer
    # than 2) has its middle within reach + 1 of a flagged pixel's centre.
    rows, columns = np.divmod(np.flatnonzero(flagged), image.shape[1])
    centres = np.stack([columns + 0.5, rows + 0.5], axis=1)
    starts = np.concatenate([s.start, s.dots])
    ends = np.concatenate([s.end, s.dots])
    owner, middle = _pieces(starts, ends, 2.0)
    distance, _ = cKDTree(centres).query(middle, distance_upper_bound=reach + 1.0 + 1e-9)
    nearby = np.zeros(len(starts), dtype=bool)
    nearby[owner[np.isfinite(distance)]] = True
    line, gaps = _soup(starts[nearby], ends[nearby])
    near = pixels_near(line, image.shape, reach, gaps=gaps)
    pick = np.flatnonzero(flagged[near.flat])
    flat, segment, split = near.flat[pick], near.segment[pick], near.polyline
    coverage = row_coverage(
        near.x[pick], near.y[pick], split[segment], split[segment + 1], flat, half, ROWS
    )
    # np.put indexes the flattened image in place, whatever its strides.
    np.put(image, np.flatnonzero(flagged), 0.0)
    np.put(image, flat[first_of_runs(flat)], coverage)


def row_coverage(
    x: np.ndarray,
    y: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    pixel: np.ndarray,
    half: float,
    rows: int,
) -> np.ndarray:
    """Area of each pixel within ``half`` of any of its segments, row by row.

    One entry per (pixel, segment) pair, grouped by ``pixel`` (equal values
    adjacent). For each of ``rows`` horizontal lines through the pixel, at
    ``y + (j + 0.5) / rows``, the points of the line within ``half`` of a
    segment form an interval (a stadium is convex): the rectangle's and the
    two end discs' intervals, merged. The pixel's intervals are merged along
    the line and their length inside the pixel measured exactly; the
    coverage is the mean over the rows. Exact in x, the midpoint rule in y:
    the error is of order ``1 / rows**2`` except where an edge of the stroke
    runs horizontally inside the pixel (up to ``1 / (2 rows)`` there).

    Returns
    -------
    ndarray, one coverage per group of ``pixel``, in order.

    Examples
    --------
    Two discs of radius 1/2 around (0.5, 0.5) and (1.0, 0.5) (two points):
    pixel (0, 0) holds the first, pi / 4, and the left half of the second,
    pi / 8, less their lens-shaped overlap, pi / 6 - sqrt(3) / 8:

    >>> point = np.array([[0.5, 0.5], [1.0, 0.5]])
    >>> covered = row_coverage(np.zeros(2), np.zeros(2), point, point, np.zeros(2), 0.5, 400)
    >>> round(float(covered[0]), 3), round(float(np.pi * 5 / 24 + np.sqrt(3) / 8), 3)
    (0.871, 0.871)
    """
    j = (np.arange(rows) + 0.5) / rows
    line_y = y[:, None] + j[None, :]  # (pairs, rows)
    lo = np.full(line_y.shape, np.inf)
    hi = np.full(line_y.shape, -np.inf)
    for point in (start, end):  # the end discs
        dy = line_y - point[:, 1, None]
        r2 = half * half - dy * dy
        inside = r2 >= 0
        r = np.sqrt(np.where(inside, r2, 0.0))
        lo = np.where(inside, np.minimum(lo, point[:, 0, None] - r), lo)
        hi = np.where(inside, np.maximum(hi, point[:, 0, None] + r), hi)
    # The rectangle: 0 <= (p - a) . u <= L and |(p - a) . n| <= half, n = (-u_y, u_x).
    direction = end - start
    length = np.hypot(*direction.T)
    safe = np.where(length > 0, length, 1.0)
    ux, uy = (direction[:, 0] / safe)[:, None], (direction[:, 1] / safe)[:, None]
    ax, ay = start[:, 0, None], start[:, 1, None]
    # Each condition is c x + d in [low, high]; x is p's, and d the rest.
    along = _slab(ux, (line_y - ay) * uy - ax * ux, 0.0, length[:, None])
    across = _slab(-uy, (line_y - ay) * ux + ax * uy, -half, half)
    rect_lo, rect_hi = np.maximum(along[0], across[0]), np.minimum(along[1], across[1])
    has = (length[:, None] > 0) & (rect_hi >= rect_lo)
    lo = np.where(has, np.minimum(lo, rect_lo), lo)
    hi = np.where(has, np.maximum(hi, rect_hi), hi)
    # Inside the pixel, from its left side; an empty interval becomes (0, 0).
    lo = np.clip(lo - x[:, None], 0.0, 1.0)
    hi = np.clip(hi - x[:, None], 0.0, 1.0)
    empty = hi <= lo
    lo[empty] = hi[empty] = 0.0
    # Merge each (pixel, row)'s intervals: sort by start, then a running
    # maximum of the ends. Groups are 4 apart, so one running maximum serves all.
    group = np.cumsum(first_of_runs(pixel)) - 1
    key = (group[:, None] * rows + np.arange(rows)[None, :]).T.ravel() * 4.0
    lo, hi = key + lo.T.ravel(), key + hi.T.ravel()
    order = np.argsort(lo)  # by group, then by start: the groups are 4 apart
    lo, hi, key = lo[order], hi[order], key[order]
    reach = np.maximum.accumulate(hi)
    before = np.concatenate([[-np.inf], reach[:-1]])
    covered = np.maximum(hi - np.maximum(lo, before), 0.0)
    total = np.bincount((key / 4.0).astype(np.int64) // rows, covered, group[-1] + 1)
    return total / rows


def _slab(
    c: np.ndarray, d: np.ndarray, low: float | np.ndarray, high: float | np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The x with ``low <= c x + d <= high``: (lo, hi), empty when hi < lo."""
    flat = np.abs(c) < 1e-12
    safe = np.where(flat, 1.0, c)
    a, b = (low - d) / safe, (high - d) / safe
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    inside = (d >= low) & (d <= high)
    lo = np.where(flat, np.where(inside, -np.inf, np.inf), lo)
    hi = np.where(flat, np.where(inside, np.inf, -np.inf), hi)
    return lo, hi


def _soup(starts: np.ndarray, ends: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Separate segments as one polyline whose odd segments are gaps."""
    line = np.empty((2 * len(starts), 2))
    line[0::2], line[1::2] = starts, ends
    gaps = np.zeros(max(len(line) - 1, 0), dtype=bool)
    gaps[1::2] = True
    return line, gaps
