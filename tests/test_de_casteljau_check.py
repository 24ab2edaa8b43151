"""course.check.de_casteljau.recursive_bezier: right answers pass, mistakes fail by name."""

import itertools

import numpy as np

from course.bezier_handouts import de_casteljau_reversed
from course.check import de_casteljau as check


def recursive_solution(points, t):
    if len(points) == 1:
        return points[0]
    return recursive_solution([(1 - t) * a + t * b for a, b in itertools.pairwise(points)], t)


def test_correct_solutions_pass_whatever_they_name_their_arguments():
    result = check.recursive_bezier(recursive_solution)
    assert result and "all 45 cases pass" in str(result)
    assert check.recursive_bezier(lambda p, t: tuple(recursive_solution(p, t)))


def test_the_reversed_convention_fails_and_names_the_case():
    result = check.recursive_bezier(lambda points, t: de_casteljau_reversed(points, t))
    assert not result
    message = str(result)
    # t = 1/2 on the symmetric first cases agrees; t = 0 gives the last point.
    assert message.startswith("FAIL recursive_bezier: case 2 is wrong")
    assert "t=0" in message and "[[0., 0.],\n [4., 2.]]" in message
    assert "expected: [0., 0.]" in message and "given:    [4., 2.]" in message


def test_exceptions_and_non_functions_are_reported():
    result = check.recursive_bezier(lambda points, t: points[5])
    assert not result and "raised IndexError" in str(result) and "case 1" in str(result)
    try:
        check.recursive_bezier(np.zeros(2))
    except TypeError as error:
        assert "recursive_bezier" in str(error)
    else:
        raise AssertionError("a non-function must raise TypeError")
