"""course.metrics: the error measures, by hand, on gray and colour images."""

import numpy as np
import pytest

from course.metrics import max_error, rmse


def test_rmse_and_max_error_by_hand():
    image = np.array([[0.0, 0.5], [1.0, 0.25]])
    truth = np.array([[0.0, 0.25], [0.5, 0.25]])
    assert rmse(image, truth) == pytest.approx(np.sqrt((0.0625 + 0.25) / 4))
    assert max_error(image, truth) == 0.5
    with pytest.raises(ValueError, match="same shape"):
        rmse(image, np.zeros((3, 3)))
    with pytest.raises(ValueError, match="reference values must lie in"):
        rmse(image, truth + 2)


def test_colour_images_count_every_channel():
    image = np.zeros((1, 2, 3))
    truth = image.copy()
    truth[0, 1, 2] = 0.75  # one channel of one pixel: 1 value in 6
    assert rmse(image, truth) == pytest.approx(0.75 / np.sqrt(6))
    assert max_error(image, truth) == 0.75
    assert rmse(image, image) == 0.0


def test_inputs_are_not_modified():
    image, truth = np.full((2, 2), 0.5), np.zeros((2, 2))
    rmse(image, truth)
    max_error(image, truth)
    assert image.tolist() == [[0.5, 0.5], [0.5, 0.5]] and not truth.any()
