"""Arrays and images: float arrays, finite and bounded values, pixels, images, kernels.

Part of :mod:`course._validate`, which re-exports every name. An array checked in
several steps (numbers, then finite, then bounded) is checked by one call
(:func:`as_finite_array`, :func:`as_finite_arrays`, :func:`as_real`, :func:`as_kernel`),
so that a function validates each argument once.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import limits
from course._validate.scalars import describe
from course.i18n import N_, _

__all__ = [
    "as_finite_array",
    "as_finite_arrays",
    "as_float_array",
    "as_gray",
    "as_image",
    "as_image_like",
    "as_image_pair",
    "as_kernel",
    "as_pixels",
    "as_real",
    "require_finite",
    "require_within",
]


def as_float_array(value: Any, name: str) -> np.ndarray:
    """A float64 copy of ``value``; TypeError unless it holds real numbers."""
    try:
        array = np.array(value)
    except ValueError as error:  # ragged nested lists
        raise ValueError(
            _(
                "{name} must be a rectangular array of numbers; got a ragged sequence ({error})"
            ).format(name=name, error=error)
        ) from None
    if array.dtype == bool or not (
        np.issubdtype(array.dtype, np.integer) or np.issubdtype(array.dtype, np.floating)
    ):
        if isinstance(value, np.ndarray):
            message = _("{name} must hold real numbers; got {value}")
        else:
            message = _("{name} must hold real numbers; got {value} with dtype {dtype}")
        raise TypeError(message.format(name=name, value=describe(value), dtype=array.dtype))
    return array.astype(float, copy=True)


def require_finite(array: np.ndarray, name: str) -> None:
    """ValueError naming the first NaN or infinite entry."""
    bad = ~np.isfinite(array)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        if array.ndim:
            message = _("{name} must be finite; got {value} at index {index}")
        else:
            message = _("{name} must be finite; got {value}")
        raise ValueError(message.format(name=name, value=array[bad].flat[0], index=index))


def require_within(
    array: np.ndarray, name: str, bound: float, what: str = N_("coordinates")
) -> None:
    """ValueError unless every entry of ``array`` lies within ``[-bound, bound]``."""
    if array.size and np.abs(array).max() > bound:
        worst = array.flat[int(np.abs(array).argmax())]
        raise ValueError(
            _("{name} {what} must lie within +-{bound:g}; got {worst:g}").format(
                name=name, what=_(what), bound=bound, worst=worst
            )
        )


def as_finite_array(
    value: Any,
    name: str,
    bound: float | None = None,
    what: str = N_("coordinates"),
    shape: Callable[[np.ndarray], np.ndarray | None] | None = None,
) -> np.ndarray:
    """:func:`as_float_array`, then ``shape`` (the caller's check of the array's shape,
    which raises its own error), then :func:`require_finite`, then (with ``bound``)
    :func:`require_within`: a float copy of finite real numbers, in one check.

    A ``shape`` that returns an array (a part of the one it is given: the window a caller
    reads) has only that part required finite and within ``bound``, and it is returned.

    Examples
    --------
    >>> as_finite_array([1, 2], "x", bound=10).tolist()
    [1.0, 2.0]
    """
    array = as_float_array(value, name)
    used = shape(array) if shape is not None else None
    if used is not None:
        array = used
    require_finite(array, name)
    if bound is not None:
        require_within(array, name, bound, what)
    return array


def as_finite_arrays(*named: tuple[Any, str]) -> list[np.ndarray]:
    """Several ``(value, name)`` arrays checked together: each converted by
    :func:`as_float_array`, then each required finite, in the order given.

    Examples
    --------
    >>> [array.tolist() for array in as_finite_arrays(([1, 2], "x"), (3, "y"))]
    [[1.0, 2.0], 3.0]
    """
    arrays = [as_float_array(value, name) for value, name in named]
    for index, array in enumerate(arrays):
        require_finite(array, named[index][1])
    return arrays


def as_real(value: Any, name: str) -> float:
    """A finite real number, read as :func:`as_float_array` reads it.

    Examples
    --------
    >>> as_real(0.5, "sample_offset")
    0.5
    """
    number = float(as_float_array(value, name))
    require_finite(np.asarray(number), name)
    return number


def as_kernel(kernel: Any) -> np.ndarray:
    """A 3 x 3 filter kernel: a float copy of finite real numbers within ``limits.LARGEST``.

    Examples
    --------
    >>> as_kernel([[0, 0, 0], [0, 1, 0], [0, 0, 0]])[1]
    array([0., 1., 0.])
    """
    array = as_float_array(kernel, "kernel")
    if array.shape != (3, 3):
        raise ValueError(
            _("kernel must be a 3 x 3 array; got shape {array_shape}").format(
                array_shape=array.shape
            )
        )
    require_finite(array, "kernel")
    require_within(array, "kernel", limits.LARGEST, "values")
    return array


def as_pixels(pixels: Any, name: str = "pixels") -> np.ndarray:
    """Validate an integer (K, 2) array of (x, y) pixel coordinates."""
    array = np.asarray(pixels)
    if array.size == 0:
        array = array.reshape(0, 2).astype(np.int64)
    if array.dtype == bool or not np.issubdtype(array.dtype, np.integer):
        raise TypeError(
            _(
                "{name} must be an integer (K, 2) array of (x, y) pixels; got {value} (round or "
                "floor float coordinates first, e.g. with course.raster.nearest_pixels)"
            ).format(name=name, value=describe(pixels))
        )
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(
            _("{name} must have shape (K, 2), one (x, y) per row; got {shape}").format(
                name=name, shape=array.shape
            )
        )
    return array


def as_image(image: Any, name: str = "image", copy: bool = True) -> np.ndarray:
    """A float image ``(H, W)`` or ``(H, W, 3)`` with finite values in [0, 1]."""
    keep = not copy and isinstance(image, np.ndarray) and image.dtype.kind == "f"
    array = image if keep else as_float_array(image, name)
    if not (array.ndim == 2 or (array.ndim == 3 and array.shape[2] == 3)):
        raise ValueError(
            _("{name} must be a gray (H, W) or RGB (H, W, 3) image; got shape {shape}").format(
                name=name, shape=array.shape
            )
        )
    if array.shape[0] == 0 or array.shape[1] == 0:
        raise ValueError(
            _("{name} must not be empty; got shape {shape}").format(name=name, shape=array.shape)
        )
    if array.shape[0] * array.shape[1] > limits.MAX_PIXELS:
        raise ValueError(
            _("{name} must have at most {limit} pixels; got shape {shape}").format(
                name=name, limit=limits.MAX_PIXELS, shape=array.shape
            )
        )
    low, high = array.min(), array.max()
    # NaN and inf fail this one test too: then say which of them it was.
    if not (low >= 0 and high <= 1):
        require_finite(array, name)
        raise ValueError(
            _(
                "{name} values must lie in [0, 1]; got values from {low:g} to {high:g} (divide "
                "uint8 images by 255)"
            ).format(name=name, low=low, high=high)
        )
    return array


def as_gray(image: Any, name: str = "gray", copy: bool = True) -> np.ndarray:
    """A gray float image ``(H, W)`` in [0, 1]; ``copy=False`` as in :func:`as_image`."""
    array = as_image(image, name, copy)
    if array.ndim != 2:
        raise ValueError(
            _(
                "{name} must be a gray (H, W) image; got shape {shape} (convert colour images "
                "with course.images.to_gray)"
            ).format(name=name, shape=array.shape)
        )
    return array


def as_image_pair(image: Any, reference: Any) -> tuple[np.ndarray, np.ndarray]:
    """Two images of the same shape, by :func:`as_image` (no copy of a float array).

    Examples
    --------
    >>> [array.shape for array in as_image_pair([[0.0, 1.0]], [[0.5, 0.5]])]
    [(1, 2), (1, 2)]
    """
    first = as_image(image, "image", copy=False)
    second = as_image(reference, "reference", copy=False)
    _require_same_shape(first, second)
    return first, second


def as_image_like(image: Any, reference: np.ndarray) -> np.ndarray:
    """:func:`as_image_pair` against a ``reference`` already checked: the image alone.

    Examples
    --------
    >>> as_image_like([[0.0, 1.0]], np.zeros((1, 2))).shape
    (1, 2)
    """
    first = as_image(image, "image", copy=False)
    _require_same_shape(first, reference)
    return first


def _require_same_shape(first: np.ndarray, second: np.ndarray) -> None:
    if first.shape != second.shape:
        raise ValueError(
            _(
                "image and reference must have the same shape; got {first_shape} and {second_shape}"
            ).format(first_shape=first.shape, second_shape=second.shape)
        )
