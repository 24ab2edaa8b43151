"""The inputs of an edit, checked once: the images, the foreground's offset, the mask.

:func:`clone_inputs` checks what :func:`course.poisson.seamless_clone` and the functions
that set up a clone take (the background, the foreground, its offset and a mask), and
:func:`inpaint_inputs` what :func:`course.poisson.inpaint` takes (the image and its hole);
every message names the parameter. :mod:`course.poisson.problem` builds the Poisson
problem from what they return.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import as_float_array, as_image, as_int, describe, require_finite
from course.i18n import _

__all__ = ["clone_inputs", "inpaint_inputs"]


def clone_inputs(
    background: Any, foreground: Any, offset: Any, mask: Any
) -> tuple[np.ndarray, np.ndarray, tuple[int, int], np.ndarray | None]:
    """Validate seamless_clone's inputs once; every message names the parameter."""
    _same_kind_of_dtype(background, foreground)
    background = _as_float_image(background, "background")
    foreground = _as_float_image(foreground, "foreground")
    if background.ndim != foreground.ndim:
        kinds = {2: _("gray"), 3: "RGB"}
        raise ValueError(
            _(
                "foreground is {foreground_kind} (shape {foreground_shape}) but background is "
                "{background_kind} "
                "(shape {background_shape}): both must be gray or both RGB (course.images.to_gray "
                "converts)"
            ).format(
                foreground_kind=kinds[foreground.ndim],
                foreground_shape=foreground.shape,
                background_kind=kinds[background.ndim],
                background_shape=background.shape,
            )
        )
    x, y = _as_offset(offset)
    height, width = foreground.shape[:2]
    full_height, full_width = background.shape[:2]
    if not (0 <= x and x + width <= full_width and 0 <= y and y + height <= full_height):
        raise ValueError(
            _(
                "foreground of shape {foreground_size} at offset (x, y) = ({x}, {y}) does not fit "
                "inside background of shape {background_size}: it would cover columns {x} to "
                "{right} "
                "and rows {y} to {bottom}; the background has columns 0 to {full_width} and rows 0 "
                "to "
                "{full_height}"
            ).format(
                foreground_size=foreground.shape[:2],
                x=x,
                y=y,
                background_size=background.shape[:2],
                right=x + width - 1,
                bottom=y + height - 1,
                full_width=full_width - 1,
                full_height=full_height - 1,
            )
        )
    if height < 3 or width < 3:
        raise ValueError(
            _(
                "foreground must be at least 3 x 3 pixels: its outer ring is the boundary and the "
                "region lies inside it; got shape {foreground_size}"
            ).format(foreground_size=foreground.shape[:2])
        )
    if mask is not None:
        mask = _as_mask(mask, "mask", (height, width), _("the foreground's (h, w)"))
        ring = mask.copy()
        ring[1:-1, 1:-1] = False
        if ring.any():
            rows, columns = np.nonzero(ring)
            raise ValueError(
                _(
                    "mask must be False on the foreground's outer ring (its first and last rows "
                    "and columns), which is the boundary and takes the background's values; got "
                    "{size} masked pixels there, e.g. (x, y) = ({columns}, {rows})"
                ).format(size=rows.size, columns=columns[0], rows=rows[0])
            )
    return background, foreground, (x, y), mask


def inpaint_inputs(image: Any, mask: Any) -> tuple[np.ndarray, np.ndarray]:
    """Validate inpaint's inputs once: the image, and a hole with known pixels all around it.

    Examples
    --------
    >>> hole = np.zeros((4, 4), bool); hole[1:3, 2] = True
    >>> [array.shape for array in inpaint_inputs(np.zeros((4, 4)), hole)]
    [(4, 4), (4, 4)]
    """
    image = as_image(image, "image")
    mask = _as_mask(mask, "mask", image.shape[:2], _("the image's (H, W)"))
    rows, columns = np.nonzero(mask)
    height, width = mask.shape
    edge = (rows == 0) | (rows == height - 1) | (columns == 0) | (columns == width - 1)
    if edge.any():
        where = (int(columns[edge][0]), int(rows[edge][0]))
        raise ValueError(
            _(
                "mask touches the image border, e.g. at (x, y) = {where}: inpaint needs known "
                "pixels all around the hole, so leave the first and last rows and columns unmasked "
                "(or pad the image)"
            ).format(where=where)
        )
    return image, mask


def _as_float_image(image: Any, name: str) -> np.ndarray:
    """:func:`as_image`, checking a float64 array where it lies instead of copying it.

    Nothing here writes to the images (the result is a new array), and the
    copies and passes of the general check cost a 512 x 512 clone a tenth of
    its time. An image of the right shape whose minimum and maximum lie in
    [0, 1] is finite (NaN would be the minimum); anything else goes through
    the general check, for its message.
    """
    if (
        isinstance(image, np.ndarray)
        and image.dtype == np.float64
        and (image.ndim == 2 or (image.ndim == 3 and image.shape[2] == 3))
        and image.shape[0] > 0
        and image.shape[1] > 0
        and 0.0 <= image.min()
        and image.max() <= 1.0
    ):
        return image
    return as_image(image, name)


def _same_kind_of_dtype(background: Any, foreground: Any) -> None:
    kinds = [np.asarray(image).dtype for image in (background, foreground)]
    floating = [np.issubdtype(kind, np.floating) for kind in kinds]
    if floating[0] != floating[1]:
        raise TypeError(
            _(
                "foreground has dtype {foreground_dtype} but background has dtype "
                "{background_dtype}: convert both to "
                "float images in [0, 1] (a uint8 image / 255)"
            ).format(foreground_dtype=kinds[1], background_dtype=kinds[0])
        )


def _as_offset(offset: Any) -> tuple[int, int]:
    if isinstance(offset, (str, bytes)) or not hasattr(offset, "__len__") or len(offset) != 2:
        raise ValueError(
            _(
                "offset must be a pair (x, y) of integers, the column and row of the foreground's "
                "top-left pixel in the background; got {offset}"
            ).format(offset=describe(offset))
        )
    return as_int(offset[0], "offset[0] (x)"), as_int(offset[1], "offset[1] (y)")


def _as_mask(mask: Any, name: str, shape: tuple[int, int], what: str) -> np.ndarray:
    array = np.asarray(mask)
    if array.dtype != bool:
        values = as_float_array(array, name)
        require_finite(values, name)
        if not np.isin(values, (0.0, 1.0)).all():
            raise ValueError(
                _(
                    "{name} must be boolean (or 0 and 1); got values from {lowest:g} to {highest:g}"
                ).format(name=name, lowest=values.min(), highest=values.max())
            )
        array = values == 1.0
    if array.shape != shape:
        raise ValueError(
            _("{name} must have shape {shape}, {what}; got shape {array_shape}").format(
                name=name, shape=shape, what=what, array_shape=array.shape
            )
        )
    if not array.any():
        raise ValueError(
            _("{name} is empty: it selects no pixel, so there is nothing to solve").format(
                name=name
            )
        )
    return array.copy()
