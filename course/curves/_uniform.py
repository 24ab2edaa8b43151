"""Uniform t steps, and a path flattened in Wang's count of them, on checked input.

Kernels behind :func:`course.curves.flattening.uniform_parameters` (the handouts' steps,
:func:`uniform_steps`) and :func:`course.curves.drawable_paths.flatten_uniform` (every curve
of a :class:`~course.curves.paths.Curves` in uniform steps, :func:`uniform_polyline`), which
check their arguments before they call these; :mod:`course.antialias` draws its checked
paths with them. What flattening a path costs depends on its curves and the tolerance
together: :func:`uniform_polyline` checks it as it goes, curve degree after curve degree.

Unchecked kernels: this module trusts its callers and checks no input
(``UNCHECKED = True``, which the fuzz test reads).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course.curves._bezier_fast import de_casteljau_chunked
from course.i18n import _
from course.limits import require_bounded_evaluation

__all__ = ["assemble", "uniform_points", "uniform_polyline", "uniform_steps", "wang_segment_counts"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def uniform_steps(step: float, accumulate: str) -> np.ndarray:
    """The parameters t = 0, step, 2 step, ... <= 1 of a checked ``step`` and ``accumulate``.

    Examples
    --------
    >>> uniform_steps(0.25, "exact")
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    """
    if step > 1:
        return np.zeros(1)
    if accumulate == "exact":
        count = int(np.floor(1 / step * (1 + 1e-12)))
        return np.arange(count + 1) * step
    dtype = np.float32 if accumulate == "float32" else np.float64
    steps = np.full(int(np.ceil(1 / step)) + 2, step, dtype=dtype)
    # cumsum adds sequentially in the given dtype, exactly like the C++ loop.
    t = np.concatenate([np.zeros(1, dtype), np.cumsum(steps, dtype=dtype)])
    return t[t <= 1].astype(float)


def wang_segment_counts(control: np.ndarray, tolerance: float) -> np.ndarray:
    """Wang's segment count for each curve of a checked stack ``(M, N, 2)`` of equal degree."""
    degree = control.shape[1] - 1
    if degree < 2:
        return np.ones(len(control), dtype=np.int64)
    second = control[:, :-2] - 2 * control[:, 1:-1] + control[:, 2:]
    bound = degree * (degree - 1) * np.hypot(second[..., 0], second[..., 1]).max(axis=1)
    return np.maximum(1, np.ceil(np.sqrt(bound / (8 * tolerance)))).astype(np.int64)


def uniform_polyline(curves: Any, tolerance: float) -> tuple[np.ndarray, np.ndarray]:
    """:func:`course.curves.drawable_paths.flatten_uniform` of checked ``curves`` (Curves)
    and ``tolerance``: one polyline and its gaps."""
    counts = np.zeros(len(curves.sizes), dtype=np.int64)
    pieces: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    for size in np.unique(curves.sizes).tolist():
        which = np.flatnonzero(curves.sizes == size)
        control = curves.points.take(curves.starts[which][:, None] + np.arange(size), 0)
        count = (
            np.zeros(len(which), dtype=np.int64)
            if size == 1
            else wang_segment_counts(control, tolerance)
        )
        require_bounded_evaluation(size, int(count.sum()) + len(count), "curves")
        if count.sum() > limits.MAX_SAMPLES:
            raise ValueError(
                _(
                    "tolerance {tolerance:g} would need {total} vertices, more than the {most} "
                    "allowed: raise it"
                ).format(tolerance=tolerance, total=count.sum(), most=limits.MAX_SAMPLES)
            )
        counts[which] = count
        # A line's one step is its two control points, exactly as evaluated.
        points = control.reshape(-1, 2) if size <= 2 else uniform_points(control, count)
        pieces[size] = (which, points)
    return assemble(curves, counts + 1, pieces)


def uniform_points(control: np.ndarray, count: np.ndarray) -> np.ndarray:
    """The points at t = 0, 1/count, ..., 1 of each curve, one after another."""
    curve = np.repeat(np.arange(len(count)), count + 1)
    step = np.arange(len(curve)) - np.repeat(np.cumsum(count + 1) - count - 1, count + 1)
    t = (step / np.maximum(count, 1)[curve])[:, None]
    degree = control.shape[1] - 1
    if degree > 3:
        return np.concatenate(
            [
                de_casteljau_chunked(np.array(c, dtype=float), np.linspace(0.0, 1.0, n + 1))
                for c, n in zip(control, count, strict=True)
            ]
        )
    s = 1.0 - t
    # Only the degree's own Bernstein weights (a dict of all four built them all).
    if degree == 0:
        weights = [np.ones_like(t)]
    elif degree == 1:
        weights = [s, t]
    elif degree == 2:
        weights = [s * s, 2 * s * t, t * t]
    else:
        weights = [s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t]
    # control[:, i].take(curve, 0): a row gather, far cheaper than control[curve, i].
    points = sum(w * control[:, i].take(curve, 0) for i, w in enumerate(weights))
    # t = 0 and t = 1 give the end points themselves, so joins stay exact.
    ends = step == count[curve]
    starts = step == 0
    points[starts] = control[:, 0].take(curve[starts], 0)
    points[ends] = control[:, -1].take(curve[ends], 0)
    return points


def assemble(
    curves: Any, counts: np.ndarray, pieces: dict[int, tuple[np.ndarray, np.ndarray]]
) -> tuple[np.ndarray, np.ndarray]:
    """One polyline from each curve's points (given by groups), and its gap segments."""
    if len(counts) == 0:
        return np.zeros((0, 2)), np.zeros(0, dtype=bool)
    joined = curves.joined()
    kept = counts - joined  # a joined curve's first point is the previous curve's last
    offset = np.cumsum(kept) - kept
    line = np.empty((int(kept.sum()), 2))
    for which, points in pieces.values():
        count = counts[which]
        local = np.arange(len(points)) - np.repeat(np.cumsum(count) - count, count)
        curve = np.repeat(which, count)
        keep = local >= joined[curve].astype(np.int64)
        at = (offset[curve] + local - joined[curve])[keep]
        line[:, 0][at], line[:, 1][at] = points[:, 0][keep], points[:, 1][keep]
    gaps = np.zeros(max(len(line) - 1, 0), dtype=bool)
    new_subpath = np.flatnonzero(~joined[1:]) + 1
    gaps[offset[new_subpath] - 1] = True
    return line, gaps
