"""Blue noise: Ulichney's void-and-cluster threshold mask, and how to measure it.

Blue noise is noise without low frequencies: its dots are spread evenly, no
clumps and no big gaps, which the eye, a low-pass filter, barely sees. The
lab downloaded a 256 x 256 texture; :func:`blue_noise_mask` makes one.

Void-and-cluster ranks the pixels of a square one by one. A pattern of dots
has an *energy* at every pixel, the sum of a Gaussian of every dot's
distance (on a torus, so the mask tiles): high energy is a *cluster*, low
energy a *void*. Starting from a random pattern rearranged until it is even
(every tightest cluster moved to the largest void), the dots are removed
tightest cluster first (ranks counting down), then the rest is filled
largest void first (ranks counting up). Every prefix of the ranking is thus
an even pattern, so thresholding the mask at any level gives blue noise.
The ranking runs on checked input in ``_void_and_cluster``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate import as_finite_array, as_int, as_positive_float, as_rng
from course.halftone._void_and_cluster import blue_noise_levels, gaussian_on_torus, rank_pixels
from course.i18n import _

__all__ = [
    "blue_noise_mask",
    "cluster_energy",
    "low_frequency_fraction",
    "radial_power_spectrum",
    "torus_gaussian",
    "void_and_cluster",
]


def torus_gaussian(size: int, sigma: float = 1.5) -> np.ndarray:
    """``exp(-d**2 / (2 sigma**2))`` of the wrap-around distance d from pixel (0, 0).

    Examples
    --------
    >>> np.round(torus_gaussian(4, 1.0)[0], 3)
    array([1.   , 0.607, 0.135, 0.607])
    """
    size = as_int(size, "size", minimum=1, maximum=int(limits.MAX_PIXELS**0.5))
    sigma = as_positive_float(sigma, "sigma")
    return gaussian_on_torus(size, sigma)


def cluster_energy(pattern: Any, sigma: float = 1.5) -> np.ndarray:
    """The energy of a square dot pattern at every pixel, on a torus.

    The sum over the dots of ``torus_gaussian`` centred on each, computed
    as a circular convolution with the FFT.

    Examples
    --------
    >>> pattern = np.zeros((4, 4), dtype=bool)
    >>> pattern[0, 0] = True
    >>> np.round(cluster_energy(pattern, 1.0)[0], 3)
    array([1.   , 0.607, 0.135, 0.607])
    """
    dots = _as_square_pattern(pattern)
    # A square pattern of at most MAX_PIXELS entries has a side torus_gaussian takes.
    kernel = gaussian_on_torus(dots.shape[0], as_positive_float(sigma, "sigma"))
    return np.real(np.fft.ifft2(np.fft.fft2(dots) * np.fft.fft2(kernel)))


def _as_dots(value: Any, name: str) -> np.ndarray:
    """A finite float copy; a boolean dot pattern counts as 0s and 1s."""
    if isinstance(value, np.ndarray) and value.dtype == bool:
        value = value.astype(float)
    array = as_finite_array(value, name, limits.LARGEST, "values")
    if array.size > limits.MAX_PIXELS:
        raise ValueError(
            _("{name} must have at most {most} entries; got {size}").format(
                name=name, most=limits.MAX_PIXELS, size=array.size
            )
        )
    return array


def _as_square_pattern(pattern: Any) -> np.ndarray:
    array = _as_dots(pattern, "pattern")
    if array.ndim != 2 or array.shape[0] != array.shape[1] or array.size == 0:
        raise ValueError(
            _("pattern must be a square (N, N) array of dots; got shape {array_shape}").format(
                array_shape=array.shape
            )
        )
    return array


def void_and_cluster(
    size: int,
    rng: np.random.Generator | None = None,
    sigma: float = 1.5,
    initial_fraction: float = 0.1,
) -> np.ndarray:
    """Rank the pixels of a ``size`` x ``size`` torus by void-and-cluster.

    Parameters
    ----------
    size : int
        From 2 to :data:`course.limits.MAX_MASK_SIZE` (128): the cost grows as size**4.
    rng : numpy.random.Generator, optional
        Places the initial random dots; ``default_rng(0)`` if omitted.
    sigma : float
        Width of the Gaussian energy filter in pixels (Ulichney: 1.5).
    initial_fraction : float
        Share of pixels in the initial pattern, in (0, 0.5].

    Returns
    -------
    ndarray of int, (size, size)
        A permutation of 0 .. size**2 - 1: the order in which pixels light
        up as the gray level rises. The ``round(initial_fraction size**2)``
        lowest ranks come from the initial pattern, removed tightest cluster
        first; the others were added largest void first. (Ulichney's third
        phase, filling the tightest clusters of the remaining zeros, picks
        the same pixels: on a torus the zeros' energy is a constant minus
        the dots' energy.)

    References
    ----------
    R. Ulichney, "The void-and-cluster method for dither array generation",
    Proceedings of SPIE 1913, Human Vision, Visual Processing, and Digital
    Display IV, 1993.

    Examples
    --------
    >>> ranks = void_and_cluster(4, np.random.default_rng(0))
    >>> sorted(ranks.ravel().tolist()) == list(range(16))
    True
    """
    size = as_int(size, "size", minimum=2, maximum=limits.MAX_MASK_SIZE)
    generator = as_rng(rng)
    sigma = as_positive_float(sigma, "sigma")
    fraction = as_positive_float(initial_fraction, "initial_fraction")
    if fraction > 0.5:
        raise ValueError(
            _("initial_fraction must be in (0, 0.5]; got {fraction}").format(fraction=fraction)
        )
    return rank_pixels(size, generator, sigma, fraction)


def blue_noise_mask(size: int = 64, rng: np.random.Generator | None = None) -> np.ndarray:
    """A tileable blue-noise texture: void-and-cluster ranks as levels in [0, 1).

    The values are a permutation of ``(i + 0.5) / size**2``, one per pixel,
    so the histogram is exactly flat, and a flat patch at level v dithered
    with it lights ``round(v size**2)`` pixels of each tile.

    Examples
    --------
    >>> mask = blue_noise_mask(4, np.random.default_rng(0))
    >>> np.sort(mask.ravel())[:4] * 16
    array([0.5, 1.5, 2.5, 3.5])
    """
    size = as_int(size, "size", minimum=2, maximum=limits.MAX_MASK_SIZE)
    return blue_noise_levels(size, as_rng(rng))


def _as_texture(image: Any) -> np.ndarray:
    array = _as_dots(image, "image")
    if array.ndim != 2 or min(array.shape, default=0) < 2:
        raise ValueError(
            _("image must be a 2-D (H, W) array, H, W >= 2; got shape {array_shape}").format(
                array_shape=array.shape
            )
        )
    return array


def radial_power_spectrum(image: Any) -> tuple[np.ndarray, np.ndarray]:
    """Mean power ``|FFT|**2`` of ``image - mean`` in rings of equal frequency.

    Returns ``(frequency, power)``: ring centres in cycles per pixel (0 to
    about 0.7) and the mean power of the FFT coefficients in each ring,
    normalised so that white noise of variance v is flat at v.

    Examples
    --------
    >>> frequency, power = radial_power_spectrum(np.random.default_rng(0).random((64, 64)))
    >>> bool(abs(power[1:].mean() / (1 / 12) - 1) < 0.1)
    True
    """
    array = _as_texture(image)
    power = np.abs(np.fft.fft2(array - array.mean())) ** 2 / array.size
    radius = _frequency_radius(array.shape)
    ring = np.rint(radius * max(array.shape)).astype(int)
    sums = np.bincount(ring.ravel(), weights=power.ravel())
    counts = np.bincount(ring.ravel())
    used = counts > 0
    return np.flatnonzero(used) / max(array.shape), sums[used] / counts[used]


def _frequency_radius(shape: tuple[int, ...]) -> np.ndarray:
    fy = np.fft.fftfreq(shape[0])[:, None]
    fx = np.fft.fftfreq(shape[1])[None, :]
    return np.hypot(fy, fx)


def low_frequency_fraction(image: Any, cutoff: float = 0.125) -> float:
    """Share of the power (mean removed) at frequencies below ``cutoff`` cycles/pixel.

    White noise spreads its power evenly, so its share is about the area
    of that disc in the frequency square, ``pi cutoff**2`` (0.049 for the
    default); blue noise has far less.

    Examples
    --------
    >>> round(low_frequency_fraction(np.random.default_rng(0).random((128, 128))), 3)
    0.044
    """
    array = _as_texture(image)
    cutoff = as_positive_float(cutoff, "cutoff")
    power = np.abs(np.fft.fft2(array - array.mean())) ** 2
    total = power.sum()
    if total == 0:
        raise ValueError(_("image is constant: it has no power to split"))
    return float(power[_frequency_radius(array.shape) < cutoff].sum() / total)
