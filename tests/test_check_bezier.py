"""course.check.recursive_bezier, naive_bezier: right answers pass, mistakes fail by name."""

import itertools
import math

import numpy as np

from course import check
from course.bezier_handouts import de_casteljau_reversed


def recursive_solution(points, t):
    if len(points) == 1:
        return points[0]
    return recursive_solution([(1 - t) * a + t * b for a, b in itertools.pairwise(points)], t)


def naive_solution(points, t):
    n = len(points) - 1
    return sum(math.comb(n, i) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))


def test_correct_solutions_pass_whatever_they_name_their_arguments():
    result = check.recursive_bezier(recursive_solution)
    assert result and "all 45 cases pass" in str(result)
    assert check.naive_bezier(naive_solution)
    assert check.naive_bezier(lambda p, t: tuple(naive_solution(p, t)))


def test_the_reversed_convention_fails_and_names_the_case():
    result = check.recursive_bezier(lambda points, t: de_casteljau_reversed(points, t))
    assert not result
    message = str(result)
    # t = 1/2 on the symmetric first cases agrees; t = 0 gives the last point.
    assert message.startswith("FAIL recursive_bezier: case 2 is wrong")
    assert "t=0" in message and "[[0., 0.],\n [4., 2.]]" in message
    assert "expected: [0., 0.]" in message and "given:    [4., 2.]" in message


def test_naive_bezier_with_the_points_count_as_the_degree_fails():
    def off_by_one(points, t):
        n = len(points)
        return sum(math.comb(n, i) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))

    result = check.naive_bezier(off_by_one)
    # At t = 1/2 and t = 0 the line happens to come out right; t = 1 does not.
    assert not result and "case 3 is wrong" in str(result) and "t=1" in str(result)


def test_int32_binomials_fail_only_at_high_degree():
    def int32_comb(n, k):
        value = math.comb(n, k) % 2**32
        return value - 2**32 if value >= 2**31 else value

    def naive_int32(points, t):
        n = len(points) - 1
        return sum(int32_comb(n, i) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))

    assert check.naive_bezier(naive_int32)  # degree <= 11: C(11, 5) fits in an int


def test_exceptions_and_non_functions_are_reported():
    result = check.recursive_bezier(lambda points, t: points[5])
    assert not result and "raised IndexError" in str(result) and "case 1" in str(result)
    try:
        check.naive_bezier(np.zeros(2))
    except TypeError as error:
        assert "naive_bezier" in str(error)
    else:
        raise AssertionError("a non-function must raise TypeError")
