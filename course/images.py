"""Sample images: matplotlib's bundled photograph and procedural test images.

Every image is a float array in [0, 1], gray (H, W) or RGB (H, W, 3). Nothing
is downloaded: photographs come from matplotlib's own sample data.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib import cbook

from course._validate import as_image

__all__ = ["photograph", "to_gray"]

# ITU-R BT.601 luma weights, as OpenCV's cvtColor(..., COLOR_RGB2GRAY).
_LUMA = np.array([0.299, 0.587, 0.114])


def photograph() -> np.ndarray:
    """Grace Hopper, 600 x 512 RGB, from matplotlib's sample data.

    Examples
    --------
    >>> image = photograph()
    >>> image.shape, image.dtype, bool(0 <= image.min() <= image.max() <= 1)
    ((600, 512, 3), dtype('float64'), True)
    """
    import matplotlib.image

    with cbook.get_sample_data("grace_hopper.jpg") as file:
        pixels = matplotlib.image.imread(file, format="jpg")
    return pixels[..., :3].astype(float) / 255.0


def to_gray(image: Any) -> np.ndarray:
    """Luma of an RGB image (BT.601 weights); a gray image is returned as a copy.

    Examples
    --------
    >>> to_gray(np.ones((2, 2, 3)))
    array([[1., 1.],
           [1., 1.]])
    """
    array = as_image(image)
    if array.ndim == 2:
        return array
    return np.clip(array @ _LUMA, 0.0, 1.0)


# --- lessons 06-07: dithering and filtering ---------------------------------

__all__ += ["ramp"]


def ramp(width: int = 256, height: int = 32) -> np.ndarray:
    """A horizontal gray ramp, black to white: pixel x has the value (x + 0.5) / width.

    Every column has its own level, so a dithering method's tone (or its
    failure to keep it) shows along the ramp.

    Examples
    --------
    >>> ramp(4, 2)
    array([[0.125, 0.375, 0.625, 0.875],
           [0.125, 0.375, 0.625, 0.875]])
    """
    from course._validate import as_int

    width = as_int(width, "width", minimum=1)
    height = as_int(height, "height", minimum=1)
    return np.tile((np.arange(width) + 0.5) / width, (height, 1))
