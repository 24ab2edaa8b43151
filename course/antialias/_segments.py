"""The drawn segments of a flattened path: directions, neighbours, subpaths, dots.

A path flattened is one polyline and a boolean per segment, True for the
*gaps* (the pen moving between subpaths, :mod:`course.curves.paths`). The stroke's
outline (:mod:`course.antialias.stroke`) and the search for overlaps
(:mod:`course.antialias._overlaps`) both work on the drawn segments, with each one's
neighbours along the path.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["SHORT", "Segments", "segments"]

#: Segments shorter than this are points; their neighbours meet directly.
SHORT = 1e-9


@dataclass(frozen=True)
class Segments:
    """The drawn segments of a polyline, their neighbours and directions."""

    start: np.ndarray
    end: np.ndarray
    length: np.ndarray
    unit: np.ndarray
    normal: np.ndarray  # the unit turned by +90 degrees: side 0 is +normal, side 1 -normal
    next: np.ndarray  # the segment joined at the end, -1 for an open end
    prev: np.ndarray
    subpath: np.ndarray
    dots: np.ndarray  # isolated points: subpaths of zero length
    # The join into each segment from ``prev`` (0, 1 and 0 where there is none):
    cross: np.ndarray  # prev's unit x this one's: > 0 turning towards side 0
    dot: np.ndarray  # prev's unit . this one's
    turn: np.ndarray  # the signed angle turned, arctan2(cross, dot)


def segments(polyline: np.ndarray, gaps: np.ndarray) -> Segments:
    """The drawn segments of a polyline with gaps, without segments shorter than ``SHORT``.

    A segment shorter than ``SHORT`` is dropped and its neighbours meet
    directly; a subpath that ends where it starts is closed; vertices that
    no drawn segment touches are isolated points (``dots``).
    """
    line, gaps = polyline, gaps
    for _ in range(3):  # removing a point can, rarely, leave another short segment
        step = np.diff(line, axis=0)
        length = np.hypot(step[:, 0], step[:, 1])
        short = ~gaps & (length <= SHORT)
        if not short.any():
            break
        keep = np.concatenate([[True], ~short])
        kept = np.flatnonzero(keep)
        gaps = gaps[kept[1:] - 1]
        line = line.compress(keep, 0)
    else:  # the last removal left the steps stale
        step = np.diff(line, axis=0)
        length = np.hypot(step[:, 0], step[:, 1])
    drawn = np.flatnonzero(~gaps)
    start, end = line.take(drawn, 0), line.take(drawn + 1, 0)
    direction, length = step.take(drawn, 0), length[drawn]  # end - start, exactly
    unit = direction / length[:, None]
    normal = np.empty_like(unit)
    normal[:, 0], normal[:, 1] = -unit[:, 1], unit[:, 0]
    count = len(drawn)
    joined = np.diff(drawn) == 1
    following = np.full(count, -1)
    following[:-1][joined] = np.arange(1, count)[joined]
    previous = np.full(count, -1)
    previous[1:][joined] = np.arange(count - 1)[joined]
    subpath = np.cumsum(previous < 0) - 1
    # A subpath that ends where it starts is closed: its two ends are joined.
    first, last = np.flatnonzero(previous < 0), np.flatnonzero(following < 0)
    apart = start.take(first, 0) - end.take(last, 0)
    closed = (last > first) & (np.hypot(apart[:, 0], apart[:, 1]) <= SHORT)
    following[last[closed]], previous[first[closed]] = first[closed], last[closed]
    touched = np.zeros(len(line), dtype=bool)
    touched[drawn] = touched[drawn + 1] = True
    dots = line.compress(~touched, 0)
    # The joins, computed once for the outline and the search for overlaps.
    before = np.where(previous >= 0, previous, np.arange(count))
    ux, uy = unit[:, 0], unit[:, 1]
    bx, by = ux.take(before), uy.take(before)
    cross = np.where(previous >= 0, bx * uy - by * ux, 0.0)
    dot = np.where(previous >= 0, bx * ux + by * uy, 1.0)
    turn = np.arctan2(cross, dot)
    return Segments(
        start, end, length, unit, normal, following, previous, subpath, dots, cross, dot, turn
    )
