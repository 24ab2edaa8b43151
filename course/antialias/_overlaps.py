"""Where the outline of a stroke is not its boundary: the overlapping parts of the path.

The outline :mod:`course.antialias.stroke` draws is the boundary of the stroke where
the path does not come back on itself. Two parts of the path that come
within w of each other without being neighbours along it (a loop, two
subpaths, a hairpin) overlap, and the outline counts the overlap twice.
:func:`overlapping` finds those segments (pairs within w of each other,
except neighbours and pairs the path turns less than ``TURNING_LIMIT``
between), and :func:`crowded_dots` the isolated points near the rest;
:func:`course.antialias._integrate.integrate` recomputes the pixels near them.
"""

from __future__ import annotations

import itertools

import numpy as np
from scipy.spatial import cKDTree

from course import limits
from course.antialias._segments import Segments
from course.i18n import _

__all__ = ["TURNING_LIMIT", "crowded_dots", "distance_to", "overlapping", "pieces"]

#: A path that turns less than this between two segments cannot bring them
#: within w of each other except through the joins between them, which the
#: outline settles (a hairpin or a loop turns by half a turn or more).
TURNING_LIMIT = 0.75 * np.pi
# Up to this many (point, segment) pairs, crowded points are found by measuring all.
_BRUTE_PAIRS = 50_000


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
    # Neighbours meet at a join the outline draws; along one subpath, a path
    # turning less than TURNING_LIMIT cannot come back. Both tests read only
    # the path's structure, and they leave few pairs of the many.
    keep = (s.next[first] != second) & (s.next[second] != first)
    first, second = first[keep], second[keep]
    keep = _turning_between(s, first, second) >= TURNING_LIMIT
    first, second = first[keep], second[keep]
    # Segments whose middles lie farther apart than their half lengths and
    # the reach cannot be that close: a cheap test before the exact one.
    middle = 0.5 * (s.start + s.end)
    apart = middle.take(first, 0) - middle.take(second, 0)
    within = 2 * half * (1 + 1e-9) + 0.5 * (s.length[first] + s.length[second])
    keep = apart[:, 0] * apart[:, 0] + apart[:, 1] * apart[:, 1] <= within * within
    first, second = first[keep], second[keep]
    start, end = s.start.take(first, 0), s.end.take(first, 0)
    close = _segment_gap(start, end, s.start.take(second, 0), s.end.take(second, 0))
    keep = close <= 2 * half * (1 + 1e-9)
    doubtful[first[keep]] = doubtful[second[keep]] = True
    return doubtful


def crowded_dots(segments: Segments, half: float) -> np.ndarray:
    """Isolated points within 2 half of another point or of a segment."""
    s = segments
    crowded = np.zeros(len(s.dots), dtype=bool)
    if len(s.dots) == 0:
        return crowded
    if len(s.dots) > 1:
        pairs = cKDTree(s.dots).query_pairs(2 * half * (1 + 1e-9), output_type="ndarray")
        crowded[pairs.ravel()] = True
    if len(s.length) and len(s.dots) * len(s.length) <= _BRUTE_PAIRS:
        # Few points (a text has one or two, or none): every (point, segment)
        # pair measured, cheaper than the tree's per-point lists.
        dot = np.repeat(np.arange(len(s.dots)), len(s.length))
        segment = np.tile(np.arange(len(s.length)), len(s.dots))
        gap = distance_to(s.dots.take(dot, 0), s.start.take(segment, 0), s.end.take(segment, 0))
        crowded[dot[gap <= 2 * half * (1 + 1e-9)]] = True
    elif len(s.length):
        # Pieces of the segments no longer than 2: their middles lie within
        # 2 half + 1 of a point the segment passes within 2 half of.
        owner, middle = pieces(s.start, s.end, 2.0)
        # Every point near a piece, not only the nearest: a segment can have
        # one point close by and another just within 2 half farther along.
        near = cKDTree(s.dots).query_ball_point(middle, 2 * half + 1.0 + 1e-9, return_sorted=False)
        counts = np.fromiter(map(len, near), dtype=np.int64, count=len(near))
        dot = np.fromiter(itertools.chain.from_iterable(near), dtype=np.int64, count=counts.sum())
        segment = np.repeat(owner, counts)
        gap = distance_to(s.dots.take(dot, 0), s.start.take(segment, 0), s.end.take(segment, 0))
        crowded[dot[gap <= 2 * half * (1 + 1e-9)]] = True
    return crowded


def pieces(
    start: np.ndarray, end: np.ndarray, piece: float, length: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Segments cut into pieces no longer than ``piece``: each piece's owner and middle.

    ``length``, the segments' lengths if they are known already.
    """
    if length is None:
        length = np.hypot(*(end - start).T)
    pieces = np.maximum(np.ceil(length / piece), 1).astype(np.int64)
    owner = np.repeat(np.arange(len(pieces)), pieces)
    step = np.arange(len(owner)) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    fraction = ((step + 0.5) / pieces[owner])[:, None]
    first = start.take(owner, 0)
    return owner, first + fraction * (end.take(owner, 0) - first)


def _candidate_pairs(s: Segments, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (i, j), i != j, that include every pair of segments ``reach`` apart or less.

    Segments are cut into pieces no longer than p; two segments within reach
    have pieces whose middles lie within ``reach + p``. A k-d tree of the
    middles finds those (scipy's, compiled: a glyph's thousand pieces cost
    a fraction of a millisecond). Pairs may repeat.
    """
    piece = max(reach, 2.0)
    owner, middle = pieces(s.start, s.end, piece, s.length)
    # An unbalanced tree of loose nodes builds faster and finds the same pairs.
    tree = cKDTree(middle, balanced_tree=False, compact_nodes=False)
    pairs = tree.query_pairs(reach + piece, output_type="ndarray")
    first, second = owner[pairs[:, 0]], owner[pairs[:, 1]]
    different = first != second
    return first[different], second[different]


def _turning_between(s: Segments, first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """Total |turn| of the path between two segments of one subpath (inf otherwise)."""
    turn = np.abs(s.turn)  # the turn into each segment (0 at a subpath's start)
    # Cumulative turning along each subpath, from its first segment in storage order.
    head = np.concatenate([[True], s.subpath[1:] != s.subpath[:-1]])
    total = np.cumsum(np.where(head, 0.0, turn))
    heads = np.flatnonzero(head)
    along = total - total[heads][s.subpath]
    low, high = np.minimum(first, second), np.maximum(first, second)
    between = along[high] - along[low]
    # A closed subpath can also be walked the other way round.
    closing = s.prev[heads][s.subpath]  # last segment, joined to the first
    closed = closing >= 0
    first_turn = turn[heads][s.subpath]  # the closing join's turn
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
    # Each end to the other segment, the four measured in one call.
    ends = distance_to(
        np.concatenate([a0, a1, b0, b1]),
        np.concatenate([b0, b0, a0, a0]),
        np.concatenate([b1, b1, a1, a1]),
    )
    gap = ends.reshape(4, -1).min(axis=0)

    def side(p: np.ndarray, q0: np.ndarray, q1: np.ndarray) -> np.ndarray:
        d, e = q1 - q0, p - q0
        return d[:, 0] * e[:, 1] - d[:, 1] * e[:, 0]

    crossing = (side(a0, b0, b1) * side(a1, b0, b1) < 0) & (side(b0, a0, a1) * side(b1, a0, a1) < 0)
    return np.where(crossing, 0.0, gap)
