"""course.halftone.blue_noise_masks: void-and-cluster by its definition, and its spectrum."""

import numpy as np
import pytest

from course.halftone import blue_noise_masks as bn


@pytest.mark.parametrize("size", [5, 16])
def test_mask_is_a_permutation_of_the_levels(size):
    mask = bn.blue_noise_mask(size, np.random.default_rng(0))
    ranks = np.sort(mask.ravel()) * size * size - 0.5
    assert np.allclose(ranks, np.arange(size * size), atol=1e-9)


def test_mask_is_reproducible_from_the_generator():
    first = bn.blue_noise_mask(12, np.random.default_rng(3))
    assert np.array_equal(first, bn.blue_noise_mask(12, np.random.default_rng(3)))
    assert not np.array_equal(first, bn.blue_noise_mask(12, np.random.default_rng(4)))


def test_every_rank_follows_void_and_cluster_by_its_definition():
    size, sigma = 16, 1.5
    ranks = bn.void_and_cluster(size, np.random.default_rng(6), sigma)
    count = round(0.1 * size * size)
    for rank in range(size * size):
        pixel = np.unravel_index(np.flatnonzero(ranks.ravel() == rank)[0], ranks.shape)
        if rank >= count:  # added at the largest void of the lower ranks
            dots = ranks < rank
            energy = bn.cluster_energy(dots, sigma)
            assert energy[pixel] <= energy[~dots].min() + 1e-9
        else:  # removed as the tightest cluster of the ranks up to it
            dots = ranks <= rank
            energy = bn.cluster_energy(dots, sigma)
            assert energy[pixel] >= energy[dots].max() - 1e-9


def test_mask_has_far_less_low_frequency_power_than_white_noise():
    mask = bn.blue_noise_mask(32, np.random.default_rng(1))
    white = np.random.default_rng(1).random((32, 32))
    ratio = bn.low_frequency_fraction(mask) / bn.low_frequency_fraction(white)
    assert ratio < 0.01
    frequency, power = bn.radial_power_spectrum(mask)
    low, high = power[(frequency > 0) & (frequency < 0.1)], power[frequency > 0.4]
    assert low.mean() < 0.01 * high.mean()


def test_radial_power_spectrum_of_white_noise_is_flat_at_its_variance():
    white = np.random.default_rng(2).random((128, 128))
    frequency, power = bn.radial_power_spectrum(white)
    assert frequency[0] == 0 and power[0] == pytest.approx(0, abs=1e-20)
    # Rings from 0.1 to 0.5 cycles/pixel hold 40 to 200 independent
    # coefficients (the others are their conjugates): within a factor 2.
    ring = (frequency > 0.1) & (frequency < 0.5)
    assert np.all((power[ring] > 1 / 24) & (power[ring] < 1 / 6))
    assert power[ring].mean() == pytest.approx(1 / 12, rel=0.05)


def test_torus_gaussian_is_symmetric_and_wraps():
    kernel = bn.torus_gaussian(7, 1.5)
    assert np.allclose(kernel, kernel.T)
    assert np.allclose(kernel[1:], kernel[1:][::-1])
    assert kernel[0, 0] == 1.0
