"""Error measures: how far an image is from a reference, in one number.

The one home of the measures every lesson reports: anti-aliased curves
against the exact coverage, supersampled images against the exact box
filter, dithered images after the eye's blur. Images are gray ``(H, W)`` or
RGB ``(H, W, 3)`` float arrays in [0, 1] of the same shape; the measures themselves
are array code in ``course._metrics``, for callers that checked their images once.
"""

from __future__ import annotations

from typing import Any

from course._metrics import max_difference, rms_difference
from course._validate import as_image_pair

__all__ = ["max_error", "rmse"]


def rmse(image: Any, reference: Any) -> float:
    """Root-mean-square difference over every pixel (and channel) of the image.

    Examples
    --------
    >>> rmse([[0.0, 1.0]], [[0.0, 0.5]])
    0.3535533905932738
    """
    return rms_difference(*as_image_pair(image, reference))


def max_error(image: Any, reference: Any) -> float:
    """Largest absolute difference at any pixel (and channel).

    Examples
    --------
    >>> max_error([[0.0, 1.0]], [[0.25, 0.5]])
    0.5
    """
    return max_difference(*as_image_pair(image, reference))
