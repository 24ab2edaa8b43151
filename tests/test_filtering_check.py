"""course.check.filtering: the lab's Blur and Edge, right and wrong."""

import numpy as np
import pytest

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


def _frame_zero(function):
    def student(image):
        output = np.zeros_like(np.asarray(image, dtype=float))
        output[1:-1, 1:-1] = function(image)[1:-1, 1:-1]
        return output

    return student


def _frame_copied(image):
    output = np.array(image, dtype=float)
    output[1:-1, 1:-1] = filters.blur(image)[1:-1, 1:-1]
    return output


@pytest.mark.parametrize(
    ("student", "mistake"),
    [
        (lambda image: filters.convolve(image, filters.BOX, "zero"), "zero padding"),
        (_frame_zero(filters.blur), "the frame skipped"),
        (_frame_copied, "the frame copied"),
        (
            lambda image: filters.convolve(image, filters.BOX, "replicate"),
            "the edge pixel repeated",
        ),
    ],
)
def test_blur_mistakes_are_named_with_a_map_and_the_first_pixel(student, mistake):
    result = check.blur(student)
    assert not result
    assert result.mistake == mistake
    assert result.picture is not None and result.picture.startswith(b"\x89PNG")
    # The first case's first wrong pixel is the top-left corner: 4 of its 9 neighbours inside.
    assert (
        "the first wrong pixel is (x, y) = (0, 0), on the border: 4 of 9 inside" in result.message
    )


@pytest.mark.parametrize(
    ("student", "mistake"),
    [
        (lambda image: filters.sobel(image, "zero"), "zero padding"),
        (lambda image: np.clip(filters.sobel(image), 0, 1), "clipped to 1"),
        (lambda image: np.abs(filters.convolve(image, filters.SOBEL_X, "replicate")), "Gx alone"),
        (_frame_zero(filters.sobel), "the frame skipped"),
    ],
)
def test_edge_mistakes_are_named_with_a_map(student, mistake):
    result = check.edge(student)
    assert not result
    assert result.mistake == mistake
    assert result.picture is not None
    assert "pixels differ" in result.message


def test_an_interior_error_is_placed_inside_the_image():
    def off_by_one_pixel(image):
        output = filters.blur(image)
        if output.shape[:2] == (8, 10):
            output[4, 5] += 0.25
        return output

    result = check.blur(off_by_one_pixel)
    assert "(x, y) = (5, 4), inside the image; 1 pixel differs" in result.message
    assert result.mistake is None
