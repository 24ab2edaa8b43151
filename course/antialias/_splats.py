"""The handouts' splats on checked samples: what :mod:`course.antialias.splats` runs.

Nothing here checks its input (``UNCHECKED = True``): ``points`` is a finite float
``(M, 2)`` array of curve points within :data:`course.limits.MAX_COORDINATE`, as
:mod:`course.antialias.splats` makes sure before it calls :func:`splat_points`, which
gives every pixel each sample touches and its weight, before any clipping to a canvas.
:func:`course.antialias.render` splats the samples it made here too. Each splat is
explained, with the handout it comes from, where it is public, beside its one-sample
form.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

__all__ = [
    "SQRT2",
    "SUBSAMPLE_MAX_DISTANCE",
    "arc_length_weights",
    "splat_points",
]

UNCHECKED = True  # kernels for checked callers; see the module docstring

SQRT2 = math.sqrt(2.0)
# Seed 002's normaliser: the farthest a point can be from a sub-sample of its pixel.
SUBSAMPLE_MAX_DISTANCE = math.sqrt(1.125)


def _block(
    corner_x: np.ndarray, corner_y: np.ndarray, weights: list[np.ndarray], order: list[tuple]
) -> tuple[np.ndarray, np.ndarray]:
    """Stack per-sample pixel offsets (dx, dy) from a corner, sample by sample."""
    offsets = np.array(order, dtype=np.int64)
    x = corner_x.astype(np.int64)[:, None] + offsets[:, 0]
    y = corner_y.astype(np.int64)[:, None] + offsets[:, 1]
    pixels = np.stack([x.ravel(), y.ravel()], axis=1)
    return pixels, np.stack(weights, axis=1).ravel()


def _nearest_truncate(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    pixels = np.trunc(points).astype(np.int64)
    return pixels, np.ones(len(pixels))


def _nearest_round(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    pixels = np.rint(points).astype(np.int64)
    return pixels, np.ones(len(pixels))


def _bilinear_zero_offset(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    x, y = points[:, 0], points[:, 1]
    # Each corner is rounded on its own, as cv::Point(p2) etc. would.
    corners = [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)]
    pixels = np.stack([np.rint(np.stack(c, axis=1)) for c in corners], axis=1)
    dx, dy = x - x, y - y
    weights = np.stack([(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy], axis=1).ravel()
    return pixels.reshape(-1, 2).astype(np.int64), weights


def _bilinear_corners(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    corner = np.floor(points)
    dx, dy = (points - corner).T
    weights = [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]
    return _block(corner[:, 0], corner[:, 1], weights, [(0, 0), (1, 0), (0, 1), (1, 1)])


def _round_half_away(values: np.ndarray) -> np.ndarray:
    """C++ ``std::round``: halves away from zero (numpy's rint rounds them to even)."""
    return np.copysign(np.floor(np.abs(values) + 0.5), values)


def _bilinear_centres(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    center = _round_half_away(points)
    dx, dy = (points - (center - 0.5)).T
    weights = [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]
    return _block(center[:, 0] - 1, center[:, 1] - 1, weights, [(0, 0), (1, 0), (0, 1), (1, 1)])


def _subsample_falloff(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    corner = np.floor(points)
    fx, fy = (points - corner).T
    total = np.zeros(len(points))
    for sx, sy in ((0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)):
        distance = np.hypot(fx - sx, fy - sy)
        total += (SUBSAMPLE_MAX_DISTANCE - distance) / SUBSAMPLE_MAX_DISTANCE
    return corner.astype(np.int64), total / 4


def _normalised_centres(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    low = np.floor(points)
    p0 = np.where(points - low < 0.5, low, np.ceil(points))
    order = [(0, 0), (-1, 0), (0, -1), (-1, -1)]
    raw = [
        SQRT2 - np.hypot(points[:, 0] - (p0[:, 0] + ox + 0.5), points[:, 1] - (p0[:, 1] + oy + 0.5))
        for ox, oy in order
    ]
    total = np.sum(raw, axis=0)
    weights = [w / total for w in raw]
    return _block(p0[:, 0], p0[:, 1], weights, order)


_VECTORIZED: dict[str, Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]] = {
    "nearest_truncate": _nearest_truncate,
    "nearest_round": _nearest_round,
    "bilinear_zero_offset": _bilinear_zero_offset,
    "bilinear_corners": _bilinear_corners,
    "bilinear_centres": _bilinear_centres,
    "subsample_falloff": _subsample_falloff,
    "normalised_centres": _normalised_centres,
}


def splat_points(points: np.ndarray, kind: str) -> tuple[np.ndarray, np.ndarray]:
    """The splat ``kind`` of every sample at once: (pixels (K, 2) ints, weights (K,))."""
    return _VECTORIZED[kind](points)


def arc_length_weights(points: np.ndarray) -> np.ndarray:
    """The length of curve each sample stands for: half of each chord beside it."""
    chords = np.hypot(*np.diff(points, axis=0).T)
    padded = np.concatenate([[0.0], chords, [0.0]])
    return 0.5 * (padded[:-1] + padded[1:])
