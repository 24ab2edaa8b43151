"""course.halftone.dither: every method's properties and forms, the measures, and bad input."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from course.halftone import blue_noise_masks as bn
from course.halftone import dither
from course.images import ramp

# Gray images of exact binary fractions, and of arbitrary floats in [0, 1].
shapes = st.tuples(st.integers(1, 9), st.integers(1, 11))
dyadic_grays = arrays(np.float64, shapes, elements=st.integers(0, 256).map(lambda k: k / 256))
float_grays = arrays(
    np.float64, shapes, elements=st.floats(0, 1, allow_nan=False, allow_subnormal=False)
)


def all_methods(gray):
    mask = bn.blue_noise_mask(8, np.random.default_rng(0))
    return {
        "threshold": dither.threshold(gray),
        "uniform_random": dither.uniform_random(gray, np.random.default_rng(1)),
        "blue_noise": dither.blue_noise(gray, mask),
        "ordered": dither.ordered(gray),
        "bayer": dither.bayer(gray, 4),
        **{kernel: dither.error_diffusion(gray, kernel) for kernel in dither.KERNELS},
    }


@given(float_grays)
def test_every_method_outputs_only_zeros_and_ones(gray):
    for name, result in all_methods(gray).items():
        assert set(np.unique(result)) <= {0.0, 1.0}, name
        expected = (3 * gray.shape[0], 3 * gray.shape[1]) if name == "ordered" else gray.shape
        assert result.shape == expected, name


@given(float_grays)
def test_inputs_are_not_modified(gray):
    before = gray.copy()
    all_methods(gray)
    dither.error_diffusion(gray, method="loop")
    dither.error_diffusion(gray, method="rows", serpentine=True)
    assert np.array_equal(gray, before)


@pytest.mark.parametrize("value", [0.0, 0.25, 0.5, 0.5 + 2**-52, 0.75, 1.0])
def test_threshold_of_a_constant_image_is_constant(value):
    result = dither.threshold(np.full((3, 4), value))
    assert np.array_equal(result, np.full((3, 4), float(value > 0.5)))


# --- ordered -----------------------------------------------------------------


@pytest.mark.parametrize("lit", range(10))
def test_ordered_lights_exactly_k_subpixels_per_cell_at_the_ten_levels(lit):
    # Level k/9 lights k sub-pixels; anything just above (k-1)/9 too.
    for level in (lit / 9, max(lit - 1, 0) / 9 + 1e-9 if lit else 0.0):
        result = dither.ordered(np.full((4, 5), level))
        cells = result.reshape(4, 3, 5, 3).sum(axis=(1, 3))
        assert np.all(cells == lit)


def test_ordered_patterns_follow_the_matrix_and_grow_one_subpixel_at_a_time():
    previous = np.zeros((3, 3))
    for lit in range(1, 10):
        pattern = dither.ordered([[lit / 9]])
        new = pattern - previous
        assert new.min() == 0 and new.sum() == 1
        # The new sub-pixel is where the matrix holds lit - 1.
        assert new[dither.ORDERED_MATRIX == lit - 1] == 1
        previous = pattern


@given(float_grays)
def test_ordered_loop_and_fast_forms_are_equal(gray):
    assert np.array_equal(dither.ordered(gray), dither.ordered(gray, method="loop"))


# --- random and blue noise ---------------------------------------------------


def test_uniform_random_is_the_specified_formula_and_reproducible():
    gray = ramp((8, 40))
    expected = gray + (np.random.default_rng(7).random(gray.shape) - 0.5) > 0.5
    assert np.array_equal(dither.uniform_random(gray, np.random.default_rng(7)), expected)
    assert np.array_equal(dither.uniform_random(gray), dither.uniform_random(gray))


def test_uniform_random_keeps_the_tone_on_average():
    result = dither.uniform_random(np.full((200, 200), 0.3), np.random.default_rng(3))
    # Binomial: standard deviation of the mean is sqrt(0.21 / 40000) = 0.0023.
    assert abs(result.mean() - 0.3) < 0.01


def test_blue_noise_texture_tiles_over_a_larger_image():
    rng = np.random.default_rng(2)
    gray, noise = rng.random((10, 7)), rng.random((4, 3))
    tiled = np.tile(noise, (3, 3))[:10, :7]
    assert np.array_equal(dither.blue_noise(gray, noise), gray + (tiled - 0.5) > 0.5)


@pytest.mark.parametrize("lit", [0, 1, 17, 128, 200, 256])
def test_blue_noise_with_the_mask_lights_k_pixels_per_tile_at_level_k_over_n(lit):
    mask = bn.blue_noise_mask(16, np.random.default_rng(5))
    result = dither.blue_noise(np.full((32, 48), lit / 256), mask)
    tiles = result.reshape(2, 16, 3, 16).sum(axis=(1, 3))
    assert np.all(tiles == lit)


# --- Bayer -------------------------------------------------------------------


@pytest.mark.parametrize("size", [1, 2, 4, 8])
def test_bayer_matrix_is_a_permutation_built_by_the_recursion(size):
    matrix = dither.bayer_matrix(size)
    assert sorted(matrix.ravel()) == list(range(size * size))
    if size > 1:
        half = dither.bayer_matrix(size // 2)
        assert np.array_equal(matrix[: size // 2, : size // 2], 4 * half)
        assert np.array_equal(matrix[size // 2 :, size // 2 :], 4 * half + 1)
    assert np.array_equal(dither.bayer_matrix(2), [[0, 2], [3, 1]])


@pytest.mark.parametrize("size", [2, 4, 8])
def test_bayer_lights_k_pixels_per_tile_without_bias(size):
    count = size * size
    for lit in range(count + 1):
        level = min(max((lit + 0.25) / count, 0.0), 1.0) if lit < count else 1.0
        result = dither.bayer(np.full((2 * size, 3 * size), level), size)
        tiles = result.reshape(2, size, 3, size).sum(axis=(1, 3))
        assert np.all(tiles == lit)


def test_bayer_rejects_a_size_that_is_not_a_power_of_two():
    with pytest.raises(ValueError, match="size must be a power of two"):
        dither.bayer(np.zeros((4, 4)), 3)


# --- quality -----------------------------------------------------------------


def test_mean_difference_measures_the_ordered_bias():
    # Level 0.3 shows as 3/9: 1/30 too bright; Bayer 4 rounds 0.3 * 16 = 4.8 to 5.
    gray = np.full((8, 8), 0.3)
    assert dither.mean_difference(gray, dither.ordered(gray)) == pytest.approx(1 / 3 - 0.3)
    assert dither.mean_difference(gray, dither.bayer(gray, 4)) == pytest.approx(5 / 16 - 0.3)


def test_blurred_error_ranks_error_diffusion_far_above_threshold_on_a_ramp():
    gray = ramp((32, 128))
    errors = {
        "threshold": dither.blurred_error(gray, dither.threshold(gray)),
        "error_diffusion": dither.blurred_error(gray, dither.error_diffusion(gray)),
    }
    assert errors["error_diffusion"] < errors["threshold"] / 3
    assert dither.blurred_error(gray, np.round(gray)) == errors["threshold"]


def test_blurred_error_is_zero_for_an_image_against_itself_at_any_scale():
    binary = np.random.default_rng(0).integers(0, 2, (6, 7)).astype(float)
    assert dither.blurred_error(binary, binary) == 0
    enlarged = np.repeat(np.repeat(binary, 3, axis=0), 3, axis=1)
    assert dither.blurred_error(binary, enlarged) == pytest.approx(0, abs=1e-15)


# --- bad input ---------------------------------------------------------------


@pytest.mark.parametrize(
    "call",
    [
        dither.threshold,
        dither.ordered,
        dither.bayer,
        dither.error_diffusion,
        dither.error_diffusion_wraparound,
        lambda gray: dither.uniform_random(gray, np.random.default_rng(0)),
        lambda gray: dither.blue_noise(gray, np.full((2, 2), 0.5)),
    ],
)
@pytest.mark.parametrize(
    ("gray", "message"),
    [
        (np.full((4, 4, 3), 0.5), r"gray must be a gray \(H, W\) image; got shape \(4, 4, 3\)"),
        (np.full((3, 3), 1.5), r"gray values must lie in \[0, 1\]"),
        (np.full((3, 3), -0.1), r"gray values must lie in \[0, 1\]"),
        (np.array([[0.5, np.nan]]), "gray must be finite; got nan"),
        (np.zeros((0, 4)), "gray must not be empty"),
        (np.full(5, 0.5), r"gray must be a gray \(H, W\) or RGB \(H, W, 3\) image"),
    ],
)
def test_bad_gray_images_are_rejected_naming_the_parameter(call, gray, message):
    with pytest.raises(ValueError, match=message):
        call(gray)


@pytest.mark.parametrize(
    ("noise", "message"),
    [
        (np.full(16, 0.5), r"noise must be a gray \(H, W\) or RGB \(H, W, 3\) image; got shape"),
        (np.full((4, 4, 3), 0.5), r"noise must be a gray \(H, W\) image; got shape \(4, 4, 3\)"),
        (np.full((2, 2, 2, 2), 0.5), r"noise must be a gray .* got shape \(2, 2, 2, 2\)"),
        (np.full((4, 4), 2.0), r"noise values must lie in \[0, 1\]"),
        (np.zeros((0, 0)), "noise must not be empty"),
    ],
)
def test_bad_noise_textures_are_rejected_naming_noise(noise, message):
    with pytest.raises(ValueError, match=message):
        dither.blue_noise(np.full((4, 4), 0.5), noise)


def test_bad_options_are_rejected_naming_them():
    gray = np.full((3, 3), 0.5)
    with pytest.raises(ValueError, match="kernel must be one of 'floyd-steinberg'"):
        dither.error_diffusion(gray, "sierra")
    with pytest.raises(ValueError, match="method must be one of 'wavefront', 'rows', 'loop'"):
        dither.error_diffusion(gray, method="fast")
    with pytest.raises(TypeError, match="serpentine must be True or False"):
        dither.error_diffusion(gray, serpentine="yes")
    with pytest.raises(TypeError, match=r"rng must be a numpy\.random\.Generator"):
        dither.uniform_random(gray, 42)
    with pytest.raises(ValueError, match=r"halftone must have the shape of gray \(3, 3\)"):
        dither.mean_difference(gray, np.zeros((4, 4)))
    with pytest.raises(ValueError, match="sigma must be > 0"):
        dither.blurred_error(gray, gray, sigma=0)
    with pytest.raises(ValueError, match="initial_fraction must be in"):
        bn.void_and_cluster(8, initial_fraction=0.7)
    with pytest.raises(ValueError, match="size must be >= 2"):
        bn.blue_noise_mask(1)
    with pytest.raises(ValueError, match=r"pattern must be a square \(N, N\) array"):
        bn.cluster_energy(np.zeros((3, 4)))


def test_bayer_sizes_are_bounded_before_the_matrix_is_built():
    from course import limits
    from course.halftone.dither import bayer, bayer_matrix

    with pytest.raises(ValueError, match=f"size must be between 1 and {limits.MAX_BAYER_SIZE}"):
        bayer_matrix(2**14)
    with pytest.raises(ValueError, match="size must be between"):
        bayer(np.full((4, 4), 0.5), size=2**14)
    assert bayer_matrix(limits.MAX_BAYER_SIZE).shape == (2**11, 2**11)
