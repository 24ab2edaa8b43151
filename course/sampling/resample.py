"""Resampling: bilinear interpolation, and shrinking an image by supersampling.

Pixel (r, c) is the unit square ``[c, c+1) x [r, r+1)`` and its value is the
image at its centre ``(c + 0.5, r + 0.5)``. :func:`bilinear` reads the image
at any continuous point by blending the four nearest centres.
:func:`supersample` shrinks an image the way the lab's Task 6 asks: each
output pixel averages rate x rate bilinear samples spread evenly over its
square, at the sub-pixel centres ``(i + 0.5) / rate``.

The report's version (:func:`supersample_without_offset`) drops both halves:
its samples start at the corner of the output pixel (``i / rate``) and its
bilinear lookup puts pixel centres at integers. The two shifts have opposite
signs and do not cancel; :func:`measure_shift` measures what is left.

References
----------
.. [1] F. C. Crow, "The aliasing problem in computer-generated shaded
   images", Communications of the ACM 20(11), 1977 (supersampling).
.. [2] P. S. Heckbert, "Fundamentals of texture mapping and image warping",
   MSc thesis, UC Berkeley, 1989, section 3 (pixel centres, resampling).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from scipy import sparse

from course import limits
from course._validate import (
    as_choice,
    as_finite_arrays,
    as_image,
    as_int,
    as_real,
    as_shape,
    describe,
    require_finite,
)
from course.i18n import _

__all__ = [
    "SUPERSAMPLE_METHODS",
    "bilinear",
    "measure_shift",
    "supersample",
    "supersample_shifted",
    "supersample_without_offset",
]

SUPERSAMPLE_METHODS = ("separable", "loop")


def bilinear(image: Any, x: Any, y: Any) -> np.ndarray:
    """The image at continuous points (x, y), blended from the four nearest centres.

    Points beyond the outermost pixel centres take the edge value (clamped),
    so the image extends as a constant past its border.

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3), values in [0, 1]
    x, y : float or array_like
        Image-space coordinates (x right, y down); broadcast together.

    Returns
    -------
    ndarray
        Shape ``broadcast(x, y).shape``, plus ``(3,)`` for an RGB image.

    Examples
    --------
    >>> image = np.array([[0.0, 1.0], [0.5, 0.5]])
    >>> bilinear(image, [0.5, 1.0, 1.5, 3.0], 0.5)  # centres, midway, clamped
    array([0. , 0.5, 1. , 1. ])
    >>> float(bilinear(image, 1.0, 1.0))
    0.5
    """
    pixels = as_image(image, "image", copy=False)
    xs, ys = as_finite_arrays((x, "x"), (y, "y"))
    try:
        xs, ys = np.broadcast_arrays(xs, ys)
    except ValueError:
        raise ValueError(
            _("x and y must broadcast together; got shapes {xs_shape} and {ys_shape}").format(
                xs_shape=xs.shape, ys_shape=ys.shape
            )
        ) from None
    return _bilinear(pixels, xs, ys)


def _taps(position: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Neighbours i0, i1 and the weight of i1, for positions where pixel i sits at i."""
    clamped = np.clip(position, 0, size - 1)
    first = np.minimum(np.floor(clamped).astype(np.int64), max(size - 2, 0))
    second = np.minimum(first + 1, size - 1)
    return first, second, clamped - first


def _bilinear(image: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Bilinear lookup without validation (x, y already broadcast)."""
    height, width = image.shape[:2]
    left, right, fx = _taps(x - 0.5, width)
    top, bottom, fy = _taps(y - 0.5, height)
    if image.ndim == 3:
        fx, fy = fx[..., None], fy[..., None]
    upper = image[top, left] * (1 - fx) + image[top, right] * fx
    lower = image[bottom, left] * (1 - fx) + image[bottom, right] * fx
    return upper * (1 - fy) + lower * fy


def supersample(image: Any, out_shape: Any, rate: int, method: str = "separable") -> np.ndarray:
    """Shrink (or enlarge) an image, averaging rate x rate bilinear samples per pixel.

    Output pixel (r, c) covers the input square from ``c * W / w`` to
    ``(c + 1) * W / w`` across (likewise down). It is the mean of the image
    sampled bilinearly at ``((c + (i + 0.5) / rate) * W / w,
    (r + (j + 0.5) / rate) * H / h)`` for i, j in ``range(rate)``: sub-pixel
    centres, so the samples are centred on the output pixel. As the rate
    grows this tends to the box filter (the mean over the square) of the
    bilinearly reconstructed image.

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3), values in [0, 1]
    out_shape : (h, w)
    rate : int >= 1
        Samples per output pixel along each axis.
    method : {"separable", "loop"}
        ``"loop"`` is the handout's: for every output pixel, for every
        sample, look up and add. ``"separable"`` (the default) computes the
        same sums as two sparse matrix products, one per axis, since both
        the sample grid and bilinear weights are separable.

    Returns
    -------
    ndarray, shape (h, w) or (h, w, 3)

    Examples
    --------
    Stripes one pixel wide, shrunk threefold: one sample per output pixel
    lands on a single stripe (aliasing); three sample all of them.

    >>> image = np.array([[0.0, 1.0, 0.0, 1.0, 0.0, 1.0]])
    >>> supersample(image, (1, 2), rate=1)  # samples at x = 1.5 and 4.5
    array([[1., 0.]])
    >>> supersample(image, (1, 2), rate=3)
    array([[0.33333333, 0.66666667]])
    """
    pixels = as_image(image, "image", copy=False)
    height, width = as_shape(out_shape, "out_shape")
    rate = as_int(rate, "rate", minimum=1, maximum=limits.MAX_RATE)
    _require_bounded_samples(height, width, rate)
    method = as_choice(method, "method", SUPERSAMPLE_METHODS)
    if method == "loop":
        return _supersample_loop(pixels, (height, width), rate)
    return _supersample_separable(pixels, (height, width), rate)


def _supersample_separable(image: np.ndarray, out_shape: tuple[int, int], rate: int) -> np.ndarray:
    """Two sparse products: one axis' samples and bilinear weights, then the other's."""
    height, width = out_shape
    rows = _resampling_matrix(image.shape[0], height, rate, sample_offset=0.5, centre=0.5)
    columns = _resampling_matrix(image.shape[1], width, rate, sample_offset=0.5, centre=0.5)
    return _separable(image, rows, columns)


def _supersample_loop(image: np.ndarray, out_shape: tuple[int, int], rate: int) -> np.ndarray:
    """The handout's loops: every output pixel, every sample, one bilinear lookup."""
    in_height, in_width = image.shape[:2]
    height, width = out_shape
    result = np.zeros((height, width, *image.shape[2:]))
    for row in range(height):
        for column in range(width):
            total = 0.0
            for j in range(rate):
                for i in range(rate):
                    x = (column + (i + 0.5) / rate) * in_width / width
                    y = (row + (j + 0.5) / rate) * in_height / height
                    total = total + _bilinear(image, np.float64(x), np.float64(y))
            result[row, column] = total / rate**2
    return result


def supersample_without_offset(image: Any, out_shape: Any, rate: int) -> np.ndarray:
    """The report's supersampling (seed 001, Task 6): a pitfall, kept to be measured.

    Its samples sit at ``(c + i / rate) * W / w``: they start at the output
    pixel's corner instead of being centred in it, which moves them half a
    sample spacing, ``1 / (2 rate)`` output pixels, up and left. Its bilinear
    lookup (``ix = int(fx)``, weight ``fx - ix``) treats input pixel centres
    as lying at integers, which moves them half an *input* pixel,
    ``1 / (2 s)`` output pixels (s = W / w), down and right. What remains is
    ``(1 / s - 1 / rate) / 2`` output pixels, -0.44 px at rate 1 when
    shrinking 2500 to 320, shrinking but not vanishing as the rate grows.
    :func:`supersample_shifted` with both offsets 0.

    Examples
    --------
    >>> image = np.array([[0.0, 1.0, 0.0, 1.0]])
    >>> supersample_without_offset(image, (1, 2), rate=1)  # samples at x = 0.5, 2.5
    array([[0., 0.]])
    """
    pixels, height, width, rate = _checked_supersampling(image, out_shape, rate)
    return _supersample_shifted(pixels, (height, width), rate, 0.0, 0.0)


def supersample_shifted(
    image: Any, out_shape: Any, rate: int, sample_offset: float = 0.5, pixel_centre: float = 0.5
) -> np.ndarray:
    """Supersampling with the sample positions and the pixel centres where you put them.

    Sample i of output pixel c sits at ``(c + (i + sample_offset) / rate) *
    W / w`` along each axis, and the bilinear lookup takes input pixel k to
    sit at ``k + pixel_centre``. The defaults, 0.5 and 0.5, are
    :func:`supersample`; the lab report's formula has 0 and 0
    (:func:`supersample_without_offset`), and each half of its mistake alone
    is one of the two set to 0.

    Examples
    --------
    >>> image = np.array([[0.0, 1.0, 0.0, 1.0]])
    >>> supersample_shifted(image, (1, 2), 1).tolist(), supersample(image, (1, 2), 1).tolist()
    ([[0.5, 0.5]], [[0.5, 0.5]])
    >>> supersample_shifted(image, (1, 2), 1, pixel_centre=0.0)  # samples at 1, 3: pixels 1, 3
    array([[1., 1.]])
    """
    pixels, height, width, rate = _checked_supersampling(image, out_shape, rate)
    sample_offset = as_real(sample_offset, "sample_offset")
    pixel_centre = as_real(pixel_centre, "pixel_centre")
    return _supersample_shifted(pixels, (height, width), rate, sample_offset, pixel_centre)


def _checked_supersampling(
    image: Any, out_shape: Any, rate: int
) -> tuple[np.ndarray, int, int, int]:
    """The checks every supersampling makes: the image, the output's shape and the rate."""
    pixels = as_image(image, "image", copy=False)
    height, width = as_shape(out_shape, "out_shape")
    rate = as_int(rate, "rate", minimum=1, maximum=limits.MAX_RATE)
    _require_bounded_samples(height, width, rate)
    return pixels, height, width, rate


def _supersample_shifted(
    image: np.ndarray, out_shape: tuple[int, int], rate: int, sample_offset: float, centre: float
) -> np.ndarray:
    """:func:`supersample_shifted` of checked arguments."""
    height, width = out_shape
    rows = _resampling_matrix(image.shape[0], height, rate, sample_offset, centre)
    columns = _resampling_matrix(image.shape[1], width, rate, sample_offset, centre)
    return _separable(image, rows, columns)


def _resampling_matrix(
    in_size: int, out_size: int, rate: int, sample_offset: float, centre: float
) -> sparse.csr_matrix:
    """The (out_size, in_size) matrix averaging one axis' bilinear samples.

    Sample i of output pixel o sits at ``(o + (i + sample_offset) / rate) *
    in_size / out_size``; input pixel k is taken to sit at ``k + centre``.
    """
    outputs = np.arange(out_size)[:, None]
    positions = (outputs + (np.arange(rate) + sample_offset) / rate) * (in_size / out_size)
    first, second, weight = _taps(positions - centre, in_size)
    owners = np.broadcast_to(outputs, positions.shape)
    matrix = sparse.csr_matrix(
        (
            np.concatenate([(1 - weight).ravel(), weight.ravel()]) / rate,
            (np.concatenate([owners.ravel()] * 2), np.concatenate([first.ravel(), second.ravel()])),
        ),
        shape=(out_size, in_size),
    )
    matrix.sum_duplicates()
    return matrix


def _separable(
    image: np.ndarray, rows: sparse.csr_matrix, columns: sparse.csr_matrix
) -> np.ndarray:
    """``rows @ image @ columns.T`` for each channel."""
    in_height, in_width = image.shape[:2]
    channels = image.shape[2:]
    height, width = rows.shape[0], columns.shape[0]
    # Rows first: it shrinks the data the second product reads.
    across = rows @ image.reshape(in_height, -1)
    across = across.reshape(height, in_width, -1).transpose(1, 0, 2).reshape(in_width, -1)
    result = (columns @ across).reshape(width, height, -1).transpose(1, 0, 2)
    # Convex weights can stray past [0, 1] by a rounding error; keep images valid.
    return np.clip(result.reshape(height, width, *channels), 0.0, 1.0)


def measure_shift(
    resampler: Callable[..., np.ndarray], in_size: int, out_size: int, rate: int
) -> float:
    """How far a resampler's samples sit from the output pixel centres, in output pixels.

    A horizontal ramp whose value is proportional to x is resampled from
    ``in_size`` to ``out_size`` pixels across; since bilinear interpolation
    reproduces a ramp exactly, each interior output pixel reads the mean x
    of its samples. The result is that mean minus the pixel's centre, in
    output pixels: 0 for :func:`supersample`, negative when the samples lie
    left of (and up from) the centre, so the picture moves right and down.
    Rows are treated the same way, so the vertical shift is the same.

    Examples
    --------
    >>> abs(measure_shift(supersample, 2500, 320, rate=1)) < 1e-9
    True
    >>> round(measure_shift(supersample_without_offset, 2500, 320, rate=1), 4)
    -0.436
    """
    if not callable(resampler):
        raise TypeError(
            _("resampler must be a function like supersample; got {resampler}").format(
                resampler=describe(resampler)
            )
        )
    in_size = as_int(in_size, "in_size", minimum=2, maximum=limits.MAX_SIDE)
    out_size = as_int(out_size, "out_size", minimum=3, maximum=limits.MAX_SIDE)
    rate = as_int(rate, "rate", minimum=1, maximum=limits.MAX_RATE)
    ramp = np.broadcast_to((np.arange(in_size) + 0.5) / in_size, (2, in_size))
    result = _checked_row(resampler(ramp, (1, out_size), rate), out_size)
    scale = in_size / out_size
    centres = np.arange(out_size) + 0.5
    # The first and last output pixels may have samples clamped at the border.
    interior = slice(1, out_size - 1)
    return float(np.mean(result[interior] * in_size / scale - centres[interior]))


def _checked_row(answer: Any, out_size: int) -> np.ndarray:
    """The one row of what ``resampler`` returned: a finite (1, out_size) image."""
    try:
        array = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(
            _(
                "resampler must return a (1, {out_size}) image of numbers; it returned {answer}"
            ).format(out_size=out_size, answer=describe(answer))
        ) from None
    if array.shape != (1, out_size):
        raise ValueError(
            _(
                "resampler must return an image of shape (1, {out_size}), the out_shape it was "
                "given; it returned shape {array_shape}"
            ).format(out_size=out_size, array_shape=array.shape)
        )
    require_finite(array, _("resampler's result"))
    return array[0]


def _require_bounded_samples(height: int, width: int, rate: int) -> None:
    if height * width * rate**2 > limits.MAX_SUPERSAMPLES:
        raise ValueError(
            _(
                "out_shape and rate must ask for at most {most} samples (H * W * rate**2); got "
                "{height} x {width} x {rate}**2"
            ).format(most=limits.MAX_SUPERSAMPLES, height=height, width=width, rate=rate)
        )
