"""The type-I discrete sine transform: the Laplacian's eigenvectors on a rectangle.

With fixed values around an ``m x n`` rectangle, the five-point Laplacian is
diagonalised by products of sines, so a Poisson solve is a sine transform, a
division by the eigenvalues and the transform back. :mod:`course.poisson_solvers`
(``solve_dst``) and :mod:`course.poisson_capacitance` (its box solves and
Green's function) share these. Like them, pure array functions with no input
checks.
"""

from __future__ import annotations

import functools

import numpy as np
import scipy.fft

__all__ = ["laplacian_eigenvalues", "largest_prime_factor", "sine_matrix", "sine_transform"]


def laplacian_eigenvalues(size: int) -> np.ndarray:
    """Eigenvalues ``2 - 2 cos(pi k / (size + 1))`` of the 1-D Laplacian ``[-1, 2, -1]``."""
    return 2.0 - 2.0 * np.cos(np.pi * np.arange(1, size + 1) / (size + 1))


def sine_transform(x: np.ndarray, axis: int) -> np.ndarray:
    """``sum_j x_j sin(pi j k / (size + 1))`` along ``axis`` (1 or 2) of a ``(C, m, n)`` array.

    A type-I DST of length ``size`` is an FFT of length ``2 (size + 1)``.
    When ``size + 1`` has a large prime factor (199 for a 200-pixel patch)
    that FFT is ten times slower than for a neighbouring size, and below a
    thousand pixels a matrix product with the sine matrix (BLAS) is faster.
    """
    size = x.shape[axis]
    if size > 1024 or largest_prime_factor(size + 1) <= 50:
        return scipy.fft.dst(x, type=1, axis=axis) * 0.5  # scipy's DST-I has a factor 2
    sines = sine_matrix(size)
    # 2-D products only: numpy's stacked (broadcast) matmul does not call BLAS.
    if axis == 2:
        return (x.reshape(-1, size) @ sines).reshape(x.shape)
    return np.stack([sines @ plane for plane in x])


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
