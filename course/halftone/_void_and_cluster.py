"""Void-and-cluster behind :mod:`course.halftone.blue_noise_masks`: array code on checked input.

Nothing here checks its input (``UNCHECKED = True``): ``size`` is an integer from 2
to :data:`course.limits.MAX_MASK_SIZE` (from 1 for :func:`gaussian_on_torus`),
``generator`` a ``numpy.random.Generator``, ``sigma`` a float > 0 and
``fraction`` a float in (0, 0.5], as :func:`course.halftone.blue_noise_masks.void_and_cluster`
makes sure before it calls :func:`rank_pixels`. :func:`course.halftone.dither.all_methods`
makes its default mask here too, from constants it need not check.
"""

from __future__ import annotations

import numpy as np

__all__ = ["blue_noise_levels", "gaussian_on_torus", "rank_pixels"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def gaussian_on_torus(size: int, sigma: float) -> np.ndarray:
    """``exp(-d**2 / (2 sigma**2))`` of the wrap-around distance d from pixel (0, 0)."""
    index = np.arange(size)
    distance = np.minimum(index, size - index).astype(float)
    return np.exp(-(distance[:, None] ** 2 + distance[None, :] ** 2) / (2 * sigma**2))


def rank_pixels(
    size: int, generator: np.random.Generator, sigma: float, fraction: float
) -> np.ndarray:
    """The void-and-cluster ranks of a ``size`` x ``size`` torus: (size, size) ints."""
    total = size * size
    kernel = np.tile(gaussian_on_torus(size, sigma), (2, 2))

    def footprint(index: int) -> np.ndarray:
        """A dot's energy everywhere, as flat (size**2,) view-based copy."""
        y, x = divmod(int(index), size)
        return kernel[size - y : 2 * size - y, size - x : 2 * size - x].ravel()

    def tightest_cluster(dots: np.ndarray, energy: np.ndarray) -> int:
        return int(np.argmax(np.where(dots, energy, -np.inf)))

    def largest_void(dots: np.ndarray, energy: np.ndarray) -> int:
        return int(np.argmin(np.where(dots, np.inf, energy)))

    count = max(1, round(fraction * total))
    dots = np.zeros(total, dtype=bool)
    dots[generator.choice(total, size=count, replace=False)] = True
    energy = np.zeros(total)
    for index in np.flatnonzero(dots):
        energy += footprint(index)

    # Initial pattern: move the tightest cluster to the largest void until
    # the void found is the spot just vacated. Each move lowers the total
    # energy, so it ends; the bound is a guard.
    for _move in range(total):
        cluster = tightest_cluster(dots, energy)
        dots[cluster] = False
        energy -= footprint(cluster)
        void = largest_void(dots, energy)
        dots[void] = True
        energy += footprint(void)
        if void == cluster:
            break

    ranks = np.empty(total, dtype=int)
    remaining, remaining_energy = dots.copy(), energy.copy()
    for rank in range(count - 1, -1, -1):
        cluster = tightest_cluster(remaining, remaining_energy)
        remaining[cluster] = False
        remaining_energy -= footprint(cluster)
        ranks[cluster] = rank
    for rank in range(count, total):
        void = largest_void(dots, energy)
        dots[void] = True
        energy += footprint(void)
        ranks[void] = rank
    return ranks.reshape(size, size)


def blue_noise_levels(size: int, generator: np.random.Generator) -> np.ndarray:
    """Ulichney's mask (sigma 1.5, a tenth of the pixels to start) as levels ``(i + 0.5) / N``."""
    ranks = rank_pixels(size, generator, 1.5, 0.1)
    return (ranks + 0.5) / ranks.size
