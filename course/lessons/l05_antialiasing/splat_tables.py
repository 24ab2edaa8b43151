"""A splat as a table: rows (x, y, weight), the one form lesson 05's splat checker compares.

:func:`splat_table` puts any splat (pixels and their weights) in that form;
:func:`table_of` turns a splat function of the library's, such as
:func:`course.antialias.bilinear_centres`, into one that gives a point's
table. :mod:`.check` reads the reference and the student's answer into
tables, and :mod:`.mistakes` gives each known mistake's answer as one.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import limits
from course._validate import require_finite
from course.i18n import _

__all__ = ["splat_table", "table_of"]


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
        raise TypeError(
            _("pixels must be numbers; got dtype {dtype}").format(dtype=coordinates.dtype)
        )
    coordinates = coordinates.reshape(-1, 2)
    if len(coordinates) != len(amounts):
        raise ValueError(
            _(
                "pixels and weights must match: {coordinates_count} pixels, {amounts_count} weights"
            ).format(coordinates_count=len(coordinates), amounts_count=len(amounts))
        )
    require_finite(amounts, "weights")
    if not np.isfinite(coordinates).all() or not np.array_equal(coordinates, np.round(coordinates)):
        raise ValueError(_("pixels must be whole numbers (x, y)"))
    if np.abs(coordinates).max() > limits.MAX_COORDINATE:
        raise ValueError(
            _("pixels must lie within +-{bound:g}").format(bound=limits.MAX_COORDINATE)
        )
    unique, index = np.unique(coordinates.astype(np.int64), axis=0, return_inverse=True)
    totals = np.bincount(index.ravel(), amounts, minlength=len(unique))
    keep = np.abs(totals) > 1e-12
    return np.column_stack([unique[keep], totals[keep]]).astype(float)


def table_of(splat: Callable[..., Any]) -> Callable[[float, float], np.ndarray]:
    """``splat`` for one point (x, y), its pixels and weights given as a splat table."""
    return lambda x, y: splat_table(*splat([[x, y]]))
