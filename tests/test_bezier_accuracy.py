"""course.curves.bezier_accuracy: exact evaluation, the power basis, the accuracy study."""

import itertools
from fractions import Fraction

import numpy as np
import pytest

from course.curves.bezier import de_casteljau
from course.curves.bezier_accuracy import (
    accuracy_by_degree,
    bezier_exact,
    bezier_power,
    power_coefficients,
    relative_errors,
)


def exact_de_casteljau(points, t):
    """de Casteljau in Fractions: independent of the integer Bernstein sum."""
    level = [[Fraction(float(v)) for v in row] for row in points]
    t = Fraction(float(t))
    while len(level) > 1:
        level = [
            [(1 - t) * a + t * b for a, b in zip(p, q, strict=True)]
            for p, q in itertools.pairwise(level)
        ]
    return level[0]


@pytest.mark.parametrize("degree", [0, 1, 5, 12])
def test_exact_evaluation_equals_exact_de_casteljau(degree):
    points = np.random.default_rng(degree).uniform(-3, 3, (degree + 1, 2))
    for t in (0.0, 0.3, 0.5, 1.0, 1.7):
        assert list(bezier_exact(points, t)) == exact_de_casteljau(points, t)


def test_power_coefficients_reproduce_the_curve_exactly_where_floats_allow():
    points = np.array([[0.0, 1], [2, 5], [4, -1], [8, 3], [1, 1]])
    coefficients = power_coefficients(points)
    # Degree 4 with integer points: the coefficients are integers, Horner is exact.
    for t in (0.0, 0.25, 0.5, 1.0):
        expected = sum(coefficients[j] * t**j for j in range(5))
        np.testing.assert_array_equal(bezier_power(points, t), expected)
        assert [float(v) for v in bezier_exact(points, t)] == expected.tolist()


def test_relative_errors_are_zero_for_exact_values_and_scale_with_the_polygon():
    points = np.array([[0.0, 0.0], [4.0, 8.0], [8.0, 0.0]])
    t = np.array([0.25, 0.5])
    assert relative_errors(points, t, de_casteljau(points, t)).tolist() == [0.0, 0.0]
    shifted = de_casteljau(points, t) + np.array([[0.0, 0.5], [0.25, 0.0]])
    assert relative_errors(points, t, shifted).tolist() == [0.5 / 8, 0.25 / 8]


def test_accuracy_study_power_basis_fails_while_de_casteljau_holds():
    errors = accuracy_by_degree([3, 20, 40], samples=9, rng=np.random.default_rng(0))
    assert errors["degree"].tolist() == [3, 20, 40]
    for method in ("de_casteljau", "bernstein_loop", "bernstein_horner"):
        assert np.all(errors[method] < 1e-14)
    assert errors["power"][0] < 1e-14
    assert errors["power"][2] > 1e-3
    with pytest.raises(ValueError, match="methods"):
        accuracy_by_degree([3], methods=("monomial",))
