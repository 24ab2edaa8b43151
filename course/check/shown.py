"""A case's input or a student's answer in one line of a checker's report.

Small values are shown in full, floats to 12 significant digits (a float's last
binary digit is noise to a student), large arrays by their shape, dtype and range.
The checkers' reports (:mod:`course.check.base`), the reading of an answer
(:mod:`course.check.answers`) and the lessons' own report lines call it.
"""

from __future__ import annotations

from itertools import islice
from typing import Any

import numpy as np

from course.i18n import _

__all__ = ["show_value"]

#: Most numbers of an image of three or more axes shown in full (a 2 x 4 colour image).
_LARGEST_SHOWN_IMAGE = 24


def show_value(value: Any) -> str:
    """A case's input or an answer in one line: in full when small, by its shape when not.

    Examples
    --------
    >>> show_value(np.float64(0.5)), show_value(np.zeros((30, 30), dtype=np.int64))
    ('0.5', 'an array of shape (30, 30), dtype int64, all 0')
    >>> show_value(np.full((8, 8, 3), 0.25))
    'an array of shape (8, 8, 3), dtype float64, all 0.25'
    >>> show_value(np.zeros((2, 21)))
    '[[0., 0., 0., ..., 0., 0., 0.], [0., 0., 0., ..., 0., 0., 0.]] (shape (2, 21))'
    >>> from course.i18n import message_language
    >>> with message_language("zh-CN"):
    ...     show_value(np.zeros((2, 21)))[-14:]
    ']]（形状 (2, 21)）'
    """
    if isinstance(value, np.generic):
        return repr(_rounded(value.item()))
    if isinstance(value, np.ndarray):
        # A colour image's numbers fill screens: past a few pixels, its size and range say more.
        if value.size > 400 or (value.ndim >= 3 and value.size > _LARGEST_SHOWN_IMAGE):
            return _summary(value)
        text = " ".join(np.array2string(value, precision=6, separator=", ", threshold=40).split())
        if value.size > 40:  # numpy elided some numbers: the shape is what a student can't count
            shape = _("(shape {shape})").format(shape=value.shape)
            # A full-width parenthesis (Chinese) carries its own space; a half-width one needs one.
            text += shape if shape.startswith("（") else " " + shape
        return text
    text = repr(_rounded(value))
    return text if len(text) <= 300 else text[:297] + "..."


def _rounded(value: Any, depth: int = 0) -> Any:
    """``value`` with its floats to 12 significant digits, so that 0.1 + 0.475 shows as 0.575.

    A float's last binary digit is noise to a student (0.5750000000000002); a check's
    tolerance is far wider than 12 digits, so two answers it tells apart still show apart.
    Plain tuples and lists are rounded inside (their first hundred items: the rest are cut
    from the line anyway); anything else is left as it is.

    >>> _rounded(0.1 + 0.475), _rounded((1, 0.1 + 0.2, [2.5, float("nan")]))
    (0.575, (1, 0.3, [2.5, nan]))
    """
    if type(value) is float:
        return float(f"{value:.12g}") if np.isfinite(value) else value
    if type(value) in (tuple, list) and depth < 4:
        items = [_rounded(item, depth + 1) for item in islice(value, 100)]
        return type(value)(items + list(value[100:]))
    return value


def _summary(value: np.ndarray) -> str:
    """An array by its shape, dtype and range (the range only when it is real and finite)."""
    if value.size and value.dtype.kind in "biuf" and np.isfinite(value).all():
        low, high = value.min(), value.max()
        message = (
            _("an array of shape {shape}, dtype {dtype}, all {low:.6g}")
            if low == high
            else _("an array of shape {shape}, dtype {dtype}, values {low:.6g} to {high:.6g}")
        )
        return message.format(shape=value.shape, dtype=value.dtype, low=low, high=high)
    return _("an array of shape {shape}, dtype {dtype}").format(
        shape=value.shape, dtype=value.dtype
    )
