"""Canvases: blank images, the one function that paints pixels, zoom crops.

Images are float arrays in [0, 1], gray ``(H, W)`` or RGB ``(H, W, 3)``,
indexed ``image[y, x]``. Rasterizers elsewhere return pixel coordinates;
:func:`paint` is the only function that writes them into an image. It clips:
a pixel outside the canvas is dropped, never wrapped around to the other side
as a negative numpy index would be.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import (
    as_choice,
    as_float_array,
    as_image,
    as_int,
    as_pixels,
    as_point,
    as_shape,
    as_unit,
    describe,
    require_finite,
)
from course.i18n import _

__all__ = [
    "PAINT_MODES",
    "blank",
    "crop",
    "crop_extent",
    "inside",
    "paint",
    "painted",
    "yellow_fraction",
]

PAINT_MODES = ("add", "max", "over")


def blank(shape: Any, color: Any = 0.0) -> np.ndarray:
    """A new image of ``shape = (H, W)`` filled with ``color``.

    A scalar color gives a gray ``(H, W)`` image, an RGB triple an
    ``(H, W, 3)`` image.

    Examples
    --------
    >>> blank((2, 3))
    array([[0., 0., 0.],
           [0., 0., 0.]])
    >>> blank((1, 2), (1, 0, 0)).shape
    (1, 2, 3)
    """
    height, width = as_shape(shape)
    value = _as_color(color, "color")
    return np.broadcast_to(value, (height, width, *value.shape)).copy()


def _as_color(color: Any, name: str, channels: int | None = None) -> np.ndarray:
    value = as_float_array(color, name)
    if value.shape not in ((), (3,)):
        raise ValueError(
            _("{name} must be a number or an RGB triple; got shape {value_shape}").format(
                name=name, value_shape=value.shape
            )
        )
    if not np.all(np.isfinite(value)) or value.min() < 0 or value.max() > 1:
        raise ValueError(
            _("{name} values must be finite and in [0, 1]; got {value}").format(
                name=name, value=value.tolist()
            )
        )
    if channels == 1 and value.shape == (3,):
        raise ValueError(
            _("{name} must be a number for a gray image; got an RGB triple").format(name=name)
        )
    return value


def inside(pixels: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """Boolean mask of the (x, y) pixels that lie on a canvas of this shape.

    Examples
    --------
    >>> inside(np.array([[0, 0], [-1, 0], [2, 1], [1, 2]]), (2, 3))
    array([ True, False,  True, False])
    """
    coordinates = as_pixels(pixels)
    if not isinstance(shape, (tuple, list)) or len(shape) not in (2, 3):
        raise ValueError(
            _("shape must be (H, W) or (H, W, C); got {shape}").format(shape=describe(shape))
        )
    height, width = as_shape(tuple(shape[:2]))
    x, y = coordinates[:, 0], coordinates[:, 1]
    return (x >= 0) & (x < width) & (y >= 0) & (y < height)


def paint(
    image: np.ndarray,
    pixels: Any,
    color: Any,
    weight: Any = 1.0,
    mode: str = "add",
) -> np.ndarray:
    """Write ``color`` into ``image`` at ``pixels``, in place; the one painter.

    Parameters
    ----------
    image : ndarray, float, (H, W) or (H, W, 3)
        Modified in place, and returned for convenience.
    pixels : int array, shape (K, 2)
        (x, y) pixel coordinates; those off the canvas are dropped.
    color : float or RGB triple in [0, 1]
    weight : float or array, shape (K,)
        Per-pixel strength in [0, 1] (anti-aliasing coverage).
    mode : {"add", "max", "over"}
        ``"add"``: ``image + weight * color``, saturating at 1, like the
        handouts' ``Vec3b +=``; repeated pixels add up, so brightness depends
        on how many samples land in a pixel. ``"max"``: keep the brighter.
        ``"over"``: blend ``image * (1 - weight) + color * weight``, applied
        once per repeated pixel, in order.

    Examples
    --------
    >>> image = blank((2, 4))
    >>> _ = paint(image, np.array([[0, 0], [3, 1], [-1, 0], [4, 1]]), 1.0)
    >>> image
    array([[1., 0., 0., 0.],
           [0., 0., 0., 1.]])
    >>> _ = paint(image, np.array([[1, 0], [1, 0]]), 0.5, weight=0.8)
    >>> image[0, 1]
    np.float64(0.8)
    """
    if not isinstance(image, np.ndarray) or not np.issubdtype(image.dtype, np.floating):
        raise TypeError(
            _(
                "image must be a float numpy array (H, W) or (H, W, 3) to paint into; got {image}"
            ).format(image=describe(image))
        )
    if not (image.ndim == 2 or (image.ndim == 3 and image.shape[2] == 3)):
        raise ValueError(
            _("image must have shape (H, W) or (H, W, 3); got {image_shape}").format(
                image_shape=image.shape
            )
        )
    require_finite(image, "image")
    coordinates, value, strength, mode = _paint_arguments(
        pixels, color, weight, mode, channels=1 if image.ndim == 2 else 3
    )
    return _paint_into(image, coordinates, value, strength, mode)


def painted(
    shape: Any, pixels: Any, color: Any = 1.0, weight: Any = 1.0, mode: str = "add"
) -> np.ndarray:
    """A new black canvas of ``shape = (H, W)`` with ``pixels`` painted: :func:`paint` on
    :func:`blank`, without checking an image it has just made (a full pass over it).

    Examples
    --------
    >>> painted((2, 3), np.array([[1, 0], [1, 0], [9, 9]]), 1.0, 0.75)
    array([[0., 1., 0.],
           [0., 0., 0.]])
    """
    height, width = as_shape(shape)
    coordinates, value, strength, mode = _paint_arguments(pixels, color, weight, mode)
    image = np.zeros((height, width, *value.shape))
    return _paint_into(image, coordinates, value, strength, mode)


def _paint_arguments(
    pixels: Any, color: Any, weight: Any, mode: str, channels: int | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray, str]:
    """:func:`paint`'s checks of everything but the image."""
    coordinates = as_pixels(pixels)
    value = _as_color(color, "color", channels=channels)
    strength = as_float_array(weight, "weight")
    if strength.ndim > 1 or (strength.ndim == 1 and strength.shape[0] != len(coordinates)):
        raise ValueError(
            _(
                "weight must be a number or an array of shape ({coordinates_count},), one per "
                "pixel; got shape {strength_shape}"
            ).format(coordinates_count=len(coordinates), strength_shape=strength.shape)
        )
    if not np.all(np.isfinite(strength)) or (
        strength.size and (strength.min() < 0 or strength.max() > 1)
    ):
        raise ValueError(_("weight values must be finite and in [0, 1]"))
    mode = as_choice(mode, "mode", PAINT_MODES)
    return coordinates, value, strength, mode


def _paint_into(
    image: np.ndarray, coordinates: np.ndarray, value: np.ndarray, strength: np.ndarray, mode: str
) -> np.ndarray:
    """Paint checked arguments into ``image``, in place; pixels off the canvas are dropped."""
    strength = np.broadcast_to(strength, (len(coordinates),))
    keep = inside(coordinates, image.shape)
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


def crop(image: np.ndarray, centre: Any, size: int) -> tuple[np.ndarray, tuple[float, ...]]:
    """A ``size`` x ``size`` window of ``image`` around ``centre`` = (x, y).

    The window is shifted to stay on the canvas. Returns the crop (a view)
    and its ``extent`` for ``imshow(crop, extent=extent)``, so that axes keep
    image-space coordinates (pixel (r, c) spans [c, c+1) x [r, r+1)).

    Examples
    --------
    >>> window, extent = crop(np.zeros((10, 10)), (0.2, 9.7), 4)
    >>> window.shape, extent
    ((4, 4), (0, 4, 10, 6))
    """
    array = as_image(image, "image", copy=False)
    left, right, bottom, top = crop_extent(array.shape[:2], centre, size)
    return array[top:bottom, left:right], (left, right, bottom, top)


def crop_extent(shape: Any, centre: Any, size: int) -> tuple[int, int, int, int]:
    """The window :func:`crop` takes from a canvas of ``shape``: ``(left, right, bottom, top)``.

    Examples
    --------
    >>> crop_extent((10, 10), (0.2, 9.7), 4)
    (0, 4, 10, 6)
    """
    height, width = as_shape(shape)
    size = as_int(size, "size", minimum=1)
    x, y = as_point(centre, "centre", dim=2)
    size_x, size_y = min(size, width), min(size, height)
    x0 = int(np.clip(np.floor(x) - size_x // 2, 0, width - size_x))
    y0 = int(np.clip(np.floor(y) - size_y // 2, 0, height - size_y))
    return x0, x0 + size_x, y0 + size_y, y0


def yellow_fraction(image: np.ndarray, threshold: float = 0.5) -> float:
    """The GAMES101 check: of the pixels painted red or green, the share that are both.

    Paint the Bernstein curve in red and the de Casteljau curve in green: where
    they hit the same pixels, the pixel is yellow. 1.0 means every curve pixel
    is yellow; a curve drawn backwards or a wrong formula lowers it.

    Examples
    --------
    >>> image = blank((1, 3), (0, 0, 0))
    >>> image[0, 0] = image[0, 1] = (1, 1, 0)
    >>> image[0, 2] = (1, 0, 0)
    >>> round(yellow_fraction(image), 3)
    0.667
    """
    array = as_image(image, "image", copy=False)
    if array.ndim != 3:
        raise ValueError(
            _("image must be an RGB (H, W, 3) image; got shape {array_shape}").format(
                array_shape=array.shape
            )
        )
    threshold = as_unit(threshold, "threshold")
    red = array[..., 0] > threshold
    green = array[..., 1] > threshold
    painted = int(np.count_nonzero(red | green))
    if painted == 0:
        raise ValueError(_("image has no red or green pixels to compare"))
    return float(np.count_nonzero(red & green) / painted)
