"""The type-I discrete sine transform: the Laplacian's eigenvectors on a rectangle.

With fixed values around an ``m x n`` rectangle, the five-point Laplacian is
diagonalised by products of sines, so a Poisson solve is a sine transform, a
division by the eigenvalues and the transform back. :mod:`course.poisson.solvers`
(``solve_dst``) and :mod:`course.poisson.capacitance` (its box solves and
Green's function) share these. Like them, pure array functions with no input
checks. They leave the thread count to the caller: the solvers run them inside
:func:`course.poisson._threads.limited_threads`, which sets scipy.fft's workers and
the BLAS threads.

Unchecked kernels: like dhermes/bezier's ``hazmat``, this module trusts its
caller and checks no input (``UNCHECKED = True``, which the fuzz test reads).
Its public callers (:mod:`course.poisson`, :class:`course.poisson.problem.PoissonProblem`)
validate once, at their boundary.
"""

from __future__ import annotations

import functools

import numpy as np
import scipy.fft

__all__ = [
    "box_solve",
    "fast_transform",
    "harmonic_fill",
    "laplacian_eigenvalues",
    "largest_prime_factor",
    "sine_matrix",
    "sine_transform",
]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def laplacian_eigenvalues(size: int) -> np.ndarray:
    """Eigenvalues ``2 - 2 cos(pi k / (size + 1))`` of the 1-D Laplacian ``[-1, 2, -1]``."""
    return 2.0 - 2.0 * np.cos(np.pi * np.arange(1, size + 1) / (size + 1))


def sine_transform(x: np.ndarray, axis: int) -> np.ndarray:
    """``sum_j x_j sin(pi j k / (size + 1))`` along ``axis`` (1 or 2) of a ``(C, m, n)`` array.

    By FFT where that is fast (:func:`fast_transform`), otherwise as a matrix
    product with the sine matrix (BLAS).
    """
    size = x.shape[axis]
    if fast_transform(size):
        return scipy.fft.dst(x, type=1, axis=axis) * 0.5  # scipy's DST-I has a factor 2
    sines = sine_matrix(size)
    # 2-D products only: numpy's stacked (broadcast) matmul does not call BLAS.
    if axis == 2:
        return (x.reshape(-1, size) @ sines).reshape(x.shape)
    return np.stack([sines @ plane for plane in x])


def box_solve(rhs: np.ndarray) -> np.ndarray:
    """``L^{-1} rhs`` on a ``(C, m, n)`` box with zero values around it: two sine transforms.

    ``L`` is the five-point operator ``4 u_p - sum_q u_q``. The box's sine
    modes are its eigenvectors, with eigenvalues ``4 - 2 cos(pi k / (m + 1)) -
    2 cos(pi l / (n + 1))``: the solve is a transform, a division by the
    eigenvalues and the transform back. When both sides are FFT-friendly
    (:func:`fast_transform`), one ``scipy.fft.dstn`` call transforms both
    axes of every channel, and ``idstn`` is its exact inverse; otherwise
    :func:`sine_transform` goes axis by axis, and as it is its own inverse up
    to ``(size + 1) / 2`` per axis, that factor joins the division.

    Examples
    --------
    >>> box_solve(np.ones((1, 1, 3)))   # 4 y_1 - y_2 = 1, 4 y_2 - y_1 - y_3 = 1
    array([[[0.35714286, 0.42857143, 0.35714286]]])
    """
    height, width = rhs.shape[1:]
    if fast_transform(height) and fast_transform(width):
        spectrum = scipy.fft.dstn(rhs, type=1, axes=(1, 2))
        spectrum *= _inverse_eigenvalues(height, width, 1.0)
        return scipy.fft.idstn(spectrum, type=1, axes=(1, 2), overwrite_x=True)
    spectrum = sine_transform(sine_transform(rhs, axis=1), axis=2)
    spectrum *= _inverse_eigenvalues(height, width, 4.0 / ((height + 1) * (width + 1)))
    return sine_transform(sine_transform(spectrum, axis=1), axis=2)


def harmonic_fill(ring: np.ndarray) -> np.ndarray:
    """The interior of a ``(C, m + 2, n + 2)`` box, harmonic, with ``ring``'s outer ring as it is.

    ``L^{-1}`` of the right-hand side that the ring's values make: nonzero
    only beside the ring, so its sine transform is four outer products of a
    side's 1-D transform with one sine mode, not a 2-D transform (only the
    inverse is). The interior of ``ring`` is not read. A clone whose guidance
    is the foreground's own Laplacian is the foreground plus this fill of the
    ring's differences: lesson 08's drag moves only the ring.

    Examples
    --------
    >>> ring = np.zeros((1, 3, 4)); ring[0, :, 0] = 1.0
    >>> harmonic_fill(ring) * 15   # as box_solve of [[1, 0]]: the left values moved over
    array([[[4., 1.]]])
    """
    height, width = ring.shape[1] - 2, ring.shape[2] - 2
    if fast_transform(height) and fast_transform(width):
        return _fast_harmonic_fill(ring.transpose(1, 2, 0), height, width).transpose(2, 0, 1)
    sides = [
        (ring[:, 0, 1:-1], _sine_mode(height, 1), False),
        (ring[:, -1, 1:-1], _sine_mode(height, height), False),
        (ring[:, 1:-1, 0], _sine_mode(width, 1), True),
        (ring[:, 1:-1, -1], _sine_mode(width, width), True),
    ]
    spectrum = np.zeros((len(ring), height, width))
    for side, mode, is_column in sides:
        along = sine_transform(side[:, None, :], axis=2)[:, 0, :]  # the side's own transform
        if is_column:
            spectrum += along[:, :, None] * mode[None, None, :]
        else:
            spectrum += mode[None, :, None] * along[:, None, :]
    spectrum *= _inverse_eigenvalues(height, width, 4.0 / ((height + 1) * (width + 1)))
    return sine_transform(sine_transform(spectrum, axis=1), axis=2)


def _fast_harmonic_fill(ring: np.ndarray, height: int, width: int) -> np.ndarray:
    """:func:`harmonic_fill` by scipy's FFTs, channels last: ``(m + 2, n + 2, C)`` to ``(m, n, C)``.

    Channels last, the inverse transform's output is the layout an RGB
    image adds to without a strided pass. The four outer products are one
    matrix product: ``[top mode, bottom mode, left sides, right sides]``
    (m x (2 + 2C)) times ``[top side, bottom side, left and right modes]``.
    """
    channels = ring.shape[2]
    across = scipy.fft.dst(ring[[0, -1], 1:-1], type=1, axis=1)  # top and bottom sides: (2, n, C)
    down = scipy.fft.dst(ring[1:-1, [0, -1]], type=1, axis=0)  # left and right sides: (m, 2, C)
    left = np.empty((height, 2 + 2 * channels))
    left[:, 0] = _sine_mode(height, 1)
    left[:, 1] = _sine_mode(height, height)
    left[:, 2:] = down.reshape(height, -1)
    right = np.empty((2 + 2 * channels, width * channels))
    right[:2] = across.reshape(2, -1)
    right[2:] = _side_modes(width, channels)
    spectrum = (left @ right).reshape(height, width, channels)
    spectrum *= _inverse_eigenvalues_by_channel(height, width, channels)
    return scipy.fft.idstn(spectrum, type=1, axes=(0, 1), overwrite_x=True)


@functools.lru_cache(maxsize=8)
def _inverse_eigenvalues_by_channel(height: int, width: int, channels: int) -> np.ndarray:
    """:func:`_inverse_eigenvalues` for :func:`_fast_harmonic_fill`, repeated along its channels.

    Its scale is 2: scipy's DST-I has a factor 2, once in the sides'
    transforms and twice in ``idstn``. Repeated, not broadcast: a
    multiplication whose innermost axis is three channels long and
    broadcast runs five times slower.
    """
    inverse = np.repeat(_inverse_eigenvalues(height, width, 2.0)[:, :, None], channels, axis=2)
    inverse.flags.writeable = False
    return inverse


@functools.lru_cache(maxsize=8)
def _side_modes(width: int, channels: int) -> np.ndarray:
    """Rows of :func:`_fast_harmonic_fill`'s right factor for the left and right sides; read-only.

    Row ``side * C + c`` holds ``sin(pi index l / (n + 1))`` (index 1 for the
    left side, n for the right) at channel c of each column l, zero elsewhere,
    in the order of ``down.reshape(m, -1)``'s columns.
    """
    modes = np.zeros((2, channels, width, channels))
    for side, index in enumerate((1, width)):
        for channel in range(channels):
            modes[side, channel, :, channel] = _sine_mode(width, index)
    modes = modes.reshape(2 * channels, width * channels)
    modes.flags.writeable = False
    return modes


@functools.lru_cache(maxsize=16)
def _sine_mode(size: int, index: int) -> np.ndarray:
    """``sin(pi index k / (size + 1))``, k = 1 .. size: the transform of a unit vector."""
    mode = np.sin(np.pi * index * np.arange(1, size + 1) / (size + 1))
    mode.flags.writeable = False
    return mode


def fast_transform(size: int) -> bool:
    """Whether scipy's FFT beats a product with :func:`sine_matrix` for a DST-I of ``size``.

    A type-I DST of length ``size`` is an FFT of length ``2 (size + 1)``.
    When ``size + 1`` has a large prime factor (199 for a 200-pixel patch)
    that FFT is ten times slower than for a neighbouring size, and below a
    thousand pixels a matrix product (BLAS) is faster.

    Examples
    --------
    >>> fast_transform(199), fast_transform(198), fast_transform(2000)   # 200 = 2^3 5^2; 199
    (True, False, True)
    """
    return size > 1024 or largest_prime_factor(size + 1) <= 50


@functools.lru_cache(maxsize=8)
def _inverse_eigenvalues(height: int, width: int, scale: float) -> np.ndarray:
    """``scale`` over the box's eigenvalues, ``(height, width)``; read-only."""
    eigenvalues = laplacian_eigenvalues(height)[:, None] + laplacian_eigenvalues(width)[None, :]
    inverse = scale / eigenvalues
    inverse.flags.writeable = False
    return inverse


def largest_prime_factor(number: int) -> int:
    """The largest prime factor of a positive integer (1 for 1): 5 for 200, 199 for 199."""
    largest, factor = 1, 2
    while factor * factor <= number:
        while number % factor == 0:
            largest, number = factor, number // factor
        factor += 1
    return max(largest, number)


@functools.lru_cache(maxsize=8)
def sine_matrix(size: int) -> np.ndarray:
    """The type-I sine matrix ``sin(pi j k / (size + 1))``, j, k = 1 .. size; read-only."""
    k = np.arange(1, size + 1)
    sines = np.sin(np.pi * np.outer(k, k) / (size + 1))
    sines.flags.writeable = False
    return sines
