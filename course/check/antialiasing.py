"""Lesson 05's exercise: write the bilinear splat about pixel centres.

The GAMES101 optional task: for a curve point, do not light one pixel but
share it among the pixels around it, by distance to their centres. The
student writes ``splat(x, y)`` for one point and returns ``(pixels,
weights)``: the (x, y) pixels it touches and how much of the point each
receives. The checker compares it with :func:`course.antialias.bilinear_centres`,
pixel by pixel, ignoring order and pixels of weight 0.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.antialias import bilinear_centres
from course.check.base import CheckResult, close, run_cases

__all__ = ["bilinear_splat", "splat_table"]

# Points that tell the common mistakes apart: a pixel centre (one pixel gets
# everything), a pixel corner (four equal shares), generic points, points
# whose nearest corner rounds the other way, a negative coordinate.
CASES = (
    {"x": 2.5, "y": 1.5},
    {"x": 3.0, "y": 2.0},
    {"x": 3.25, "y": 7.875},
    {"x": 10.125, "y": 4.625},
    {"x": 0.875, "y": 0.375},
    {"x": 5.75, "y": 5.75},
    {"x": -0.25, "y": 1.625},
)


def splat_table(pixels: Any, weights: Any) -> np.ndarray:
    """A splat in one canonical form: rows (x, y, weight), sorted, zero weights dropped.

    Repeated pixels are merged by adding their weights.

    Examples
    --------
    >>> splat_table([[1, 0], [0, 0], [1, 0], [2, 2]], [0.25, 0.5, 0.25, 0.0])
    array([[0. , 0. , 0.5],
           [1. , 0. , 0.5]])
    """
    coordinates = np.asarray(pixels)
    amounts = np.asarray(weights, dtype=float).reshape(-1)
    if coordinates.size == 0:
        return np.zeros((0, 3))
    if not np.issubdtype(coordinates.dtype, np.number):
        raise TypeError(f"pixels must be numbers; got dtype {coordinates.dtype}")
    coordinates = coordinates.reshape(-1, 2)
    if len(coordinates) != len(amounts):
        raise ValueError(
            f"pixels and weights must match: {len(coordinates)} pixels, {len(amounts)} weights"
        )
    if not np.array_equal(coordinates, np.round(coordinates)):
        raise ValueError("pixels must be whole numbers (x, y)")
    unique, index = np.unique(coordinates.astype(np.int64), axis=0, return_inverse=True)
    totals = np.bincount(index.ravel(), amounts, minlength=len(unique))
    keep = np.abs(totals) > 1e-12
    return np.column_stack([unique[keep], totals[keep]]).astype(float)


def _reference(x: float, y: float) -> np.ndarray:
    return splat_table(*bilinear_centres([[x, y]]))


def bilinear_splat(student: Callable[[float, float], Any]) -> CheckResult:
    """Check ``student(x, y) -> (pixels, weights)`` against the bilinear splat about centres.

    The correct splat lights the four pixels whose centres (c + 0.5,
    r + 0.5) surround the point, with weights ``(1 - dx)(1 - dy)``,
    ``dx (1 - dy)``, ``(1 - dx) dy``, ``dx dy``, where (dx, dy) is the
    point's offset from the top-left one of those centres.

    Examples
    --------
    >>> from course.antialias import bilinear_centres
    >>> bilinear_splat(lambda x, y: bilinear_centres([[x, y]]))
    PASS bilinear_splat: all 7 cases pass
    """
    return run_cases(
        "bilinear_splat",
        student,
        CASES,
        reference=_reference,
        compare=close(atol=1e-9, rtol=0.0),
        convert=lambda answer: splat_table(*answer),
        hint="the four pixels whose centres (c + 0.5, r + 0.5) surround the point; measure the "
        "point's offset (dx, dy) from the top-left of those centres, and give each pixel the "
        "area of the opposite rectangle.",
    )
