"""course.check.supersampling: the lab's loop passes, the report's version is named."""

import numpy as np

from course.check import supersampling as check
from course.resample import (
    bilinear,
    supersample_shifted,
    supersample_without_offset,
)


def test_the_supersampling_checker_passes_a_loop_and_names_the_reports_version():
    def student(image, out_shape, rate):
        height, width = out_shape
        result = np.zeros((height, width, *image.shape[2:]))
        for row in range(height):
            for column in range(width):
                j, i = np.meshgrid(np.arange(rate), np.arange(rate), indexing="ij")
                x = (column + (i + 0.5) / rate) * image.shape[1] / width
                y = (row + (j + 0.5) / rate) * image.shape[0] / height
                result[row, column] = bilinear(image, x, y).mean(axis=(0, 1))
        return result

    assert check.image_supersampling(student)
    result = check.image_supersampling(supersample_without_offset)
    assert not result and "case 1 is wrong" in result.message
    result = check.image_supersampling(lambda image, out_shape, rate: image[: out_shape[0]])
    assert not result and "case 1 is wrong" in result.message


def corner_samples(image, out_shape, rate):
    """A student's loop that starts each sample at its sub-pixel's corner."""
    height, width = out_shape
    in_height, in_width = image.shape[:2]
    result = np.zeros((height, width, *image.shape[2:]))
    for row in range(height):
        for column in range(width):
            offsets = np.arange(rate) / rate
            y, x = np.meshgrid(
                (row + offsets) * in_height / height,
                (column + offsets) * in_width / width,
                indexing="ij",
            )
            result[row, column] = bilinear(image, x, y).mean(axis=(0, 1))
    return result


def test_each_half_of_the_reports_shift_is_named_with_a_difference_picture():
    corners = check.image_supersampling(corner_samples)
    assert corners.mistake == "samples at the sub-pixel corners" and corners.picture is not None
    centres = check.image_supersampling(
        lambda image, out_shape, rate: supersample_shifted(image, out_shape, rate, pixel_centre=0.0)
    )
    assert centres.mistake == "pixel centres at whole numbers"
    assert "first wrong value: [0, 0]" in str(centres)
