"""Windows and channel layouts of an edit's images, checked.

:func:`window_in` cuts a problem's window out of an image placed at a corner (the
foreground, for a clone); :func:`window_at` cuts any window, clipped to the image;
:func:`planes_of` and :func:`image_of` turn an image to channels first, the layout of
:mod:`course.poisson.solvers`, and back. Each checks its input (finite, its shape) and
names the parameter. :mod:`course.poisson` and lesson 08's checkers use them; the
unchecked kernels behind them are in :mod:`course.poisson._layout`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import (
    as_corner,
    as_finite_array,
    as_float_array,
    as_shape,
    describe,
    require_finite,
)
from course.i18n import _
from course.poisson._layout import channels_back, clipped_window
from course.poisson.problem import PoissonProblem, as_problem

__all__ = ["MAX_CHANNELS", "image_of", "planes_of", "window_at", "window_in"]

#: The most channels an image's window has: gray, gray and alpha, RGB, RGBA.
MAX_CHANNELS = 4


def window_in(problem: PoissonProblem, image: Any, corner: Any) -> np.ndarray:
    """The problem's window cut from ``image``, whose top-left pixel sits at ``corner``.

    ``corner = (x, y)`` places ``image`` in the problem's picture (the
    foreground's offset, for a clone); the window must lie inside ``image``.

    Examples
    --------
    >>> from course.poisson.problem import clone_problem
    >>> problem = clone_problem(np.zeros((5, 5)), np.ones((3, 3)), (1, 2))
    >>> window_in(problem, np.ones((3, 3)), (1, 2)).shape
    (3, 3)
    """
    problem = as_problem(problem)
    array = as_float_array(image, "image")
    x0, y0 = as_corner(corner, "corner")
    x = problem.corner[0] - x0
    y = problem.corner[1] - y0
    height, width = problem.region.shape
    if array.ndim != problem.values.ndim or array.shape[2:] != problem.values.shape[2:]:
        raise ValueError(
            _(
                "image must have the layout of the problem's values {values_shape}; got shape "
                "{array_shape}"
            ).format(values_shape=problem.values.shape, array_shape=array.shape)
        )
    if not (0 <= x and x + width <= array.shape[1] and 0 <= y and y + height <= array.shape[0]):
        raise ValueError(
            _(
                "image of shape {array_size} at corner (x, y) = ({x0}, {y0}) does not hold the "
                "problem's window, {height} x {width} pixels at ({corner_x}, {corner_y})"
            ).format(
                array_size=array.shape[:2],
                x0=x0,
                y0=y0,
                height=height,
                width=width,
                corner_x=problem.corner[0],
                corner_y=problem.corner[1],
            )
        )
    window = array[y : y + height, x : x + width]
    require_finite(window, "image")
    return window


def window_at(image: Any, corner: Any, shape: Any) -> np.ndarray:
    """The ``shape`` window of ``image`` whose top-left pixel is ``corner = (x, y)``.

    The part of the window off the image is clipped, never wrapped around:
    the result is a copy of the pixels the window and the image share (empty
    when they share none). ``image`` is a non-empty ``(H, W)`` or ``(H, W, C)`` array
    of at most :data:`MAX_CHANNELS` channels: a ValueError names it otherwise (an
    empty image, or an extra axis such as ``(1, H, W)``, would give an empty window).

    Examples
    --------
    >>> image = np.arange(16.0).reshape(4, 4)
    >>> window_at(image, (1, 2), (2, 2))
    array([[ 9., 10.],
           [13., 14.]])
    >>> window_at(image, (-1, -1), (2, 3))   # one row and two columns on the image
    array([[0., 1.]])
    >>> window_at(np.zeros((1, 6, 6)), (1, 2), (2, 2))
    Traceback (most recent call last):
    ...
    ValueError: image must have at most 4 channels (its last axis); got shape (1, 6, 6): an \
extra axis?
    """

    def the_window(array: np.ndarray) -> np.ndarray:
        _require_image_layout(array)
        if array.ndim == 3 and array.shape[2] > MAX_CHANNELS:
            raise ValueError(
                _(
                    "image must have at most {most} channels (its last axis); got shape "
                    "{array_shape}: an extra axis?"
                ).format(most=MAX_CHANNELS, array_shape=array.shape)
            )
        return clipped_window(array, as_corner(corner, "corner"), as_shape(shape, "shape"))

    return as_finite_array(image, "image", shape=the_window).copy()


def planes_of(image: Any) -> np.ndarray:
    """``(h, w)`` or ``(h, w, C)`` to channels first, ``(C, h, w)``: a finite float copy.

    Examples
    --------
    >>> planes_of(np.zeros((2, 3, 3))).shape, planes_of(np.zeros((2, 3))).shape
    ((3, 2, 3), (1, 2, 3))
    """
    array = as_finite_array(image, "image", shape=_require_image_layout)
    return array[None] if array.ndim == 2 else np.ascontiguousarray(np.moveaxis(array, -1, 0))


def _require_image_layout(array: np.ndarray) -> None:
    if array.ndim not in (2, 3) or 0 in array.shape:
        raise ValueError(
            _(
                "image must be a non-empty (h, w) or (h, w, C) array; got shape {array_shape}"
            ).format(array_shape=array.shape)
        )


def image_of(planes: Any, like: Any) -> np.ndarray:
    """Back from channels first, ``(C, h, w)``, to the layout of ``like``: a finite copy.

    Examples
    --------
    >>> image_of(np.zeros((3, 2, 4)), np.zeros((2, 4, 3))).shape
    (2, 4, 3)
    """

    def require_layout_of_like(array: np.ndarray) -> None:
        if array.ndim != 3 or 0 in array.shape:
            raise ValueError(
                _("planes must be a non-empty (C, h, w) array; got shape {array_shape}").format(
                    array_shape=array.shape
                )
            )
        layout = np.shape(like) if isinstance(like, np.ndarray) else None
        if layout is None or len(layout) not in (2, 3):
            raise TypeError(
                _("like must be an (h, w) or (h, w, C) array; got {like}").format(
                    like=describe(like)
                )
            )
        expected = (1, *layout) if len(layout) == 2 else (layout[2], *layout[:2])
        if array.shape != expected:
            raise ValueError(
                _(
                    "planes must have shape {expected}, channels first, for like of shape "
                    "{layout}; got {array_shape}"
                ).format(expected=expected, layout=layout, array_shape=array.shape)
            )

    return channels_back(as_finite_array(planes, "planes", shape=require_layout_of_like), like)
