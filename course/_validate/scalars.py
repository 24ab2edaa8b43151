"""Numbers and choices: real numbers, integers, corners, canvas shapes, options, generators.

Part of :mod:`course._validate`, which re-exports every name; :func:`describe` words a
value for every message of the package.
"""

from __future__ import annotations

import numbers
from typing import Any

import numpy as np

from course import limits
from course.i18n import _

__all__ = [
    "as_choice",
    "as_corner",
    "as_int",
    "as_option",
    "as_positive_float",
    "as_rng",
    "as_shape",
    "as_unit",
    "describe",
]


def describe(value: Any) -> str:
    """A short description of a value for an error message."""
    if isinstance(value, np.ndarray):
        return _("an array of shape {shape} and dtype {dtype}").format(
            shape=value.shape, dtype=value.dtype
        )
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def as_positive_float(
    value: Any,
    name: str,
    allow_zero: bool = False,
    smallest: float = limits.SMALLEST,
    largest: float = limits.LARGEST,
) -> float:
    """A finite real number > 0 (or >= 0 with ``allow_zero``), within a usable range.

    A non-zero value must lie in ``[smallest, largest]`` (by default
    ``limits.SMALLEST`` and ``limits.LARGEST``): beyond them no tolerance, step
    or width can work.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(
            _("{name} must be a real number; got {value}").format(name=name, value=describe(value))
        )
    number = float(value)
    if not np.isfinite(number):
        raise ValueError(_("{name} must be finite; got {value}").format(name=name, value=number))
    if number < 0 or (number == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise ValueError(
            _("{name} must be {bound}; got {value}").format(name=name, bound=bound, value=number)
        )
    if number != 0 and not smallest <= number <= largest:
        raise ValueError(
            _("{name} must lie between {smallest:g} and {largest:g}; got {value:g}").format(
                name=name, smallest=smallest, largest=largest, value=number
            )
        )
    return number


def as_int(
    value: Any, name: str, minimum: int | None = None, maximum: int = limits.MAX_COUNT
) -> int:
    """An integer (not a bool, not a float), at least ``minimum`` and at most ``maximum``.

    Without ``minimum``, it must also be at least ``-maximum``.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(
            _("{name} must be an integer; got {value}").format(name=name, value=describe(value))
        )
    number = int(value)
    if minimum is not None and number < minimum:
        raise ValueError(
            _("{name} must be >= {minimum}; got {value}").format(
                name=name, minimum=minimum, value=number
            )
        )
    if number > maximum or (minimum is None and number < -maximum):
        low = minimum if minimum is not None else -maximum
        raise ValueError(
            _("{name} must be between {low} and {high}; got {value}").format(
                name=name, low=low, high=maximum, value=number
            )
        )
    return number


def as_corner(corner: Any, name: str = "corner") -> tuple[int, int]:
    """A pair ``(x, y)`` of integers, such as a window's top-left pixel, each checked by
    :func:`as_int` under the names ``name[0] (x)`` and ``name[1] (y)``.

    Examples
    --------
    >>> as_corner([3, -2])
    (3, -2)
    """
    if isinstance(corner, (str, bytes)) or not hasattr(corner, "__len__") or len(corner) != 2:
        raise ValueError(
            _("{name} must be a pair (x, y) of integers; got {corner}").format(
                name=name, corner=describe(corner)
            )
        )
    return as_int(corner[0], f"{name}[0] (x)"), as_int(corner[1], f"{name}[1] (y)")


def as_shape(
    shape: Any, name: str = "shape", max_pixels: int = limits.MAX_PIXELS
) -> tuple[int, int]:
    """A canvas shape ``(H, W)`` of positive integers, at most ``max_pixels`` pixels."""
    if not isinstance(shape, (tuple, list)) or len(shape) != 2:
        raise ValueError(
            _("{name} must be a pair (H, W) of positive integers; got {value}").format(
                name=name, value=describe(shape)
            )
        )
    height = as_int(
        shape[0], _("{name}[0] (height)").format(name=name), minimum=1, maximum=max_pixels
    )
    width = as_int(
        shape[1], _("{name}[1] (width)").format(name=name), minimum=1, maximum=max_pixels
    )
    if height * width > max_pixels:
        raise ValueError(
            _("{name} must have at most {limit} pixels (H * W); got {height} x {width}").format(
                name=name, limit=max_pixels, height=height, width=width
            )
        )
    return height, width


def as_choice(value: Any, name: str, choices: tuple[str, ...] | list[str]) -> str:
    """One of a fixed set of strings."""
    if not isinstance(value, str) or value not in choices:
        options = ", ".join(repr(c) for c in choices)
        raise ValueError(
            _("{name} must be one of {options}; got {value}").format(
                name=name, options=options, value=repr(value)
            )
        )
    return value


def as_option(value: Any, name: str, options: Any) -> Any:
    """One of a control's options (a dropdown's, buttons' or selection slider's).

    Examples
    --------
    >>> as_option("box", "kernel", ("box", "sobel"))
    'box'
    """
    for option in options:
        if type(option) is type(value) and option == value:
            return value
    listed = ", ".join(repr(option) for option in options)
    raise ValueError(
        _("{name} must be one of {options}; got {value}").format(
            name=name, options=listed, value=repr(value)
        )
    )


def as_unit(value: Any, name: str) -> float:
    """A real number in [0, 1], as a slider from 0 to 1 takes it.

    Examples
    --------
    >>> as_unit(0.25, "t")
    0.25
    """
    number = as_positive_float(value, name, allow_zero=True, smallest=0.0)
    if number > 1:
        raise ValueError(
            _("{name} must lie in [0, 1]; got {value:g}").format(name=name, value=number)
        )
    return number


def as_rng(rng: Any, name: str = "rng") -> np.random.Generator:
    """A numpy Generator; None gives ``default_rng(0)``, so results are reproducible."""
    if rng is None:
        return np.random.default_rng(0)
    if not isinstance(rng, np.random.Generator):
        raise TypeError(
            _(
                "{name} must be a numpy.random.Generator, e.g. numpy.random.default_rng(0); got "
                "{value}"
            ).format(name=name, value=describe(rng))
        )
    return rng
