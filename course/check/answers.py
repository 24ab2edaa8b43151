"""Reading a student's answer: pixels, numbers, and what is wrong with them in words.

The checkers read what a student's function returned before comparing it
(:func:`read_answer`): an answer that cannot be read (:class:`AnswerError`),
holds NaN, is complex or float32 is told so in the student's terms, not with
a traceback from the checker's own conversions. Read, the answer is made
:func:`plain`: the checker's own types, so that no method of the student's
(an ``__eq__`` that is always True, a ``dtype`` that raises) runs after it.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import dataclass
from itertools import islice
from typing import Any

import numpy as np

from course import limits
from course.check._wire import Opaque
from course.check.shown import show_value
from course.i18n import _

__all__ = [
    "AnswerError",
    "Reading",
    "described",
    "holds_complex",
    "narrow_float",
    "non_finite",
    "only_data",
    "pixel_rows",
    "plain",
    "read_answer",
    "type_name",
]

#: Most numbers of a wrong answer the report reads in full; past it, only sizes are compared.
_LARGEST_ANSWER = 2**20


class AnswerError(ValueError):
    """A student's answer the checker cannot read, with a message in the student's terms."""


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
            # At most one more than the most read: an endless iterator is not listed forever.
            items = list(islice(pixels, _LARGEST_ANSWER + 1))
        except TypeError:
            raise AnswerError(
                name
                + _("expected a list of (x, y) pixels; got {type}").format(
                    type=type(pixels).__name__
                )
            ) from None
        if len(items) > _LARGEST_ANSWER:
            if type(pixels) in (list, tuple):
                raise AnswerError(name + _too_many(len(pixels)))
            raise AnswerError(
                name
                + _(
                    "your {type} gave more than {count:,} pixels and did not end: return a list "
                    "(or an array) of the pixels, not an endless iterator"
                ).format(type=type(pixels).__name__, count=_LARGEST_ANSWER)
            )
        try:
            # Each pixel read as far as a third item: one that never ends is not a pair.
            pairs = [tuple(islice(item, 3)) for item in items]
            array = np.array(pairs, dtype=object).reshape(-1, 2)
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
    # The answer's own attributes are not trusted: an array's dtype is read from numpy's
    # record of it, and anything that fails to say is not complex (its reading will tell).
    try:
        if isinstance(value, complex):
            return True
        if isinstance(value, (np.ndarray, np.generic)):
            return np.asarray(value).dtype.kind == "c"
        dtype = getattr(value, "dtype", None)
        if isinstance(dtype, np.dtype):
            return dtype.kind == "c"
        if isinstance(value, (list, tuple)):
            items = (
                list.copy(value)
                if isinstance(value, list)
                else tuple.__getitem__(value, slice(None))
            )
            return len(items) <= 64 and any(holds_complex(item) for item in items)
    except Exception:
        return False
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

    The answer's own methods are not called: its shape, dtype and length are numpy's and
    Python's records of them, so an answer whose ``dtype`` or ``__len__`` raises is still
    described.

    Examples
    --------
    >>> described([1, 2]), described(None)
    ('a list of 2 items', 'a NoneType')
    """
    try:
        if isinstance(value, np.ndarray):
            array = np.ndarray.view(value, np.ndarray)
            return _("an array of shape {shape} and dtype {dtype}").format(
                shape=array.shape, dtype=array.dtype
            )
        if isinstance(value, (list, tuple)):
            count = list.__len__(value) if isinstance(value, list) else tuple.__len__(value)
            return _("a {type} of {count} items").format(type=type_name(value), count=count)
    except Exception:
        pass
    return _("a {type}").format(type=type_name(value))


def type_name(value: Any) -> str:
    """The name of an answer's type; for a part :func:`plain` could not read, its type's.

    Examples
    --------
    >>> type_name(2.5), type_name(plain(iter([1])))
    ('float', 'list_iterator')
    """
    return value.kind if isinstance(value, (_Unread, Opaque)) else type(value).__name__


#: How deep :func:`plain` looks into lists and tuples.
_DEEPEST = 32

# Types whose values say what they are: no method of theirs can lie.
_EXACT = (int, float, complex, bool, str, bytes, type(None))


class _Unread:
    """A part of an answer that is not numbers the checker can read (a generator, a dict, an
    object of the student's own class): shown by what it said of itself when it was read,
    equal to nothing else, and no number (``float()`` of it fails)."""

    __slots__ = ("kind", "text")

    def __init__(self, text: str, kind: str) -> None:
        self.text, self.kind = text, kind

    def __repr__(self) -> str:
        return self.text


def plain(value: Any, depth: int = 0) -> Any:
    """An answer as the checker's own values: exact ints, floats, lists, tuples and arrays.

    A subclass of int, float, list, tuple or ndarray becomes its base type's
    value, read from Python's and numpy's record of it, so no method the
    student wrote (an ``__eq__`` that is always True, a ``dtype`` that lies)
    runs after this; an object array's items and a list's are made plain in
    turn; another object becomes the array numpy reads from it, when that
    holds numbers, or a stand-in showing what it said of itself. Objects of
    the course's own types (a checker's conversion made them) are kept.
    Reading runs the student's methods: the checker calls this within the
    case's budget.

    Examples
    --------
    >>> class Agreeable(int):
    ...     def __eq__(self, other):
    ...         return True
    >>> answer = plain(Agreeable(3))
    >>> type(answer).__name__, answer == 4
    ('int', False)
    >>> plain((2.5, [1, (2, 3)]))
    (2.5, [1, (2, 3)])
    """
    kind = type(value)
    if kind is np.ndarray and value.dtype.hasobject:
        return _plain_objects(value, depth) if value.dtype == object else _unread(value)
    if _exact(value) or _checkers_own(kind):
        return value
    if depth >= _DEEPEST:
        return _unread(value)
    if isinstance(value, np.ndarray):
        return plain(np.ndarray.view(value, np.ndarray), depth + 1)
    if isinstance(value, np.generic):
        return plain(np.asarray(value)[()], depth + 1)
    if isinstance(value, int):
        return int.__int__(value)
    if isinstance(value, float):
        return float.__float__(value)
    if isinstance(value, complex):
        return complex(complex.real.__get__(value), complex.imag.__get__(value))
    if isinstance(value, str):
        return str.__str__(value)
    if isinstance(value, list):
        return [plain(item, depth + 1) for item in list.copy(value)]
    if isinstance(value, tuple):
        return tuple(plain(item, depth + 1) for item in tuple.__getitem__(value, slice(None)))
    try:
        array = np.asarray(value)
    except Exception:
        return _unread(value)
    if type(array) is np.ndarray and array.dtype != object:
        return array
    return _unread(value)


def only_data(value: Any, most: int = 10_000) -> bool:
    """Whether ``value`` is made only of values whose methods are Python's and numpy's own
    (exact numbers, text, None, arrays of numbers, and lists and tuples of these, up to
    ``most`` items): reading it runs no code of the student's, so needs no budget.

    Examples
    --------
    >>> only_data((1.5, [np.zeros(2), None])), only_data([iter([])])
    (True, False)
    """
    todo = [value]
    for _seen in range(most):
        if not todo:
            return True
        item = todo.pop()
        if type(item) in (list, tuple):
            todo.extend(item)
        elif not _exact(item) or (type(item) is np.ndarray and item.dtype.hasobject):
            return False
    return not todo


def _exact(value: Any) -> bool:
    """Whether ``value``'s type is one whose methods no student wrote: Python's or numpy's."""
    kind = type(value)
    return (
        kind in _EXACT
        or kind is np.ndarray
        or (isinstance(value, np.generic) and kind.__module__ == "numpy")
    )


def _plain_objects(array: np.ndarray, depth: int) -> Any:
    if array.size > _LARGEST_ANSWER or depth >= _DEEPEST:
        return _unread(array)
    flat = np.empty(array.size, dtype=object)
    for index, item in enumerate(array.reshape(-1)):
        flat[index] = plain(item, depth + 1)  # an item at a time: a list stays one item
    return flat.reshape(array.shape)


def _unread(value: Any) -> _Unread:
    kind = type(value).__name__
    try:
        return _Unread(str.__str__(show_value(value)), kind)
    except Exception:  # a repr that raises, or is no text
        return _Unread(f"<{kind}>", kind)


def _checkers_own(kind: type) -> bool:
    """Whether ``kind`` is one of the course's own classes (a checker's conversion made it)."""
    name = getattr(kind, "__module__", None)
    module = sys.modules.get(name) if isinstance(name, str) and name.startswith("course.") else None
    return module is not None and vars(module).get(getattr(kind, "__qualname__", "")) is kind


@dataclass(frozen=True)
class Reading:
    """A student's answer as the checker read it (``given``, plain; what it was, in words; what a
    narrow float loses), or the report's lines saying why it could not be read."""

    given: Any = None
    described: str = ""
    narrow: str | None = None
    lines: list[str] | None = None


def read_answer(
    count: int,
    returned: Any,
    arguments: tuple[Any, ...],
    answer: Callable[[Any, tuple[Any, ...]], Any] | None,
    convert: Callable[[Any], Any],
    compare: Callable[[Any, Any], bool],
) -> Reading:
    """Read case ``count``'s answer: made from what the function returned (``answer``), checked
    for complex numbers, converted (``convert``), made :func:`plain`. Every step may run the
    student's code, so the checker calls this within the case's budget; an exception is the
    report's words, never raised.

    Examples
    --------
    >>> read_answer(1, (1.0, 2.0), (), None, np.asarray, None).given
    array([1., 2.])
    >>> read_answer(1, [1j], (), None, np.asarray, None).lines
    ['case 1: your answer holds complex numbers; the answer is real']
    """
    raw = answer(returned, arguments) if answer is not None else returned
    seen = described(raw)
    if holds_complex(raw):
        text = _("case {count}: your answer holds complex numbers; the answer is real")
        return Reading(lines=[text.format(count=count)])
    try:
        given = plain(convert(raw))
    except AnswerError as unreadable:
        text = _("case {count}: your answer cannot be read: {reason}")
        return Reading(lines=[text.format(count=count, reason=unreadable)])
    except Exception as unreadable:
        return Reading(
            lines=[
                _(
                    "case {count}: your answer, {described}, cannot be read as the "
                    "exercise's answer ({error_type}: {error})"
                ).format(
                    count=count,
                    described=seen,
                    error_type=type(unreadable).__name__,
                    error=unreadable,
                ),
                _(
                    "  (the checker raised this while reading your answer; your function ran "
                    "without an error)"
                ),
            ]
        )
    try:
        narrow = narrow_float(raw, compare)
    except Exception:  # a dtype that raises: the answer was read all the same
        narrow = None
    return Reading(given, seen, narrow)
