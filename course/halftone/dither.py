"""Dithering: show a gray image with only black and white pixels.

Every function takes a gray float image ``(H, W)`` with values in [0, 1] and
returns a new float image of 0s and 1s. The lab's five methods are here,
specified exactly so that two correct implementations give identical output:

- :func:`threshold`: 1 where the value is > 0.5.
- :func:`uniform_random`: add ``rng.random(gray.shape) - 0.5``, then threshold.
- :func:`blue_noise`: add ``noise - 0.5`` (the texture tiles), then threshold.
- :func:`ordered`: each pixel becomes a 3 x 3 cell, sub-pixel (i, j) lit where
  the value is > ``ORDERED_MATRIX[i, j] / 9``; the output is 3 times larger.
- :func:`error_diffusion`: Floyd-Steinberg, in left-to-right raster order,
  threshold > 0.5, the error pushed 7/16 right and 3/16, 5/16, 1/16 below.

Beyond the lab: :func:`bayer` (ordered dithering at the input's size with
the 2 x 2, 4 x 4 and 8 x 8 Bayer matrices), the Jarvis-Judice-Ninke, Stucki
and Atkinson kernels and serpentine scanning for :func:`error_diffusion`,
and two quality measures, :func:`mean_difference` and :func:`blurred_error`.
The blue-noise texture itself comes from :mod:`course.halftone.blue_noise_masks`.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from scipy import ndimage

from course import limits
from course._validate import as_choice, as_gray, as_int, as_positive_float, as_rng
from course.halftone._diffusion import default_method, diffuse, kernel_offsets
from course.halftone._void_and_cluster import blue_noise_levels
from course.halftone.blue_noise_masks import blue_noise_mask
from course.halftone.diffusion import (
    ERROR_DIFFUSION_METHODS,
    KERNELS,
    diffusion_offsets,
    error_diffusion,
    error_diffusion_values,
    error_diffusion_wraparound,
)
from course.i18n import _

__all__ = [
    "ERROR_DIFFUSION_METHODS",
    "KERNELS",
    "ORDERED_MATRIX",
    "ORDERED_METHODS",
    "all_methods",
    "bayer",
    "bayer_matrix",
    "blue_noise",
    "blue_noise_mask",
    "blurred_error",
    "diffusion_offsets",
    "error_diffusion",
    "error_diffusion_values",
    "error_diffusion_wraparound",
    "mean_difference",
    "ordered",
    "threshold",
    "uniform_random",
]

#: The lab's 3 x 3 dither matrix (Foley et al.), indexed [row, column]: the
#: sub-pixel at row i, column j of a cell lights once the value exceeds M[i, j] / 9.
ORDERED_MATRIX = np.array([[6, 8, 4], [1, 0, 3], [5, 2, 7]])
ORDERED_METHODS = ("tiled", "loop")


def threshold(gray: Any) -> np.ndarray:
    """1 where the value is > 0.5, else 0.

    Examples
    --------
    >>> threshold([[0.2, 0.5, 0.51]])
    array([[0., 0., 1.]])
    """
    return _threshold(as_gray(gray, "gray"))


def _threshold(array: np.ndarray) -> np.ndarray:
    return (array > 0.5).astype(float)


def uniform_random(gray: Any, rng: np.random.Generator | None = None) -> np.ndarray:
    """Add uniform noise in [-0.5, 0.5), then threshold: ``gray + (r - 0.5) > 0.5``.

    ``r = rng.random(gray.shape)``, drawn once for the whole image (one number
    per pixel, row by row), so the same generator state gives the same output.
    Without ``rng``, ``numpy.random.default_rng(0)`` is used.

    Examples
    --------
    >>> uniform_random(np.full((2, 4), 0.5), np.random.default_rng(1))
    array([[1., 1., 0., 1.],
           [0., 0., 1., 0.]])
    """
    array = as_gray(gray, "gray")
    return _uniform_random(array, as_rng(rng))


def _uniform_random(array: np.ndarray, generator: np.random.Generator) -> np.ndarray:
    noise = generator.random(array.shape)
    return (array + (noise - 0.5) > 0.5).astype(float)


def blue_noise(gray: Any, noise: Any) -> np.ndarray:
    """Add ``noise - 0.5`` from a texture, then threshold.

    The texture ``noise`` (gray, values in [0, 1]) tiles the image from its
    top-left corner, so a small texture (e.g. :func:`blue_noise_mask`) covers
    any image. A pixel at level v lights where its noise value is > 1 - v:
    with the mask's levels ``(i + 0.5) / N``, a flat patch at level k / N
    lights exactly k pixels of each tile.

    Examples
    --------
    >>> blue_noise(np.full((2, 5), 0.5), [[0.1, 0.9], [0.6, 0.4]])
    array([[0., 1., 0., 1., 0.],
           [1., 0., 1., 0., 1.]])
    """
    return _blue_noise(as_gray(gray, "gray"), as_gray(noise, "noise"))


def _blue_noise(array: np.ndarray, texture: np.ndarray) -> np.ndarray:
    height, width = array.shape
    reps = (-(-height // texture.shape[0]), -(-width // texture.shape[1]))
    tiled = np.tile(texture, reps)[:height, :width]
    return (array + (tiled - 0.5) > 0.5).astype(float)


def ordered(gray: Any, method: str = "tiled") -> np.ndarray:
    """The lab's ordered dithering: each pixel becomes a 3 x 3 cell of sub-pixels.

    Output pixel ``(3 y + i, 3 x + j)`` is 1 where ``gray[y, x] > M[i, j] / 9``
    with ``M = ORDERED_MATRIX``, so a pixel lights ``ceil(9 v)`` of its nine
    sub-pixels: the ten patterns for the levels 0, 1/9, ..., 1. Note the
    bias: every level in ((k - 1)/9, k/9] shows as k/9, brighter on average
    by 1/18.

    Parameters
    ----------
    gray : array_like, (H, W), values in [0, 1]
    method : {"tiled", "loop"}
        ``"loop"`` is the handout's form, nine comparisons per pixel;
        ``"tiled"`` compares the whole image against the tiled matrix at once.

    Returns
    -------
    ndarray, (3 H, 3 W), of 0.0 and 1.0

    Examples
    --------
    >>> ordered([[0.3]])
    array([[0., 0., 0.],
           [1., 1., 0.],
           [0., 1., 0.]])
    """
    array = as_gray(gray, "gray")
    method = as_choice(method, "method", ORDERED_METHODS)
    if method == "loop":
        return _ordered_loop(array)
    return _ordered_tiled(array)


def _ordered_loop(array: np.ndarray) -> np.ndarray:
    """The handout's nine comparisons per pixel, one sub-pixel at a time."""
    levels = ORDERED_MATRIX / 9
    height, width = array.shape
    output = np.zeros((3 * height, 3 * width))
    for y in range(height):
        for x in range(width):
            for i in range(3):
                for j in range(3):
                    if array[y, x] > levels[i, j]:
                        output[3 * y + i, 3 * x + j] = 1.0
    return output


def _ordered_tiled(array: np.ndarray) -> np.ndarray:
    """Every pixel enlarged to 3 x 3, compared with the matrix tiled over the image."""
    enlarged = np.repeat(np.repeat(array, 3, axis=0), 3, axis=1)
    return (enlarged > np.tile(ORDERED_MATRIX / 9, array.shape)).astype(float)


def bayer_matrix(size: int) -> np.ndarray:
    """The ``size`` x ``size`` Bayer index matrix (size a power of two).

    Built by Bayer's recursion ``B_2n = [[4 B, 4 B + 2], [4 B + 3, 4 B + 1]]``
    from ``B_1 = [[0]]``: each level spreads the next four thresholds as far
    apart as possible.

    References
    ----------
    B. E. Bayer, "An optimum method for two-level rendition of continuous-tone
    pictures", IEEE International Conference on Communications, 1973.

    Examples
    --------
    >>> bayer_matrix(4)
    array([[ 0,  8,  2, 10],
           [12,  4, 14,  6],
           [ 3, 11,  1,  9],
           [15,  7, 13,  5]])
    """
    size = as_int(size, "size", minimum=1, maximum=limits.MAX_BAYER_SIZE)
    if size & (size - 1):
        raise ValueError(
            _("size must be a power of two (1, 2, 4, 8, ...); got {size}").format(size=size)
        )
    return _bayer_matrix(size)


def _bayer_matrix(size: int) -> np.ndarray:
    matrix = np.zeros((1, 1), dtype=int)
    while matrix.shape[0] < size:
        matrix = np.block([[4 * matrix, 4 * matrix + 2], [4 * matrix + 3, 4 * matrix + 1]])
    return matrix


def bayer(gray: Any, size: int = 4) -> np.ndarray:
    """Ordered dithering at the input's size with the tiled Bayer matrix.

    Pixel ``(y, x)`` is 1 where ``gray[y, x] > (B[y % n, x % n] + 0.5) / n**2``
    with ``B = bayer_matrix(n)``. The half-step centres the thresholds, so a
    flat patch at level v lights ``round(n**2 v)`` pixels per tile: no bias,
    unlike the lab's ``M / 9``.

    Examples
    --------
    >>> bayer(np.full((2, 4), 0.5), size=2)
    array([[1., 0., 1., 0.],
           [0., 1., 0., 1.]])
    """
    return _bayer(as_gray(gray, "gray"), bayer_matrix(size))


def _bayer(array: np.ndarray, matrix: np.ndarray) -> np.ndarray:
    n = matrix.shape[0]
    reps = (-(-array.shape[0] // n), -(-array.shape[1] // n))
    levels = np.tile((matrix + 0.5) / n**2, reps)[: array.shape[0], : array.shape[1]]
    return (array > levels).astype(float)


def all_methods(
    gray: Any, noise: Any = None, rng: np.random.Generator | None = None
) -> dict[str, np.ndarray]:
    """Every method of this module on one image, by display name.

    ``noise`` defaults to ``blue_noise_mask(64)`` and ``rng`` (for the
    uniform noise) to ``default_rng(0)``. Ordered 3 x 3 is three times
    larger than the others.

    Examples
    --------
    >>> results = all_methods(np.full((4, 4), 0.5))
    >>> [(name, float(result.mean())) for name, result in results.items()][:3]
    [('threshold', 0.0), ('uniform random', 0.625), ('blue noise', 0.5)]
    """
    array = as_gray(gray, "gray")
    generator = as_rng(rng)
    if noise is None:
        texture = blue_noise_levels(64, np.random.default_rng(0))
    else:
        texture = as_gray(noise, "noise")
    return {
        "threshold": _threshold(array),
        "uniform random": _uniform_random(array, generator),
        "blue noise": _blue_noise(array, texture),
        "ordered 3x3": _ordered_tiled(array),
        "Bayer 8x8": _bayer(array, _bayer_matrix(8)),
        "Floyd-Steinberg": _error_diffusion(array, "floyd-steinberg"),
        "Floyd-Steinberg serpentine": _error_diffusion(array, "floyd-steinberg", serpentine=True),
        "Jarvis-Judice-Ninke": _error_diffusion(array, "jarvis-judice-ninke"),
        "Stucki": _error_diffusion(array, "stucki"),
        "Atkinson": _error_diffusion(array, "atkinson"),
    }


def _error_diffusion(array: np.ndarray, kernel: str, serpentine: bool = False) -> np.ndarray:
    """:func:`error_diffusion` of a checked image, with its default form."""
    offsets = kernel_offsets(KERNELS[kernel])
    return diffuse(array, offsets, serpentine, default_method(serpentine))[0]


# --- quality -----------------------------------------------------------------


def _as_halftone(halftone: Any, gray: np.ndarray) -> tuple[np.ndarray, int]:
    """Validate a dithered image: gray, and the input's size times a whole factor."""
    array = as_gray(halftone, "halftone")
    factor = array.shape[0] // gray.shape[0]
    if factor < 1 or array.shape != (factor * gray.shape[0], factor * gray.shape[1]):
        raise ValueError(
            _(
                "halftone must have the shape of gray {gray_shape} times a whole factor (ordered "
                "dithering gives 3 times); got shape {array_shape}"
            ).format(gray_shape=gray.shape, array_shape=array.shape)
        )
    return array, factor


def mean_difference(gray: Any, halftone: Any) -> float:
    """Mean of the dithered image minus mean of the original: 0 means the tone is kept.

    Examples
    --------
    >>> mean_difference(np.full((1, 1), 0.3), ordered(np.full((1, 1), 0.3)))
    0.033333333333333326
    """
    original = as_gray(gray, "gray")
    array, _ = _as_halftone(halftone, original)
    return float(array.mean() - original.mean())


def blurred_error(gray: Any, halftone: Any, sigma: float = 1.5) -> float:
    """RMS difference between dithered and original after the same Gaussian blur.

    A rough model of the eye, which averages neighbouring dots: a good
    dithering keeps the local tone, so blurred, it looks like the original.
    ``sigma`` is in input pixels; for an output ``k`` times larger (ordered
    dithering) the original is enlarged by pixel repetition and the blur is
    ``k sigma``, so every method is judged at the same viewing size. Borders
    are mirrored (``scipy.ndimage.gaussian_filter``, mode ``"reflect"``).

    Examples
    --------
    >>> gray = np.full((16, 16), 0.5)
    >>> [round(blurred_error(gray, result), 2) for result in (threshold(gray), bayer(gray, 2))]
    [0.5, 0.01]
    """
    original = as_gray(gray, "gray")
    array, factor = _as_halftone(halftone, original)
    sigma = as_positive_float(sigma, "sigma")
    enlarged = np.repeat(np.repeat(original, factor, axis=0), factor, axis=1)
    difference = ndimage.gaussian_filter(array - enlarged, factor * sigma, mode="reflect")
    return float(np.sqrt(np.mean(difference**2)))
