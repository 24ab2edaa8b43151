"""The window's arrays laid out: a clipped window, channels first and back, a mask per channel.

Kernels shared by :mod:`course.poisson.problem` (the problem's planes, its window of
the background, the paste) and :mod:`course.poisson.windows` (the checked
:func:`~course.poisson.windows.window_at` and :func:`~course.poisson.windows.image_of`).
Both check their arrays before they call these: finite floats, ``(h, w)`` or ``(h, w, C)``
images, ``(C, h, w)`` planes, a corner and a shape of integers.

Unchecked kernels: this module trusts its callers and checks no input
(``UNCHECKED = True``, which the fuzz test reads).
"""

from __future__ import annotations

import numpy as np

__all__ = ["channels_back", "channels_first", "clipped_window", "mask_for"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def clipped_window(
    image: np.ndarray, corner: tuple[int, int], shape: tuple[int, int]
) -> np.ndarray:
    """The ``shape`` window of ``image`` at ``corner = (x, y)``: a view, clipped to the image."""
    x, y = corner
    top, left = max(y, 0), max(x, 0)
    bottom = max(min(y + shape[0], image.shape[0]), top)
    right = max(min(x + shape[1], image.shape[1]), left)
    return image[top:bottom, left:right]


def channels_first(image: np.ndarray) -> np.ndarray:
    """``(h, w)`` or ``(h, w, C)`` to channels first, ``(C, h, w)``, as floats."""
    if image.ndim == 2:
        return image[None].astype(float)
    return np.ascontiguousarray(np.moveaxis(image, -1, 0), dtype=float)


def channels_back(planes: np.ndarray, like: np.ndarray) -> np.ndarray:
    """Channels first, ``(C, h, w)``, back to the layout of ``like``."""
    if like.ndim == 2:
        return planes[0].copy()
    return np.ascontiguousarray(np.moveaxis(planes, 0, -1))


def mask_for(mask: np.ndarray, like: np.ndarray) -> np.ndarray:
    """The ``(h, w)`` mask, with a channel axis when ``like`` has one, to select from it."""
    return mask if like.ndim == 2 else mask[..., None]
