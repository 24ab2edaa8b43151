"""course.raster.canvas: painting clips, never wraps, and each mode means what it says."""

import numpy as np
import pytest

from course.raster.canvas import blank, crop, inside, paint, painted, yellow_fraction


def test_paint_drops_pixels_off_the_canvas_instead_of_wrapping():
    image = blank((3, 4))
    pixels = np.array([[-1, 0], [0, -1], [4, 0], [0, 3], [-4, -3], [1, 1]])
    paint(image, pixels, 1.0)
    expected = np.zeros((3, 4))
    expected[1, 1] = 1.0
    np.testing.assert_array_equal(image, expected)


def test_add_saturates_and_counts_repeats():
    image = blank((1, 2))
    paint(image, np.array([[0, 0]] * 3 + [[1, 0]] * 5), 1.0, weight=0.25)
    np.testing.assert_allclose(image, [[0.75, 1.0]])


def test_max_keeps_the_brighter_value():
    image = blank((1, 2), 0.5)
    paint(image, np.array([[0, 0], [1, 0]]), 1.0, weight=np.array([0.25, 0.75]), mode="max")
    np.testing.assert_allclose(image, [[0.5, 0.75]])


def test_over_blends_each_repeat_in_turn():
    image = blank((1, 1), 0.0)
    paint(image, np.array([[0, 0], [0, 0]]), 1.0, weight=0.5, mode="over")
    # 0 -> 0.5 -> 0.75, as two successive blends give.
    np.testing.assert_allclose(image, [[0.75]])
    untouched = blank((1, 2), 0.3)
    paint(untouched, np.array([[0, 0]]), 1.0, weight=0.5, mode="over")
    assert untouched[0, 1] == 0.3


def test_rgb_paint_writes_the_color():
    image = blank((2, 2), (0, 0, 0))
    paint(image, np.array([[1, 0]]), (1, 0, 0))
    paint(image, np.array([[1, 0], [0, 1]]), (0, 1, 0))
    np.testing.assert_array_equal(image[0, 1], [1, 1, 0])
    np.testing.assert_array_equal(image[1, 0], [0, 1, 0])
    assert yellow_fraction(image) == 0.5


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"pixels": np.array([[0.5, 1.0]])}, TypeError, "pixels"),
        ({"pixels": np.array([0, 1])}, ValueError, "(K, 2)"),
        ({"color": 2.0}, ValueError, "color"),
        ({"color": (1, 0, 0)}, ValueError, "gray"),
        ({"weight": np.array([0.5, 0.5])}, ValueError, "weight"),
        ({"weight": np.nan}, ValueError, "weight"),
        ({"mode": "set"}, ValueError, "mode"),
    ],
)
def test_paint_rejects_bad_input_by_name(kwargs, error, words):
    arguments = {"pixels": np.array([[0, 0]]), "color": 1.0} | kwargs
    with pytest.raises(error, match=words.replace("(", r"\(").replace(")", r"\)")):
        paint(blank((2, 2)), **arguments)


def test_paint_needs_a_float_image():
    with pytest.raises(TypeError, match="image"):
        paint(np.zeros((2, 2), dtype=np.uint8), np.array([[0, 0]]), 1.0)


def test_inside_and_crop_stay_on_the_canvas():
    assert inside(np.array([[2, 1]]), (2, 3)).tolist() == [True]
    window, extent = crop(np.arange(100.0).reshape(10, 10) / 100, (9.5, 0.2), 4)
    assert window.shape == (4, 4)
    assert extent == (6, 10, 4, 0)
    assert window[0, 0] == 0.06


def test_painted_is_paint_on_a_blank_canvas_for_every_mode():
    rng = np.random.default_rng(4)
    pixels = rng.integers(-2, 12, size=(40, 2))
    weights = rng.random(40)
    for mode in ("add", "max", "over"):
        for color in (0.7, (0.2, 0.5, 1.0)):
            expected = paint(
                blank((8, 10), 0.0 if np.ndim(color) == 0 else (0, 0, 0)),
                pixels,
                color,
                weights,
                mode,
            )
            np.testing.assert_array_equal(painted((8, 10), pixels, color, weights, mode), expected)


@pytest.mark.parametrize("threshold", ["abc", None, np.nan, -0.5, 1.5])
def test_yellow_fraction_names_a_bad_threshold(threshold):
    from course.raster.canvas import blank, yellow_fraction

    image = blank((2, 2), (1.0, 1.0, 0.0))
    with pytest.raises((TypeError, ValueError), match="threshold"):
        yellow_fraction(image, threshold)
