"""course.sine_transform: the type-I DST, both of its ways, against its definition."""

import numpy as np
import pytest

from course.sine_transform import (
    laplacian_eigenvalues,
    largest_prime_factor,
    sine_matrix,
    sine_transform,
)


def definition(x: np.ndarray, axis: int) -> np.ndarray:
    size = x.shape[axis]
    j = np.arange(1, size + 1)
    sines = np.sin(np.pi * np.outer(j, j) / (size + 1))
    return np.moveaxis(np.tensordot(np.moveaxis(x, axis, -1), sines, axes=(-1, 0)), -1, axis)


@pytest.mark.parametrize("size", [1, 7, 198, 199, 1100])  # FFT-friendly, prime + 1, large
@pytest.mark.parametrize("axis", [1, 2])
def test_the_transform_is_its_definition_by_fft_or_by_matrix(size, axis):
    shape = [2, 3, 4]
    shape[axis] = size
    x = np.random.default_rng(size).normal(size=shape)
    np.testing.assert_allclose(sine_transform(x, axis), definition(x, axis), atol=1e-9 * size)


def test_applied_twice_it_is_the_identity_times_half_of_size_plus_one():
    x = np.random.default_rng(1).normal(size=(1, 5, 9))
    twice = sine_transform(sine_transform(x, 2), 2)
    np.testing.assert_allclose(twice, x * 10 / 2, atol=1e-12)


def test_the_sines_diagonalise_the_one_dimensional_laplacian():
    size = 6
    laplacian = 2 * np.eye(size) - np.eye(size, k=1) - np.eye(size, k=-1)
    sines = sine_matrix(size)
    np.testing.assert_allclose(laplacian @ sines, sines * laplacian_eigenvalues(size), atol=1e-12)
    assert not sines.flags.writeable


def test_largest_prime_factor():
    assert [largest_prime_factor(n) for n in (1, 2, 200, 199, 2 * 3 * 97)] == [1, 2, 5, 199, 97]
