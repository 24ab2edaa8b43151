"""Comparing a student's answer with the reference's, and saying where they differ.

Values within a tolerance (:func:`close`, :func:`first_difference`), and
pixel sets in any order (:func:`same_pixels`, :func:`pixel_difference`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.answers import pixel_rows, type_name
from course.check.views import quiet
from course.i18n import _

__all__ = ["close", "first_difference", "pixel_difference", "same_pixels"]

# The comparisons' own numpy, held from import: an earlier cell's `np.allclose = lambda *a,
# **k: True` does not make a wrong answer pass (course.check.views.CheckersView puts numpy
# back for the rest of a check).
_allclose, _array_equal, _isclose = np.allclose, np.array_equal, np.isclose
_asarray, _unique = np.asarray, np.unique


def close(atol: float = 1e-9, rtol: float = 1e-9) -> Callable[[Any, Any], bool]:
    """A comparison: same shape and equal within the tolerances.

    The comparison carries its tolerances (``compare.atol``, ``compare.rtol``)
    for the report.

    Examples
    --------
    >>> close(atol=1e-3)([1.0, 2.0], (1.0, 2.0005))
    True
    """

    def compare(expected: Any, given: Any) -> bool:
        expected, given = _asarray(expected, dtype=float), _asarray(given, dtype=float)
        return expected.shape == given.shape and bool(
            _allclose(given, expected, atol=atol, rtol=rtol)
        )

    compare.atol, compare.rtol = atol, rtol  # type: ignore[attr-defined]
    return compare


# Pixels are compared as one int64 key each, in reading order: (y, x) -> y * _WIDE + x.
_OFFSET = 2**21
_WIDE = 2**22


def _keys(pixels: Any, name: str) -> np.ndarray:
    rows = pixels if isinstance(pixels, np.ndarray) and pixels.dtype == np.int64 else None
    rows = pixel_rows(pixels, name) if rows is None else rows.reshape(-1, 2)
    return _unique((rows[:, 1] + _OFFSET) * _WIDE + (rows[:, 0] + _OFFSET))


def _pixel_of(key: int) -> tuple[int, int]:
    return int(key % _WIDE - _OFFSET), int(key // _WIDE - _OFFSET)


def same_pixels(expected: Any, given: Any) -> bool:
    """A comparison of pixel sets: the same (x, y) pixels, in any order, repeats ignored.

    Examples
    --------
    >>> same_pixels([[1, 2], [3, 4]], [[3, 4], [1, 2], [1, 2]])
    True
    """
    return bool(_array_equal(_keys(expected, "expected"), _keys(given, "given")))


def first_difference(expected: Any, given: Any, atol: float = 1e-9, rtol: float = 1e-9) -> str:
    """Where two answers first differ, in words: the first wrong value and its index.

    Examples
    --------
    >>> first_difference([1.0, 2.0, 3.0], [1.0, 2.5, 3.0])
    'first wrong value: [1] expected 2, given 2.5'
    >>> first_difference([[1.0, 2.0]], [1.0, 2.0])
    'expected shape (1, 2), given shape (2,)'
    >>> wrong = np.zeros((5, 5)); wrong[2, 3] = 1
    >>> print(first_difference(np.zeros((5, 5)), wrong))
    first wrong value: [2, 3] expected 0, given 1
      around it, rows 1-3 and columns 2-4:
        expected [[0., 0., 0.], [0., 0., 0.], [0., 0., 0.]]
        given    [[0., 0., 0.], [0., 1., 0.], [0., 0., 0.]]
    """
    try:
        with quiet():
            expected, given = _asarray(expected, dtype=float), _asarray(given, dtype=float)
    except (TypeError, ValueError):
        return _("given a {type}, not numbers").format(type=type_name(given))
    if expected.shape != given.shape:
        return _("expected shape {expected}, given shape {given}").format(
            expected=expected.shape, given=given.shape
        )
    if expected.ndim == 0:
        return ""  # one value: the lines above say it all
    wrong = ~_isclose(given, expected, atol=atol, rtol=rtol)
    if not wrong.any():
        return _("the values agree within the tolerance")
    index = tuple(int(i) for i in np.argwhere(wrong)[0])
    where = "[" + ", ".join(map(str, index)) + "]"
    first = _("first wrong value: {where} expected {expected:.6g}, given {given:.6g}").format(
        where=where, expected=expected[index], given=given[index]
    )
    if expected.ndim < 2 or expected.size <= _SHOWN_IN_FULL:
        return first  # the report's lines above show every value
    return first + _window(expected, given, index)


#: Most numbers an answer's report line shows in full (see ``shown.show_value``).
_SHOWN_IN_FULL = 24


def _window(expected: np.ndarray, given: np.ndarray, index: tuple[int, ...]) -> str:
    """The 3 x 3 pixels (rows and columns) around ``index``, expected and given, one line each."""
    rows = slice(max(index[0] - 1, 0), min(index[0] + 2, expected.shape[0]))
    columns = slice(max(index[1] - 1, 0), min(index[1] + 2, expected.shape[1]))

    def shown(values: np.ndarray) -> str:
        text = np.array2string(values[rows, columns], precision=4, separator=", ")
        return " ".join(text.split())

    return _(
        "\n  around it, rows {first_row}-{last_row} and columns {first_column}-{last_column}:"
        "\n    expected {expected}\n    given    {given}"
    ).format(
        first_row=rows.start,
        last_row=rows.stop - 1,
        first_column=columns.start,
        last_column=columns.stop - 1,
        expected=shown(expected),
        given=shown(given),
    )


def pixel_difference(expected: Any, given: Any) -> str:
    """Missing and extra pixels, in words, each with its first pixel in reading order.

    Repeated pixels are named: a pixel listed twice is painted twice.

    Examples
    --------
    >>> pixel_difference([[0, 0], [1, 0], [2, 1]], [[0, 0], [1, 1], [2, 1]])
    '1 pixel missing, first at (x, y) = (1, 0); 1 extra, first at (x, y) = (1, 1)'
    >>> pixel_difference([[0, 0], [1, 0]], [[0, 0], [1, 0], [1, 0]])
    'the same pixels, but 1 listed more than once, first (1, 0): each pixel once'
    """
    want, have = _keys(expected, "expected"), _keys(given, "given")
    parts = []
    missing, extra = np.setdiff1d(want, have), np.setdiff1d(have, want)
    if len(missing):
        if len(missing) == 1:
            missing_text = _("{count} pixel missing, first at (x, y) = {pixel}")
        else:
            missing_text = _("{count} pixels missing, first at (x, y) = {pixel}")
        parts.append(missing_text.format(count=len(missing), pixel=_pixel_of(missing[0])))
    if len(extra):
        parts.append(
            _("{count} extra, first at (x, y) = {pixel}").format(
                count=len(extra), pixel=_pixel_of(extra[0])
            )
        )
    if parts:
        return _("; ").join(parts)
    rows = pixel_rows(given, "given")
    keys = (rows[:, 1] + _OFFSET) * _WIDE + (rows[:, 0] + _OFFSET)
    unique, counts = np.unique(keys, return_counts=True)
    repeated = unique[counts > 1]
    if len(repeated):
        return _(
            "the same pixels, but {count} listed more than once, first {pixel}: each pixel once"
        ).format(count=len(repeated), pixel=_pixel_of(repeated[0]))
    return _("the same pixels")
