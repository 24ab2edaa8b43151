"""Painting behind :mod:`course.raster.canvas`: pure array code on validated input.

Nothing here checks its input (``UNCHECKED = True``): ``pixels`` is an integer
``(K, 2)`` array of (x, y), ``shape`` a canvas ``(H, W)`` or ``(H, W, C)`` of
positive integers, ``value`` a float colour (a number, or an RGB triple for an
RGB image) and ``strength`` float weights in [0, 1], as
:func:`course.raster.canvas.paint` makes sure before it calls :func:`paint_into`.
Rasterizers, splats and renders that made their pixels themselves call these
directly, so that nothing is checked twice.
"""

from __future__ import annotations

import numpy as np

__all__ = ["on_canvas", "paint_into", "painted_canvas"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def on_canvas(pixels: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """Boolean mask of the (x, y) pixels that lie on a canvas of this shape.

    Examples
    --------
    >>> on_canvas(np.array([[0, 0], [-1, 0], [2, 1], [1, 2]]), (2, 3))
    array([ True, False,  True, False])
    """
    height, width = shape[0], shape[1]
    x, y = pixels[:, 0], pixels[:, 1]
    return (x >= 0) & (x < width) & (y >= 0) & (y < height)


def paint_into(
    image: np.ndarray, coordinates: np.ndarray, value: np.ndarray, strength: np.ndarray, mode: str
) -> np.ndarray:
    """Paint checked arguments into ``image``, in place; pixels off the canvas are dropped."""
    strength = np.broadcast_to(strength, (len(coordinates),))
    keep = on_canvas(coordinates, image.shape)
    x, y = coordinates[keep, 0], coordinates[keep, 1]
    strength = strength[keep]
    if image.ndim == 3:
        strength = strength[:, None]
    if mode == "add":
        # Contributions are >= 0, so clipping the sum once equals saturating
        # after every addition. Only the painted pixels can have passed 1:
        # clip those, not the whole image (O(pixels), and nothing else touched).
        np.add.at(image, (y, x), strength * value)
        image[y, x] = np.minimum(image[y, x], 1.0)
    elif mode == "max":
        np.maximum.at(image, (y, x), strength * value)
    else:
        # Blending the same color k times leaves color + (old - color) * prod(1 - w),
        # so one product per distinct painted pixel is enough.
        flat, slot = np.unique(y * image.shape[1] + x, return_inverse=True)
        remaining = np.ones((len(flat), *image.shape[2:]))
        np.multiply.at(remaining, slot.ravel(), 1.0 - strength)
        rows, columns = np.divmod(flat, image.shape[1])
        image[rows, columns] = value + (image[rows, columns] - value) * remaining
    return image


def painted_canvas(
    shape: tuple[int, int],
    coordinates: np.ndarray,
    value: np.ndarray,
    strength: np.ndarray,
    mode: str,
) -> np.ndarray:
    """A new black canvas of ``shape = (H, W)`` (times the colour's channels), painted.

    Examples
    --------
    >>> painted_canvas((1, 3), np.array([[1, 0]]), np.array(1.0), np.array(0.5), "add")
    array([[0. , 0.5, 0. ]])
    """
    image = np.zeros((*shape, *value.shape))
    return paint_into(image, coordinates, value, strength, mode)
