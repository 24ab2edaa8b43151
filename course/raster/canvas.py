"""Canvases: blank images, the one function that paints pixels, zoom crops.

Images are float arrays in [0, 1], gray ``(H, W)`` or RGB ``(H, W, 3)``,
indexed ``image[y, x]``. Rasterizers elsewhere return pixel coordinates;
:func:`paint` is the only function that writes them into an image. It clips:
a pixel outside the canvas is dropped, never wrapped around to the other side
as a negative numpy index would be. Its array code, on checked input, is in
``_paint``, where renders that made their pixels themselves paint them too.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
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
from course.raster._paint import on_canvas, paint_into, painted_canvas

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
    return on_canvas(coordinates, as_shape(tuple(shape[:2])))


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
    height, width = image.shape[:2]
    if min(height, width) < 1 or height * width > limits.MAX_PIXELS:
        as_shape((height, width))  # an empty or huge image: refused, as a canvas shape is
    return paint_into(image, coordinates, value, strength, mode)


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
    canvas = as_shape(shape)
    coordinates, value, strength, mode = _paint_arguments(pixels, color, weight, mode)
    return painted_canvas(canvas, coordinates, value, strength, mode)


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
    size = as_int(size, "size", minimum=1)
    x, y = as_point(centre, "centre", dim=2)
    left, right, bottom, top = _crop_extent(array.shape[:2], x, y, size)
    return array[top:bottom, left:right], (left, right, bottom, top)


def crop_extent(shape: Any, centre: Any, size: int) -> tuple[int, int, int, int]:
    """The window :func:`crop` takes from a canvas of ``shape``: ``(left, right, bottom, top)``.

    Examples
    --------
    >>> crop_extent((10, 10), (0.2, 9.7), 4)
    (0, 4, 10, 6)
    """
    canvas = as_shape(shape)
    size = as_int(size, "size", minimum=1)
    x, y = as_point(centre, "centre", dim=2)
    return _crop_extent(canvas, x, y, size)


def _crop_extent(
    canvas: tuple[int, ...], x: float, y: float, size: int
) -> tuple[int, int, int, int]:
    """:func:`crop_extent` of checked arguments: ``canvas`` (H, W), ``size`` >= 1."""
    height, width = canvas[0], canvas[1]
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
