"""course.check.supersampling: the lab's loop passes, the report's version is named."""

import numpy as np

from course.check import supersampling as check
from course.resample import (
    bilinear,
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
