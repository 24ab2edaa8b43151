"""Sample images: matplotlib's bundled photograph and procedural test images.

Every image is a float array in [0, 1], gray (H, W) or RGB (H, W, 3). Nothing
is downloaded: photographs come from matplotlib's own sample data.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib import cbook

from course._validate import as_image, as_int, as_positive_float, as_shape

__all__ = [
    "photograph",
    "ramp",
    "to_gray",
    "zone_plate",
    "zone_plate_box",
]

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


# --- procedural images with a known box-filtered downsample (lessons 04-05) ---


def zone_plate(shape: Any = (512, 512), max_frequency: float = 0.25) -> np.ndarray:
    """A zone plate: concentric rings whose frequency grows with the distance.

    ``0.5 + 0.5 * cos(pi * k * (x**2 + y**2))`` sampled at the pixel centres,
    with the rings centred on the top-left corner. The local frequency at
    distance d is ``k * d`` cycles per pixel, and ``k = max_frequency / max(H, W)``,
    so it reaches ``max_frequency`` at the far edges (and 1.41 times that in
    the far corner). Any downsampling that aliases shows false rings.

    Parameters
    ----------
    shape : (H, W)
    max_frequency : float
        Cycles per pixel at the right and bottom edges; below 0.5 the image
        itself is free of aliasing.

    See Also
    --------
    zone_plate_box : its exact mean over any grid of output pixels.

    Examples
    --------
    >>> plate = zone_plate((4, 6), max_frequency=0.25)
    >>> plate.shape, float(plate[0, 0].round(4))
    ((4, 6), 0.9989)
    """
    height, width = as_shape(shape)
    k = _zone_plate_rate(height, width, max_frequency)
    x = np.arange(width) + 0.5
    y = np.arange(height) + 0.5
    return 0.5 + 0.5 * np.cos(np.pi * k * (y[:, None] ** 2 + x[None, :] ** 2))


def zone_plate_box(shape: Any, out_shape: Any, max_frequency: float = 0.25) -> np.ndarray:
    """The exact box-filtered downsample of :func:`zone_plate`, in closed form.

    Output pixel (r, c) is the mean of the continuous zone plate over the
    input-space square it covers, ``[c W / w, (c + 1) W / w) x [r H / h,
    (r + 1) H / h)``: what an ideal camera with square pixels records, and
    the limit every supersampler should approach. Since ``cos(a + b) =
    Re(e^{ia} e^{ib})`` the integral splits into one per axis, each a
    difference of Fresnel integrals.

    Examples
    --------
    Shrinking 2500 x 2500 to 320 x 320, the rings near the corner are far
    finer than an output pixel and average out to mid-gray:

    >>> exact = zone_plate_box((2500, 2500), (320, 320))
    >>> exact.shape, float(exact[0, 0].round(4)), float(exact[-1, -1].round(4))
    ((320, 320), 0.9999, 0.5003)

    The mean over one pixel is close to the value at its centre when the
    rings are much wider than a pixel:

    >>> means = zone_plate_box((64, 64), (64, 64), max_frequency=0.05)
    >>> bool(np.abs(means - zone_plate((64, 64), max_frequency=0.05)).max() < 0.01)
    True
    """
    from scipy.special import fresnel

    height, width = as_shape(shape)
    out_height, out_width = as_shape(out_shape, "out_shape")
    k = _zone_plate_rate(height, width, max_frequency)
    # With x = t / sqrt(2 k), pi k x**2 = pi t**2 / 2, the Fresnel integrals' form.
    stretch = np.sqrt(2 * k)

    def axis_integral(size: int, out_size: int) -> np.ndarray:
        """Integral of exp(i pi k x**2) over each output pixel's span, over its length."""
        edges = np.arange(out_size + 1) * (size / out_size)
        sine, cosine = fresnel(edges * stretch)
        integral = np.diff(cosine) + 1j * np.diff(sine)
        return integral / stretch / (size / out_size)

    mean = np.real(np.outer(axis_integral(height, out_height), axis_integral(width, out_width)))
    return np.clip(0.5 + 0.5 * mean, 0.0, 1.0)


def _zone_plate_rate(height: int, width: int, max_frequency: float) -> float:
    max_frequency = as_positive_float(max_frequency, "max_frequency")
    return max_frequency / max(height, width)


# --- lessons 06-07: dithering and filtering ---------------------------------


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
    width = as_int(width, "width", minimum=1)
    height = as_int(height, "height", minimum=1)
    return np.tile((np.arange(width) + 0.5) / width, (height, 1))
