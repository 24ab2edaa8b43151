"""The exact stroke of a polyline: its outline, filled by signed area.

The stroke of width w = 2 h around a polyline is the union of the *stadiums*
of its segments (the points within h of a segment: a rectangle and two half
discs), so its joins and caps are round. Its coverage of a pixel is the area
of the pixel inside that union. This module computes it in three steps:

1. **The outline.** On each side of every segment runs an offset edge at
   distance h. Where two segments meet, the side the path turns away from
   (the outer side) gets a circular arc around the vertex (chords every
   ``ARC_STEP``; joins turning less than ``MITER_TURN`` are mitred, within
   ``h^2 MITER_TURN^3 / 24`` of the arc's area); on the side it turns
   towards (the inner side) the two offset edges are cut where they cross.
   When that cut would use up a whole short segment (a sharp corner next to
   a finely flattened curve), the offset edges that it consumes are dropped
   and the neighbours' edges are cut where *they* cross, the boundary of
   the union. Open ends get half circles, isolated points whole circles.
2. **Signed area.** The outline is filled by :func:`course.antialias._fill.accumulate`:
   each pixel gets its exact area inside (up to the chords of the arcs).
3. **Where the outline is not the boundary.** Parts of the path that come
   within w of each other without being neighbours along it (a loop, two
   subpaths, a hairpin), and corners the cutting of step 1 cannot settle (a
   cusp, whose offset edges never cross), are found and the pixels near them
   are integrated directly (:mod:`course.antialias._overlaps` finds them,
   :mod:`course.antialias._integrate` integrates them).

Unchecked kernels: like dhermes/bezier's ``hazmat``, this module trusts its
caller and checks no input (``UNCHECKED = True``, which the fuzz test reads).
Its public callers (:mod:`course.antialias`, :mod:`course.antialias.coverage`) validate
once, at their boundary.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from course.antialias._fill import accumulate
from course.antialias._integrate import integrate
from course.antialias._overlaps import crowded_dots, distance_to, overlapping
from course.antialias._segments import Segments
from course.antialias._segments import segments as as_segments

__all__ = ["ARC_STEP", "MITER_TURN", "stroke_coverage"]

UNCHECKED = True  # kernels for checked callers; see the module docstring

#: Largest angle one chord of a round join or cap spans: the chord is at most
#: ``h (1 - cos(ARC_STEP / 2))`` inside the circle (0.00015 px for w = 1).
ARC_STEP = np.pi / 64
#: Outer joins turning less than this (radians) are mitred instead of rounded,
#: within ``h^2 MITER_TURN^3 / 24`` of the arc's area (1e-5 px^2 for w = 1).
MITER_TURN = 0.15
# Offset edges cut by at most this many rounds of consumption; beyond, integrate.
_CUT_ROUNDS = 4


def stroke_coverage(
    polyline: np.ndarray, gaps: np.ndarray, half: float, shape: tuple[int, int]
) -> np.ndarray:
    """Coverage of each pixel of the canvas by the points within ``half`` of the path.

    The unchecked core of :func:`course.antialias.stroke_area`.

    Parameters
    ----------
    polyline : ndarray (K, 2), K >= 2
        In canvas coordinates (x right, y down).
    gaps : bool ndarray (K - 1,)
        The segments that are not drawn (the pen moving between subpaths).
    half : float
        Half the stroke's width, > 0.
    shape : (H, W)

    Returns
    -------
    ndarray (H, W), a new array of coverage in [0, 1].

    Examples
    --------
    A sharp turn back: pixel (7, 1), just past the corner, stays empty (a
    mitred join would fill it); the round join puts half a disc of radius
    1/2 in pixel (6, 1), pi / 8 = 0.3927 (0.395: the pixels around so sharp
    a turn are integrated row by row, to within 1/32).

    >>> line = np.array([[1.0, 1.5], [6.0, 1.5], [1.0, 2.5]])
    >>> stroke_coverage(line, np.zeros(2, dtype=bool), 0.5, (4, 8))[1, 5:].round(3)
    array([1.   , 0.395, 0.   ])
    """
    segments = as_segments(polyline, gaps)
    starts, ends, arcs, doubtful = _outline(segments, half)
    image = accumulate(starts, ends, shape, clip=True, chains=arcs)
    doubtful |= overlapping(segments, half)
    dots = crowded_dots(segments, half)
    if doubtful.any() or dots.any():
        integrate(image, segments, doubtful, dots, half)  # values in [0, 1] already
    return image


# --- the outline ---------------------------------------------------------------


def _outline(
    segments: Segments, half: float
) -> tuple[np.ndarray, np.ndarray, tuple[np.ndarray, np.ndarray], np.ndarray]:
    """The outline's edges and arcs, and the segments it cannot settle.

    The straight edges come as start and end points, the arcs as polylines
    (their points and True at each one's last point, as
    :func:`course.antialias._fill.accumulate` takes them).

    The offset edges are indexed flat, ``2 * segment + side``, so that both
    sides are cut and linked in one pass.
    """
    s = segments
    count = len(s.length)
    first = np.flatnonzero(s.next >= 0)  # joins: segment `first` into segment `second`
    second = s.next[first]
    cross, dot, turn = s.cross.take(second), s.dot.take(second), s.turn.take(second)
    inner = (cross <= 0).astype(np.int64)  # the side the path turns towards
    cusp = 1.0 + dot <= 1e-12
    trim = half * np.abs(cross) / np.where(cusp, 1.0, 1.0 + dot)
    # Where each offset edge begins and ends, as distances along its segment.
    begin = np.zeros(2 * count)
    finish = np.repeat(s.length, 2)
    begin[2 * second + inner] = trim
    finish[2 * first + inner] -= trim
    gentle = np.flatnonzero(np.abs(turn) <= MITER_TURN)
    begin[2 * second[gentle] + 1 - inner[gentle]] = -trim[gentle]
    finish[2 * first[gentle] + 1 - inner[gentle]] += trim[gentle]
    join_of_end = np.full(count, -1)
    join_of_end[first] = np.arange(len(first))
    join_of_start = np.full(count, -1)
    join_of_start[second] = np.arange(len(second))
    through = cusp.copy()  # joins whose inner side runs through the vertex
    joins = _Joins(first, second, inner, turn, join_of_end, join_of_start, _sided(s.next), through)
    if cusp.any():
        _through(s, joins, np.flatnonzero(cusp), begin, finish)
    consumed, doubtful = _cut(s, half, begin, finish, joins)
    doubtful[first[through]] = doubtful[second[through]] = True
    # Side 0 is offset by +half normal, side 1 by -half normal.
    offset = np.empty((count, 2, 2))
    offset[:, 0] = half * s.normal
    offset[:, 1] = -offset[:, 0]
    along = s.unit[:, None, :]
    a = (s.start[:, None, :] + offset + begin.reshape(count, 2, 1) * along).reshape(-1, 2)
    b = (s.start[:, None, :] + offset + finish.reshape(count, 2, 1) * along).reshape(-1, 2)
    rounded = np.abs(turn) > MITER_TURN
    rounded &= ~cusp
    link_starts, link_ends, arc = _links(s, joins, a, b, consumed, rounded, doubtful)
    open_end = np.flatnonzero(s.next < 0)
    open_start = np.flatnonzero(s.prev < 0)
    # Every arc of the outline in one batch of chords: the outer sides of
    # round joins, then open ends, open starts and dots (a closed path has
    # no ends, and few paths have dots).
    arcs = [arc]
    if len(open_end):
        arcs.append(
            (s.end.take(open_end, 0), s.normal.take(open_end, 0), np.full(len(open_end), -np.pi))
        )
        arcs.append(
            (
                s.start.take(open_start, 0),
                -s.normal.take(open_start, 0),
                np.full(len(open_start), -np.pi),
            )
        )
    if len(s.dots):
        arcs.append(
            (s.dots, np.tile([1.0, 0.0], (len(s.dots), 1)), np.full(len(s.dots), -2 * np.pi))
        )
    centre, normal, sweep = (np.concatenate(part) for part in zip(*arcs, strict=True))
    arc_points = _arc(centre, normal, sweep, half)
    drawn = ~consumed
    side_0, side_1 = drawn[0::2], drawn[1::2]
    starts = [a[0::2].compress(side_0, 0), b[1::2].compress(side_1, 0), link_starts]
    ends = [b[0::2].compress(side_0, 0), a[1::2].compress(side_1, 0), link_ends]
    return np.concatenate(starts), np.concatenate(ends), arc_points, doubtful


def _links(
    s: Segments,
    joins: _Joins,
    a: np.ndarray,
    b: np.ndarray,
    consumed: np.ndarray,
    rounded: np.ndarray,
    doubtful: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, tuple[np.ndarray, ...]]:
    """What joins each offset edge to the next one that is drawn on its side.

    Usually nothing (a mitre or a cut: the edges meet), an arc around the
    vertex (the outer side of a round join) or two edges through the vertex.
    Anything else is a join the cutting left inconsistent: a straight
    connector keeps the outline closed and its segments are marked doubtful.
    Returns the straight edges' starts and ends, and the arcs (centre, normal,
    sweep) for :func:`_arc`, drawn with all the others at once.
    """
    drawn = np.flatnonzero(~consumed)
    following = _walk(joins.following, consumed, drawn)
    linked = following >= 0
    p, q = drawn[linked], following[linked]  # flat: 2 * segment + side
    side = p & 1
    p_segment, q_segment = p >> 1, q >> 1
    there, here = b.take(p, 0), a.take(q, 0)  # p's edge ends, q's begins
    join = joins.join_of_end[p_segment]
    single = s.next[p_segment] == q_segment
    on_inner = joins.inner[join] == side
    arc = single & rounded[join] & ~on_inner
    via = single & joins.through[join] & on_inner
    # max(|x|, |y|) by columns: numpy's reduction over an axis of two is slow.
    scale = 1e-9 * np.maximum(1.0, np.maximum(np.abs(there[:, 0]), np.abs(there[:, 1])))
    gap = there - here
    apart = ~arc & ~via & (gap[:, 0] * gap[:, 0] + gap[:, 1] * gap[:, 1] > scale * scale)
    doubtful[p_segment[apart]] = doubtful[q_segment[apart]] = True
    vertex = s.end.take(p_segment, 0)
    first = np.concatenate(
        [there.compress(via, 0), vertex.compress(via, 0), there.compress(apart, 0)]
    )
    second = np.concatenate(
        [vertex.compress(via, 0), here.compress(via, 0), here.compress(apart, 0)]
    )
    # Side 1 runs backwards: its edges go from q's edge to p's.
    back = (np.concatenate([side[via], side[via], side[apart]]) == 1)[:, None]
    starts, ends = np.where(back, second, first), np.where(back, first, second)
    # The outer side of a round join: an arc from the end of p's edge to q's.
    side, p_segment, q_segment = side[arc], p_segment[arc], q_segment[arc]
    normal = np.where(
        (side == 0)[:, None], s.normal.take(p_segment, 0), -s.normal.take(q_segment, 0)
    )
    sweep = joins.turn[join[arc]] * (1.0 - 2.0 * side)
    return starts, ends, (vertex.compress(arc, 0), normal, sweep)


def _cut(
    s: Segments, half: float, begin: np.ndarray, finish: np.ndarray, joins: _Joins
) -> tuple[np.ndarray, np.ndarray]:
    """Drop the inner offset edges a sharp turn consumes; cut their neighbours instead.

    ``begin`` and ``finish`` (flat, ``2 * segment + side``) are updated in
    place. Returns which offset edges are consumed (flat) and which segments
    the cutting could not settle (their joins then run through the vertex
    and ``through`` is set). Both sides are cut at once: a side's cuts never
    read the other's.
    """
    count = len(s.length)
    consumed = np.zeros(2 * count, dtype=bool)
    unsettled = np.zeros(count, dtype=bool)
    inner, turn = joins.inner, joins.turn
    join_of_start, join_of_end = joins.join_of_start, joins.join_of_end
    preceding = None
    for _ in range(_CUT_ROUNDS):
        short = (begin > finish + 1e-12) & ~consumed
        if not short.any():
            return consumed, unsettled
        if preceding is None:
            preceding = _sided(s.prev)
        consumed |= short
        run = np.flatnonzero(consumed)
        segment, side = run >> 1, run & 1
        before = _walk(preceding, consumed, run)
        after = _walk(joins.following, consumed, run)
        # Each run of consumed edges between `before` and `after`, once.
        ends_run = (before >= 0) & (after >= 0)
        key = np.where(ends_run, before, -1 - run)
        keys, which = np.unique(key, return_inverse=True)
        p = np.full(len(keys), -1)
        q = np.full(len(keys), -1)
        p[which], q[which] = before, after
        key_side = np.zeros(len(keys), dtype=np.int64)
        key_side[which] = side
        # The path must turn towards `side` at every join of the run, by
        # less than half a turn in all, and the offset lines must cross.
        start_join, end_join = join_of_start[segment], join_of_end[segment]
        convex = (
            (start_join >= 0)
            & (end_join >= 0)
            & (inner[np.maximum(start_join, 0)] == side)
            & (inner[np.maximum(end_join, 0)] == side)
        )
        p_segment, q_segment = np.maximum(p, 0) >> 1, np.maximum(q, 0) >> 1
        total = np.bincount(which, np.abs(turn[np.maximum(start_join, 0)]), len(keys))
        total += np.abs(turn[np.maximum(join_of_start[q_segment], 0)])
        ok = (keys >= 0) & (np.bincount(which, ~convex, len(keys)) == 0)
        ok &= total < np.pi - 1e-6
        reach = ((1.0 - 2.0 * key_side) * half)[:, None]
        up, uq = s.unit.take(p_segment, 0), s.unit.take(q_segment, 0)
        op = s.start.take(p_segment, 0) + reach * s.normal.take(p_segment, 0)
        oq = s.start.take(q_segment, 0) + reach * s.normal.take(q_segment, 0)
        denominator = up[:, 0] * uq[:, 1] - up[:, 1] * uq[:, 0]
        ok &= np.abs(denominator) > 1e-12
        safe = np.where(ok, denominator, 1.0)
        gap = oq - op
        along_p = (gap[:, 0] * uq[:, 1] - gap[:, 1] * uq[:, 0]) / safe
        along_q = (gap[:, 0] * up[:, 1] - gap[:, 1] * up[:, 0]) / safe
        crossing = op + along_p[:, None] * up
        # The crossing must lie outside every consumed segment's stadium.
        clear = distance_to(
            crossing.take(which, 0), s.start.take(segment, 0), s.end.take(segment, 0)
        )
        ok &= np.bincount(which, clear < half * (1 - 1e-9), len(keys)) == 0
        good = np.flatnonzero(ok)
        finish[p[good]] = along_p[good]
        begin[q[good]] = along_q[good]
        bad_runs = ~ok[which]
        if bad_runs.any():
            members, member_side = segment[bad_runs], side[bad_runs]
            ends_of = np.concatenate([join_of_start[members], join_of_end[members]])
            ends_side = np.concatenate([member_side, member_side])
            inside = ends_of >= 0
            ends_of, ends_side = ends_of[inside], ends_side[inside]
            _through(s, joins, ends_of[inner[ends_of] == ends_side], begin, finish)
            unsettled[members] = True
            bad_p, bad_q = p[~ok], q[~ok]
            unsettled[bad_p[bad_p >= 0] >> 1] = True
            unsettled[bad_q[bad_q >= 0] >> 1] = True
            consumed[run[bad_runs]] = False
    # Still inconsistent after the rounds: settle by sampling.
    left = np.flatnonzero(((begin > finish + 1e-12) & ~consumed).reshape(-1, 2).any(axis=1))
    ends_of = np.concatenate([join_of_start[left], join_of_end[left]])
    _through(s, joins, ends_of[ends_of >= 0], begin, finish)
    unsettled[left] = True
    return consumed, unsettled


@dataclass(frozen=True)
class _Joins:
    """Where segment ``first[j]`` meets ``second[j]``: the turn and its inner side."""

    first: np.ndarray
    second: np.ndarray
    inner: np.ndarray
    turn: np.ndarray
    join_of_end: np.ndarray  # per segment, the join at its end (-1: none)
    join_of_start: np.ndarray
    following: np.ndarray  # per offset edge (flat), the same side of the next segment
    through: np.ndarray  # the inner side runs through the vertex (set as found)


def _sided(step: np.ndarray) -> np.ndarray:
    """``step`` (a neighbour per segment, -1: none) per offset edge, flat: the same side."""
    sided = np.empty(2 * len(step), dtype=np.int64)
    sided[0::2] = np.where(step >= 0, 2 * step, -1)
    sided[1::2] = np.where(step >= 0, 2 * step + 1, -1)
    return sided


def _through(
    s: Segments, joins: _Joins, which: np.ndarray, begin: np.ndarray, finish: np.ndarray
) -> None:
    """Joins ``which`` draw their inner side through the vertex: both rectangles whole.

    The two rectangles then overlap near the vertex, which the sampling settles.
    """
    joins.through[which] = True
    side = joins.inner[which]
    before, after = joins.first[which], joins.second[which]
    finish[2 * before + side] = s.length[before]
    begin[2 * after + side] = 0.0


def _walk(step: np.ndarray, consumed: np.ndarray, index: np.ndarray) -> np.ndarray:
    """From each index, follow ``step`` to the first segment not consumed (-1: none)."""
    at = step[index]
    # Only the indices still on a consumed edge move on: few, and fewer each step.
    going = np.flatnonzero((at >= 0) & consumed[np.maximum(at, 0)] & (at != index))
    for _ in range(len(consumed)):
        if len(going) == 0:
            break
        moved = step[at[going]]
        at[going] = moved
        going = going[(moved >= 0) & consumed[np.maximum(moved, 0)] & (moved != index[going])]
    return np.where(at == index, -1, at)


def _arc(
    centre: np.ndarray, normal: np.ndarray, sweep: np.ndarray, half: float
) -> tuple[np.ndarray, np.ndarray]:
    """The arcs from ``centre + half * normal`` turning by ``sweep`` radians, as polylines.

    Returns their points, arc after arc, and True at each arc's last point:
    chords no longer than ``ARC_STEP`` radians, each point computed once, so
    a chord ends exactly where the next begins.
    """
    count = np.maximum(np.ceil(np.abs(sweep) / ARC_STEP), 1).astype(np.int64)
    arc = np.repeat(np.arange(len(count)), count + 1)
    step = np.arange(len(arc)) - np.repeat(np.cumsum(count + 1) - (count + 1), count + 1)
    angles = step * (sweep / count)[arc]
    cos, sin = np.cos(angles), np.sin(angles)
    nx, ny = normal[:, 0].take(arc), normal[:, 1].take(arc)
    points = np.empty((len(arc), 2))
    points[:, 0] = centre[arc, 0] + half * (cos * nx - sin * ny)
    points[:, 1] = centre[arc, 1] + half * (sin * nx + cos * ny)
    return points, step == count[arc]
