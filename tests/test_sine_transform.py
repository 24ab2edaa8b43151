"""course.poisson.sine_transform: the type-I DST, both of its ways, against its definition."""

import numpy as np
import pytest

from course.poisson.sine_transform import (
    box_solve,
    fast_transform,
    harmonic_fill,
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


def box_matrix(height: int, width: int) -> np.ndarray:
    laplacian = lambda size: 2 * np.eye(size) - np.eye(size, k=1) - np.eye(size, k=-1)  # noqa: E731
    return np.kron(laplacian(height), np.eye(width)) + np.kron(np.eye(height), laplacian(width))


@pytest.mark.parametrize(
    "shape",
    [(1, 1), (3, 4), (198, 3), (3, 198), (40, 52), (52, 58)],  # 199, 53 and 59 are prime
)
def test_box_solve_solves_the_box_equation_by_fft_by_matrix_or_both(shape):
    rhs = np.random.default_rng(3).normal(size=(2, *shape))
    solution = box_solve(rhs)
    matrix = box_matrix(*shape)
    expected = np.linalg.solve(matrix, rhs.reshape(2, -1).T).T.reshape(rhs.shape)
    np.testing.assert_allclose(solution, expected, rtol=0, atol=1e-12 * np.abs(expected).max())


def test_box_solve_leaves_its_input_alone():
    rhs = np.random.default_rng(4).normal(size=(1, 15, 23))  # both FFT-friendly: dstn
    before = rhs.copy()
    box_solve(rhs)
    assert np.array_equal(rhs, before)


def test_fast_transform_follows_the_largest_prime_factor_of_size_plus_one():
    sizes = (1, 15, 160, 190, 198, 52, 1025)  # + 1: 2, 16, 7 x 23, 191, 199, 53, 1026
    assert [fast_transform(n) for n in sizes] == [True, True, True, False, False, False, True]


@pytest.mark.parametrize("shape", [(1, 1), (3, 4), (198, 3), (3, 198), (40, 52), (21, 30)])
def test_harmonic_fill_solves_the_box_with_the_ring_moved_to_the_right_hand_side(shape):
    height, width = shape
    # Three channels, as an RGB clone has them, in a view whose channels are last in memory.
    ring = np.random.default_rng(5).normal(size=(height + 2, width + 2, 3)).transpose(2, 0, 1)
    rhs = np.zeros((3, height, width))  # the ring's values beside the box, by hand
    rhs[:, 0, :] += ring[:, 0, 1:-1]
    rhs[:, -1, :] += ring[:, -1, 1:-1]
    rhs[:, :, 0] += ring[:, 1:-1, 0]
    rhs[:, :, -1] += ring[:, 1:-1, -1]
    expected = np.linalg.solve(box_matrix(*shape), rhs.reshape(3, -1).T).T.reshape(rhs.shape)
    before = ring.copy()
    ring[:, 1:-1, 1:-1] = np.nan  # never read
    filled = harmonic_fill(ring)
    np.testing.assert_allclose(filled, expected, rtol=0, atol=1e-12 * np.abs(expected).max())
    assert np.array_equal(ring[:, 0], before[:, 0]) and np.array_equal(
        ring[:, :, -1], before[:, :, -1]
    )


def test_harmonic_fill_of_a_constant_ring_is_that_constant():
    ring = np.full((1, 9, 14), 0.375)
    np.testing.assert_allclose(harmonic_fill(ring), np.full((1, 7, 12), 0.375), atol=1e-14)
