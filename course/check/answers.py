"""Reading a student's answer: pixels, numbers, and what is wrong with them in words.

The checkers read what a student's function returned before comparing it: an
answer that cannot be read (:class:`AnswerError`), holds NaN, is complex or
float32 is told so in the student's terms, not with a traceback from the
checker's own conversions.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course.i18n import _

__all__ = [
    "AnswerError",
    "described",
    "holds_complex",
    "narrow_float",
    "non_finite",
    "pixel_rows",
    "show_value",
]

#: Most numbers of a wrong answer the report reads in full; past it, only sizes are compared.
_LARGEST_ANSWER = 2**20

#: Most numbers of an image of three or more axes shown in full (a 2 x 4 colour image).
_LARGEST_SHOWN_IMAGE = 24


class AnswerError(ValueError):
    """A student's answer the checker cannot read, with a message in the student's terms."""


def show_value(value: Any) -> str:
    """A case's input or an answer in one line: in full when small, by its shape when not.

    Examples
    --------
    >>> show_value(np.float64(0.5)), show_value(np.zeros((30, 30), dtype=np.int64))
    ('0.5', 'an array of shape (30, 30), dtype int64, values 0 to 0')
    >>> show_value(np.full((8, 8, 3), 0.25))
    'an array of shape (8, 8, 3), dtype float64, values 0.25 to 0.25'
    >>> show_value(np.zeros((2, 21)))
    '[[0., 0., 0., ..., 0., 0., 0.], [0., 0., 0., ..., 0., 0., 0.]] (shape (2, 21))'
    """
    if isinstance(value, np.generic):
        return repr(value.item())
    if isinstance(value, np.ndarray):
        # A colour image's numbers fill screens: past a few pixels, its size and range say more.
        if value.size > 400 or (value.ndim >= 3 and value.size > _LARGEST_SHOWN_IMAGE):
            return _summary(value)
        text = " ".join(np.array2string(value, precision=6, separator=", ", threshold=40).split())
        if value.size > 40:  # numpy elided some numbers: the shape is what a student can't count
            text += " " + _("(shape {shape})").format(shape=value.shape)
        return text
    text = repr(value)
    return text if len(text) <= 300 else text[:297] + "..."


def _summary(value: np.ndarray) -> str:
    """An array by its shape, dtype and range (the range only when it is real and finite)."""
    if value.size and value.dtype.kind in "biuf" and np.isfinite(value).all():
        return _("an array of shape {shape}, dtype {dtype}, values {low:.6g} to {high:.6g}").format(
            shape=value.shape, dtype=value.dtype, low=value.min(), high=value.max()
        )
    return _("an array of shape {shape}, dtype {dtype}").format(
        shape=value.shape, dtype=value.dtype
    )


def pixel_rows(pixels: Any, name: str = "") -> np.ndarray:
    """A student's pixels as a (K, 2) int64 array of (x, y); :class:`AnswerError` if unreadable.

    Accepts an array, or a list of pairs; each coordinate must be a whole
    number within the course's coordinate bound.

    Examples
    --------
    >>> pixel_rows([(1, 2), (3.0, 4)])
    array([[1, 2],
           [3, 4]])
    >>> pixel_rows([(1.5, 2)])
    Traceback (most recent call last):
    ...
    course.check.answers.AnswerError: a pixel is two whole numbers (x, y); pixel [0] is (1.5, 2)
    """
    name = f"{name}: " if name else ""
    if isinstance(pixels, np.ndarray):
        array = pixels
    else:
        try:
            items = list(pixels)
        except TypeError:
            raise AnswerError(
                name
                + _("expected a list of (x, y) pixels; got {type}").format(
                    type=type(pixels).__name__
                )
            ) from None
        if len(items) > _LARGEST_ANSWER:
            raise AnswerError(name + _too_many(len(items)))
        try:
            array = np.array([tuple(item) for item in items], dtype=object).reshape(-1, 2)
        except (TypeError, ValueError):
            raise AnswerError(
                name
                + _("each pixel must be a pair (x, y); got {first}...").format(
                    first=show_value(items[:3])[:80]
                )
            ) from None
    if np.iscomplexobj(array):
        raise AnswerError(name + _("pixels are real numbers; yours are complex"))
    try:
        values = np.asarray(array, dtype=float)
    except (TypeError, ValueError):
        raise AnswerError(name + _("pixels must be numbers (x, y)")) from None
    if values.size % 2 or (values.ndim == 2 and values.shape[1] != 2) or values.ndim > 2:
        raise AnswerError(
            name
            + _("pixels are (x, y) pairs, shape (K, 2); got {shape}").format(shape=values.shape)
        )
    values = values.reshape(-1, 2)
    if len(values) > _LARGEST_ANSWER:
        raise AnswerError(name + _too_many(len(values)))
    bad = ~np.isfinite(values).all(axis=1)
    if bad.any():
        index = int(np.argmax(bad))
        raise AnswerError(
            name
            + _("pixel [{index}] is {pixel}, not a number").format(
                index=index, pixel=_pair(values[index])
            )
        )
    far = (np.abs(values) > limits.MAX_COORDINATE).any(axis=1)
    if far.any():
        index = int(np.argmax(far))
        raise AnswerError(
            name
            + _("pixel [{index}] is {pixel}, beyond any image (+-{bound:g})").format(
                index=index, pixel=_pair(values[index]), bound=limits.MAX_COORDINATE
            )
        )
    whole = (values == np.round(values)).all(axis=1)
    if not whole.all():
        index = int(np.argmin(whole))
        raise AnswerError(
            name
            + _("a pixel is two whole numbers (x, y); pixel [{index}] is {pixel}").format(
                index=index, pixel=_pair(values[index])
            )
        )
    return values.astype(np.int64)


def _too_many(count: int) -> str:
    return _("{count:,} pixels, far more than any case needs").format(count=count)


def _pair(values: np.ndarray) -> str:
    return "(" + ", ".join(f"{float(v):g}" for v in values) + ")"


def holds_complex(value: Any) -> bool:
    """Whether an answer holds complex numbers (a short list or tuple is looked into).

    Examples
    --------
    >>> holds_complex([1.0, 2j]), holds_complex(np.zeros(3))
    (True, False)
    """
    if isinstance(value, complex) or np.iscomplexobj(getattr(value, "dtype", None) or 0):
        return True
    if isinstance(value, (np.ndarray, np.generic)):
        return value.dtype.kind == "c"
    if isinstance(value, (list, tuple)) and len(value) <= 64:
        return any(holds_complex(item) for item in value)
    return False


def non_finite(given: Any) -> str | None:
    """Where a converted answer holds NaN or inf, in words; None if nowhere.

    Examples
    --------
    >>> non_finite(np.array([1.0, np.nan]))
    'your answer holds nan at [1]: every value must be a finite number'
    """
    if isinstance(given, (float, np.floating)):
        return None if np.isfinite(given) else _("your answer is {value}").format(value=given)
    if not isinstance(given, np.ndarray) or given.dtype.kind != "f":
        return None
    bad = ~np.isfinite(given)
    if not bad.any():
        return None
    index = tuple(int(i) for i in np.argwhere(bad)[0])
    where = "[" + ", ".join(map(str, index)) + "]"
    return _("your answer holds {value} at {where}: every value must be a finite number").format(
        value=given[index], where=where
    )


def narrow_float(value: Any, compare: Any) -> str | None:
    """What a float32 (or narrower) answer loses, against the comparison's tolerance; or None.

    Examples
    --------
    >>> narrow_float(np.float32([0.5]), None).split(";")[0]
    'your answer is float32 (about 6 significant digits)'
    """
    dtype = getattr(value, "dtype", None)
    if dtype is None or dtype.kind != "f" or dtype.itemsize >= 8:
        return None
    tolerance = getattr(compare, "atol", None)
    allowed = _("the check is exact")
    if isinstance(tolerance, (int, float)) and tolerance:
        allowed = _("the check allows {tolerance:g}").format(tolerance=tolerance)
    return _(
        "your answer is {dtype} (about {digits} significant digits); {allowed}: compute in "
        "float64, Python's float"
    ).format(dtype=dtype, digits=np.finfo(dtype).precision, allowed=allowed)


def described(value: Any) -> str:
    """What an answer is, when its values cannot be shown: its type, and its shape or length.

    Examples
    --------
    >>> described([1, 2]), described(None)
    ('a list of 2 items', 'a NoneType')
    """
    if isinstance(value, np.ndarray):
        return _("an array of shape {shape} and dtype {dtype}").format(
            shape=value.shape, dtype=value.dtype
        )
    if isinstance(value, (list, tuple)):
        return _("a {type} of {count} items").format(type=type(value).__name__, count=len(value))
    return _("a {type}").format(type=type(value).__name__)
