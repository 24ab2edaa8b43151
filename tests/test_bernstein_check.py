"""course.check.bernstein.naive_bezier: right answers pass, mistakes fail by name."""

import math

import numpy as np

from course.check import bernstein as check


def naive_solution(points, t):
    n = len(points) - 1
    return sum(math.comb(n, i) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))


def test_a_correct_solution_passes_whatever_it_returns_a_point_in():
    assert check.naive_bezier(naive_solution)
    assert check.naive_bezier(lambda p, t: tuple(naive_solution(p, t)))
    try:
        check.naive_bezier(np.zeros(2))
    except TypeError as error:
        assert "naive_bezier" in str(error)
    else:
        raise AssertionError("a non-function must raise TypeError")


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
