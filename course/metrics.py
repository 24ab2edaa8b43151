"""Error measures: how far an image is from a reference, in one number.

The one home of the measures every lesson reports: anti-aliased curves
against the exact coverage, supersampled images against the exact box
filter, dithered images after the eye's blur. Images are gray ``(H, W)`` or
RGB ``(H, W, 3)`` float arrays in [0, 1] of the same shape.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import as_image
from course.i18n import _

__all__ = ["max_error", "rmse"]


def _pair(image: Any, reference: Any) -> tuple[np.ndarray, np.ndarray]:
    first = as_image(image, "image", copy=False)
    second = as_image(reference, "reference", copy=False)
    if first.shape != second.shape:
        raise ValueError(
            _(
                "image and reference must have the same shape; got {first_shape} and {second_shape}"
            ).format(first_shape=first.shape, second_shape=second.shape)
        )
    return first, second


def rmse(image: Any, reference: Any) -> float:
    """Root-mean-square difference over every pixel (and channel) of the image.

    Examples
    --------
    >>> rmse([[0.0, 1.0]], [[0.0, 0.5]])
    0.3535533905932738
    """
    first, second = _pair(image, reference)
    return float(np.sqrt(np.mean((first - second) ** 2)))


def max_error(image: Any, reference: Any) -> float:
    """Largest absolute difference at any pixel (and channel).

    Examples
    --------
    >>> max_error([[0.0, 1.0]], [[0.25, 0.5]])
    0.5
    """
    first, second = _pair(image, reference)
    return float(np.abs(first - second).max())
