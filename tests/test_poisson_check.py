"""course.check.poisson: the lab's boundary ring, right and wrong."""

import numpy as np
import pytest

from course.check import poisson as check


def lab_style_boundary(background, foreground, offset):
    """The lab's C++ boundary loops, transcribed (a correct student answer)."""
    height, width = foreground.shape[:2]
    x0, y0 = offset
    g = np.zeros_like(foreground)
    for y in range(height):
        g[y, 0] = background[y0 + y, x0] - foreground[y, 0]
        g[y, width - 1] = background[y0 + y, x0 + width - 1] - foreground[y, width - 1]
    for x in range(width):
        g[0, x] = background[y0, x0 + x] - foreground[0, x]
        g[height - 1, x] = background[y0 + height - 1, x0 + x] - foreground[height - 1, x]
    return g


def test_the_checker_passes_the_lab_loops():
    result = check.poisson_boundary(lab_style_boundary)
    assert result and result.cases_run == 4


def flipped_sign(background, foreground, offset):
    """foreground - background: the sign the handout's formula invites."""
    return -lab_style_boundary(background, foreground, offset)


def swapped_offset(background, foreground, offset):
    """x and y swapped: only shows when they differ."""
    return lab_style_boundary(background, foreground, offset[::-1])


def filled_inside(background, foreground, offset):
    """background - foreground everywhere: the inside must start at 0."""
    x, y = offset
    height, width = foreground.shape[:2]
    return background[y : y + height, x : x + width] - foreground


@pytest.mark.parametrize(
    ("wrong", "case"),
    [(flipped_sign, "case 1 is wrong"), (swapped_offset, "case 2"), (filled_inside, "case 1")],
)
def test_the_checker_names_the_case_a_typical_mistake_fails(wrong, case):
    result = check.poisson_boundary(wrong)
    assert not result
    assert case in result.message
