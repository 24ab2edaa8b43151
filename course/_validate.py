"""Input checks shared by every public function: the one home of every validator.

Each public function validates once, at its boundary, with these helpers and
then hands plain arrays to pure array code. Every message names the
parameter, the expected shape or type, and what was given (:func:`describe`).
"""

from __future__ import annotations

import numbers
from typing import Any

import numpy as np


def describe(value: Any) -> str:
    """A short description of a value for an error message."""
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape} and dtype {value.dtype}"
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def as_float_array(value: Any, name: str) -> np.ndarray:
    """A float64 copy of ``value``; TypeError unless it holds real numbers."""
    try:
        array = np.array(value)
    except ValueError as error:  # ragged nested lists
        raise ValueError(
            f"{name} must be a rectangular array of numbers; got a ragged sequence ({error})"
        ) from None
    if array.dtype == bool or not (
        np.issubdtype(array.dtype, np.integer) or np.issubdtype(array.dtype, np.floating)
    ):
        raise TypeError(
            f"{name} must hold real numbers; got {describe(value)}"
            + (f" with dtype {array.dtype}" if not isinstance(value, np.ndarray) else "")
        )
    return array.astype(float, copy=True)


def require_finite(array: np.ndarray, name: str) -> None:
    """ValueError naming the first NaN or infinite entry."""
    bad = ~np.isfinite(array)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f" at index {index}" if array.ndim else ""
        raise ValueError(f"{name} must be finite; got {array[bad].flat[0]}{where}")


def as_points(points: Any, name: str = "points") -> np.ndarray:
    """Validate a point list: a finite float ``(N, d)`` array, N >= 1, d >= 1.

    Returns a new float64 array, so callers may work on it freely.
    """
    array = as_float_array(points, name)
    if array.ndim != 2:
        hint = ""
        if array.ndim == 1 and array.size:
            hint = (
                "; a flat list of numbers is missing its second axis, "
                f"e.g. {name}.reshape(-1, 2) for 2-D points"
            )
        raise ValueError(
            f"{name} must be a 2-D array of shape (N, d), one row per point; "
            f"got shape {array.shape}{hint}"
        )
    if array.shape[0] == 0:
        raise ValueError(f"{name} must hold at least one point (N >= 1); got shape {array.shape}")
    if array.shape[1] == 0:
        raise ValueError(
            f"{name} must have at least one coordinate per point (d >= 1); got shape {array.shape}"
        )
    require_finite(array, name)
    return array


def as_curve(points: Any, name: str = "points") -> np.ndarray:
    """Validate control points of a curve in image space: finite, shape (N, 2)."""
    control = as_points(points, name)
    if control.shape[1] != 2:
        raise ValueError(
            f"{name} must have shape (N, 2): (x, y) control points in image space; "
            f"got shape {control.shape}"
        )
    return control


def as_point(point: Any, name: str, dim: int | None = None) -> np.ndarray:
    """Validate one point: a finite float ``(d,)`` array."""
    array = as_float_array(point, name)
    if array.ndim != 1 or array.size == 0 or (dim is not None and array.size != dim):
        expected = f"({dim},)" if dim is not None else "(d,)"
        raise ValueError(f"{name} must be one point of shape {expected}; got shape {array.shape}")
    require_finite(array, name)
    return array


def as_parameter(t: Any, name: str = "t") -> tuple[np.ndarray, bool]:
    """Validate a curve parameter: a finite scalar or 1-D array.

    Returns ``(values, is_scalar)`` with ``values`` a 1-D float64 array.
    """
    array = as_float_array(t, name)
    if array.ndim > 1:
        raise ValueError(f"{name} must be a scalar or a 1-D array; got shape {array.shape}")
    require_finite(array, name)
    return np.atleast_1d(array), array.ndim == 0


def as_scalar_parameter(t: Any, name: str = "t") -> float:
    """Validate a single finite real number."""
    values, is_scalar = as_parameter(t, name)
    if not is_scalar:
        raise ValueError(f"{name} must be a single number; got an array of shape {values.shape}")
    return float(values[0])


def as_positive_float(value: Any, name: str, allow_zero: bool = False) -> float:
    """A finite real number > 0 (or >= 0 with ``allow_zero``)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a real number; got {describe(value)}")
    number = float(value)
    if not np.isfinite(number):
        raise ValueError(f"{name} must be finite; got {number}")
    if number < 0 or (number == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise ValueError(f"{name} must be {bound}; got {number}")
    return number


def as_int(value: Any, name: str, minimum: int | None = None) -> int:
    """An integer (not a bool, not a float), optionally at least ``minimum``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer; got {describe(value)}")
    number = int(value)
    if minimum is not None and number < minimum:
        raise ValueError(f"{name} must be >= {minimum}; got {number}")
    return number


def as_shape(shape: Any, name: str = "shape") -> tuple[int, int]:
    """A canvas shape ``(H, W)`` of positive integers."""
    if not isinstance(shape, (tuple, list)) or len(shape) != 2:
        raise ValueError(
            f"{name} must be a pair (H, W) of positive integers; got {describe(shape)}"
        )
    height = as_int(shape[0], f"{name}[0] (height)", minimum=1)
    width = as_int(shape[1], f"{name}[1] (width)", minimum=1)
    return height, width


def as_pixels(pixels: Any, name: str = "pixels") -> np.ndarray:
    """Validate an integer (K, 2) array of (x, y) pixel coordinates."""
    array = np.asarray(pixels)
    if array.size == 0:
        array = array.reshape(0, 2).astype(np.int64)
    if array.dtype == bool or not np.issubdtype(array.dtype, np.integer):
        raise TypeError(
            f"{name} must be an integer (K, 2) array of (x, y) pixels; got "
            f"{describe(pixels)} (round or floor float coordinates first, "
            "e.g. with course.raster.nearest_pixels)"
        )
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"{name} must have shape (K, 2), one (x, y) per row; got {array.shape}")
    return array


def as_image(image: Any, name: str = "image", copy: bool = True) -> np.ndarray:
    """A float image ``(H, W)`` or ``(H, W, 3)`` with finite values in [0, 1]."""
    array = as_float_array(image, name) if copy or not isinstance(image, np.ndarray) else image
    if not (array.ndim == 2 or (array.ndim == 3 and array.shape[2] == 3)):
        raise ValueError(
            f"{name} must be a gray (H, W) or RGB (H, W, 3) image; got shape {array.shape}"
        )
    if array.shape[0] == 0 or array.shape[1] == 0:
        raise ValueError(f"{name} must not be empty; got shape {array.shape}")
    require_finite(array, name)
    if array.min() < 0 or array.max() > 1:
        raise ValueError(
            f"{name} values must lie in [0, 1]; got values from {array.min():g} to "
            f"{array.max():g} (divide uint8 images by 255)"
        )
    return array


def as_gray(image: Any, name: str = "gray") -> np.ndarray:
    """A gray float image ``(H, W)`` with values in [0, 1]."""
    array = as_image(image, name)
    if array.ndim != 2:
        raise ValueError(
            f"{name} must be a gray (H, W) image; got shape {array.shape} "
            "(convert colour images with course.images.to_gray)"
        )
    return array


def as_choice(value: Any, name: str, choices: tuple[str, ...] | list[str]) -> str:
    """One of a fixed set of strings."""
    if not isinstance(value, str) or value not in choices:
        options = ", ".join(repr(c) for c in choices)
        raise ValueError(f"{name} must be one of {options}; got {value!r}")
    return value


def as_rng(rng: Any, name: str = "rng") -> np.random.Generator:
    """A numpy Generator; None gives ``default_rng(0)``, so results are reproducible."""
    if rng is None:
        return np.random.default_rng(0)
    if not isinstance(rng, np.random.Generator):
        raise TypeError(
            f"{name} must be a numpy.random.Generator, e.g. numpy.random.default_rng(0); "
            f"got {describe(rng)}"
        )
    return rng
