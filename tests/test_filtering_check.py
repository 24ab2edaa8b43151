"""course.check.filtering: the lab's Blur and Edge, right and wrong."""

import numpy as np

from course import filters
from course.check import filtering as check


def test_blur_checker_passes_the_loop_and_fails_zero_padding_naming_the_case():
    assert check.blur(lambda image: filters.blur(image, method="loop"))
    result = check.blur(lambda image: filters.convolve(image, filters.BOX, "zero"))
    assert not result and "case 1 is wrong" in result.message and "image=" in result.message


def test_edge_checker_passes_sobel_and_fails_prewitt_and_a_black_border():
    assert check.edge(lambda image: filters.sobel(image, method="loop"))
    prewitt = np.array([[-1, 0, 1], [-1, 0, 1], [-1, 0, 1]])

    def prewitt_magnitude(image):
        gx = filters.convolve(image, prewitt[::-1, ::-1], "replicate")
        gy = filters.convolve(image, prewitt.T[::-1, ::-1], "replicate")
        return np.hypot(gx, gy)

    assert not check.edge(prewitt_magnitude)
    result = check.edge(lambda image: filters.sobel(image, "zero"))
    assert not result and "case 1 is wrong" in result.message
