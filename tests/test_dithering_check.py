"""course.check.dithering: a correct loop passes, the handout's slip fails by case."""

import numpy as np

from course import dither
from course.check import dithering as check


def test_checker_passes_a_correct_loop_and_fails_the_wraparound_slip_naming_the_case():
    def solution(gray):
        height, width = gray.shape
        buffer, output = gray.copy(), np.zeros_like(gray)
        for y in range(height):
            for x in range(width):
                output[y, x] = 1.0 if buffer[y, x] > 0.5 else 0.0
                error = buffer[y, x] - output[y, x]
                for dx, dy, weight in (
                    (1, 0, 7 / 16),
                    (-1, 1, 3 / 16),
                    (0, 1, 5 / 16),
                    (1, 1, 1 / 16),
                ):
                    if 0 <= x + dx < width and y + dy < height:
                        buffer[y + dy, x + dx] += error * weight
        return output

    assert check.dithering_error_diffuse(solution)
    result = check.dithering_error_diffuse(dither.error_diffusion_wraparound)
    # Case 4 is one column: there x - 1 = -1 is the column itself.
    assert not result and "case 4 is wrong" in result.message and "inputs: gray=" in result.message
    result = check.dithering_error_diffuse(lambda gray: (gray >= 0.5).astype(float))
    assert not result and "case 1 is wrong" in result.message
