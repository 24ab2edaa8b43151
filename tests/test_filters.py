"""course.filters: against scipy.ndimage inside, against the border rules on the frame."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy import ndimage

from course import filters

# Images of multiples of 1/256: every sum of a few of them is exact, so the
# loop and fast forms (which add in different orders) agree exactly.
shapes = st.one_of(
    st.tuples(st.integers(1, 9), st.integers(1, 9)),
    st.tuples(st.integers(1, 6), st.integers(1, 6), st.just(3)),
)
dyadic_images = arrays(np.float64, shapes, elements=st.integers(0, 256).map(lambda k: k / 256))
float_images = arrays(
    np.float64, shapes, elements=st.floats(0, 1, allow_nan=False, allow_subnormal=False)
)
kernels = arrays(np.float64, (3, 3), elements=st.integers(-8, 8).map(lambda k: k / 4))

SCIPY_MODES = {"zero": "constant", "replicate": "nearest", "reflect": "mirror"}


def per_channel(function, image):
    if image.ndim == 2:
        return function(image)
    return np.stack([function(image[..., c]) for c in range(image.shape[2])], axis=-1)


def scipy_sobel(image, mode="nearest"):
    def magnitude(channel):
        return np.hypot(ndimage.sobel(channel, 0, mode=mode), ndimage.sobel(channel, 1, mode=mode))

    return per_channel(magnitude, image)


def interior(image):
    return image[1:-1, 1:-1]


# --- blur --------------------------------------------------------------------


@given(float_images)
def test_blur_equals_scipy_uniform_filter_inside(image):
    expected = per_channel(lambda channel: ndimage.uniform_filter(channel, 3), image)
    assert np.allclose(interior(filters.blur(image)), interior(expected), rtol=0, atol=1e-14)


@given(float_images)
def test_blur_border_is_the_mean_of_the_in_image_neighbours(image):
    result = filters.blur(image)
    height, width = image.shape[:2]
    for y in range(height):
        for x in range(width):
            window = image[max(y - 1, 0) : y + 2, max(x - 1, 0) : x + 2]
            mean = window.reshape(-1, *image.shape[2:]).mean(axis=0)
            assert np.allclose(result[y, x], mean, rtol=0, atol=1e-14)


@given(dyadic_images)
def test_blur_loop_and_fast_forms_are_equal(image):
    assert np.array_equal(filters.blur(image), filters.blur(image, method="loop"))


@pytest.mark.parametrize("value", [0.0, 0.375, 1.0])
def test_blur_keeps_a_flat_image_flat_but_zero_padding_darkens_its_frame(value):
    image = np.full((5, 6), value)
    assert np.array_equal(filters.blur(image), image)
    zero = filters.convolve(image, filters.BOX, border="zero")
    assert np.allclose(interior(zero), value)
    assert np.allclose(zero[0, 1:-1], value * 6 / 9) and np.isclose(zero[0, 0], value * 4 / 9)


def test_blur_where_it_differs_from_scipy_is_the_one_pixel_frame():
    image = np.random.default_rng(0).random((20, 30))
    result = filters.blur(image)
    for mode in ("constant", "nearest", "reflect", "mirror"):
        difference = np.abs(result - ndimage.uniform_filter(image, 3, mode=mode)) > 1e-12
        assert not interior(difference).any()
        assert difference[0].any() and difference[-1].any()
        assert difference[:, 0].any() and difference[:, -1].any()


# --- sobel -------------------------------------------------------------------


@given(dyadic_images)
def test_sobel_equals_scipy_inside_and_with_the_same_border_everywhere(image):
    result = filters.sobel(image)
    assert np.array_equal(interior(result), interior(scipy_sobel(image, "constant")))
    for border, mode in SCIPY_MODES.items():
        assert np.array_equal(filters.sobel(image, border), scipy_sobel(image, mode))


@given(dyadic_images, st.sampled_from(["replicate", "reflect", "zero"]))
def test_sobel_loop_and_fast_forms_are_equal(image, border):
    assert np.array_equal(filters.sobel(image, border), filters.sobel(image, border, "loop"))


def test_sobel_of_a_vertical_step_is_four_on_both_sides():
    image = np.zeros((4, 6))
    image[:, 3:] = 1
    expected = np.zeros((4, 6))
    expected[:, 2:4] = 4
    assert np.array_equal(filters.sobel(image), expected)
    assert np.array_equal(filters.sobel(image.T), expected.T)


def test_sobel_of_a_flat_image_is_zero_unless_the_border_is_black():
    image = np.full((5, 5), 0.5)
    assert not filters.sobel(image).any()
    assert not filters.sobel(image, "reflect").any()
    zero = filters.sobel(image, "zero")
    assert (
        not interior(zero).any() and zero[0, 2] == 2.0 and zero[0, 0] == pytest.approx(1.5 * 2**0.5)
    )


# --- convolve ----------------------------------------------------------------


@given(float_images, kernels, st.sampled_from(sorted(SCIPY_MODES)))
def test_convolve_equals_scipy_ndimage_convolve_for_its_borders(image, kernel, border):
    expected = per_channel(
        lambda channel: ndimage.convolve(channel, kernel, mode=SCIPY_MODES[border]), image
    )
    assert np.allclose(filters.convolve(image, kernel, border), expected, rtol=0, atol=1e-13)


@given(float_images)
def test_convolve_with_the_handout_border_and_the_box_is_blur(image):
    result = filters.convolve(image, filters.BOX, "handout")
    assert np.allclose(result, filters.blur(image), rtol=0, atol=1e-14)


def test_handout_border_rescales_a_weighted_kernel_to_its_in_image_weights():
    image = np.random.default_rng(1).random((4, 5))
    kernel = np.array([[1, 2, 1], [2, 4, 2], [1, 2, 1]]) / 16
    result = filters.convolve(image, kernel, "handout")
    # Corner: in-image weights 4, 2, 2, 1 (of 16).
    corner = (4 * image[0, 0] + 2 * image[0, 1] + 2 * image[1, 0] + image[1, 1]) / 9
    assert result[0, 0] == pytest.approx(corner)
    flat = filters.convolve(np.full((4, 5), 0.25), kernel, "handout")
    assert np.allclose(flat, 0.25)


def test_convolve_flips_the_kernel_as_a_true_convolution():
    image = np.zeros((3, 5))
    image[1, 2] = 1
    right = np.zeros((3, 3))
    right[1, 2] = 1
    assert filters.convolve(image, right, "zero")[1, 3] == 1
    # The handout's dot product (correlation) is the flipped kernel.
    gx = filters.convolve(image, filters.SOBEL_X[::-1, ::-1], "zero")
    assert gx[1, 1] == 2 and gx[1, 3] == -2


def test_handout_border_refuses_a_kernel_whose_weights_cancel():
    with pytest.raises(ValueError, match="weights cancel out on part of the border"):
        filters.convolve(np.zeros((4, 4)), filters.SOBEL_X, "handout")


# --- inputs ------------------------------------------------------------------


@given(float_images)
def test_inputs_are_not_modified(image):
    before = image.copy()
    filters.blur(image)
    filters.sobel(image)
    filters.convolve(image, filters.BOX, "reflect")
    assert np.array_equal(image, before)


@pytest.mark.parametrize(
    "call",
    [
        filters.blur,
        filters.sobel,
        lambda image: filters.blur(image, method="loop"),
        lambda image: filters.convolve(image, filters.BOX),
    ],
)
@pytest.mark.parametrize(
    ("image", "message"),
    [
        (np.full((3, 3, 4), 0.5), r"image must be a gray \(H, W\) or RGB \(H, W, 3\) image"),
        (np.full(4, 0.5), r"image must be a gray \(H, W\) or RGB \(H, W, 3\) image"),
        (np.full((3, 3), 255.0), r"image values must lie in \[0, 1\]"),
        (np.array([[0.1, np.inf]]), "image must be finite; got inf"),
        (np.zeros((4, 0)), "image must not be empty"),
    ],
)
def test_bad_images_are_rejected_naming_the_parameter(call, image, message):
    with pytest.raises(ValueError, match=message):
        call(image)


def test_bad_kernels_and_options_are_rejected_naming_them():
    image = np.zeros((3, 3))
    with pytest.raises(ValueError, match=r"kernel must be a 3 x 3 array; got shape \(5, 5\)"):
        filters.convolve(image, np.ones((5, 5)))
    with pytest.raises(ValueError, match="kernel must be finite"):
        filters.convolve(image, np.full((3, 3), np.nan))
    with pytest.raises(ValueError, match="border must be one of 'handout', 'zero'"):
        filters.convolve(image, filters.BOX, "wrap")
    with pytest.raises(ValueError, match="border must be one of 'replicate', 'reflect', 'zero'"):
        filters.sobel(image, "handout")
    with pytest.raises(ValueError, match="method must be one of 'shifted_sums', 'loop'"):
        filters.blur(image, method="scipy")
    with pytest.raises(ValueError, match="method must be one of 'separable', 'loop'"):
        filters.sobel(image, method="fast")
