"""course.dither, course.error_diffusion, course.blue_noise: properties and exact forms."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from course import blue_noise as bn
from course import dither
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
    gray = ramp(40, 8)
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


# --- error diffusion ---------------------------------------------------------


def loop(gray, kernel="floyd-steinberg", serpentine=False):
    return dither.error_diffusion(gray, kernel, serpentine, method="loop")


@given(float_grays, st.sampled_from(sorted(dither.KERNELS)))
def test_the_three_forms_of_error_diffusion_are_equal_bit_for_bit(gray, kernel):
    expected = loop(gray, kernel)
    assert np.array_equal(dither.error_diffusion(gray, kernel), expected)
    assert np.array_equal(dither.error_diffusion(gray, kernel, method="rows"), expected)
    # The values the threshold saw, too: equal only if every pixel received
    # the same additions in the same order (one ulp off would fail).
    values = dither.error_diffusion_values(gray, kernel, method="loop")
    assert np.array_equal(dither.error_diffusion_values(gray, kernel), values)
    assert np.array_equal(dither.error_diffusion_values(gray, kernel, method="rows"), values)
    assert np.array_equal(values > 0.5, expected)


@given(float_grays, st.sampled_from(sorted(dither.KERNELS)), st.integers(1, 4))
def test_wavefront_in_bands_gives_the_same_values(gray, kernel, band):
    # Tall images run in bands; the bands hand on the errors in order.
    from course.error_diffusion import _diffuse_wavefront

    values = dither.error_diffusion_values(gray, kernel, method="loop")
    banded = _diffuse_wavefront(gray, dither.diffusion_offsets(kernel), band=band)[1]
    assert np.array_equal(banded, values)


@given(float_grays, st.sampled_from(sorted(dither.KERNELS)))
def test_serpentine_rows_form_equals_the_serpentine_loop(gray, kernel):
    expected = loop(gray, kernel, serpentine=True)
    assert np.array_equal(dither.error_diffusion(gray, kernel, serpentine=True), expected)
    values = dither.error_diffusion_values(gray, kernel, serpentine=True, method="loop")
    assert np.array_equal(dither.error_diffusion_values(gray, kernel, serpentine=True), values)


@pytest.mark.parametrize("kernel", sorted(dither.KERNELS))
def test_forms_are_equal_on_a_photograph_sized_input(kernel):
    gray = np.random.default_rng(11).random((37, 53))
    expected = loop(gray, kernel)
    assert np.array_equal(dither.error_diffusion(gray, kernel), expected)
    values = dither.error_diffusion_values(gray, kernel, method="loop")
    assert np.array_equal(dither.error_diffusion_values(gray, kernel), values)
    serpentine = loop(gray, kernel, serpentine=True)
    assert np.array_equal(dither.error_diffusion(gray, kernel, serpentine=True), serpentine)
    assert not np.array_equal(expected, serpentine)


def test_floyd_steinberg_values_worked_by_hand():
    # (x 0, y 0): 5/8 -> 1, error -3/8.
    # (x 1, y 0): 1/4 - 3/8 * 7/16 = 11/128 -> 0, error 11/128.
    # (x 0, y 1): 1/4 - 3/8 * 5/16 + 11/128 * 3/16 = 305/2048 -> 0.
    # (x 1, y 1): 7/8 - 3/8 * 1/16 + 11/128 * 5/16 + 305/2048 * 7/16 = 30919/32768 -> 1.
    gray = np.array([[5 / 8, 1 / 4], [1 / 4, 7 / 8]])
    expected = np.array([[5 / 8, 11 / 128], [305 / 2048, 30919 / 32768]])
    for method in dither.METHODS:
        assert np.array_equal(dither.error_diffusion_values(gray, method=method), expected)
        assert np.array_equal(dither.error_diffusion(gray, method=method), [[1, 0], [0, 1]])


@pytest.mark.parametrize("kernel", ["floyd-steinberg", "jarvis-judice-ninke", "stucki"])
def test_error_diffusion_keeps_the_mean_of_a_gradient_within_one_percent(kernel):
    gray = ramp(256, 64)
    result = dither.error_diffusion(gray, kernel)
    assert abs(result.mean() / gray.mean() - 1) < 0.01
    # And column by column the tone follows the ramp (8-column bands).
    bands = result.reshape(64, 32, 8).mean(axis=(0, 2))
    assert np.abs(bands - gray[0].reshape(32, 8).mean(axis=1)).max() < 0.05


def test_wavefront_refuses_serpentine_order_and_says_why():
    with pytest.raises(ValueError, match="no two rows can run together"):
        dither.error_diffusion(np.zeros((3, 3)), serpentine=True, method="wavefront")


@pytest.mark.parametrize(
    ("kernel", "skew"),
    [("floyd-steinberg", 2), ("atkinson", 3), ("jarvis-judice-ninke", 4), ("stucki", 4)],
)
def test_wavefront_skew_per_kernel(kernel, skew):
    from course.error_diffusion import _wavefront_skew

    assert _wavefront_skew(dither.diffusion_offsets(kernel)) == skew


def test_kernel_weights_sum_to_one_except_atkinson():
    for kernel in dither.KERNELS:
        total = sum(weight for _, _, weight in dither.diffusion_offsets(kernel))
        assert total == pytest.approx(0.75 if kernel == "atkinson" else 1.0)


# --- the pitfall -------------------------------------------------------------


def wrapped_floyd_steinberg(gray):
    """Floyd-Steinberg in plain lists, the below-left column taken modulo the width."""
    height, width = len(gray), len(gray[0])
    buffer = [list(map(float, row)) for row in gray]
    output = [[0.0] * width for _ in range(height)]
    for y in range(height):
        for x in range(width):
            old = buffer[y][x]
            output[y][x] = new = 1.0 if old > 0.5 else 0.0
            error = old - new
            if x + 1 < width:
                buffer[y][x + 1] += error * (7 / 16)
            if y + 1 < height:
                buffer[y + 1][(x - 1) % width] += error * (3 / 16)
                buffer[y + 1][x] += error * (5 / 16)
                if x + 1 < width:
                    buffer[y + 1][x + 1] += error * (1 / 16)
    return np.array(output)


def test_wraparound_pitfall_sends_the_left_columns_error_to_the_next_rows_last_pixel():
    gray = np.random.default_rng(4).random((30, 40))
    good, bad = dither.error_diffusion(gray), dither.error_diffusion_wraparound(gray)
    assert np.array_equal(bad, wrapped_floyd_steinberg(gray))
    assert np.array_equal(good[0], bad[0])  # the first push below comes after row 0
    assert not np.array_equal(good, bad)
    # The first damage in visiting order is at the right edge.
    first = np.flatnonzero((good != bad).ravel())[0]
    assert first % 40 >= 40 - 1 - 2 * (first // 40)


def test_wraparound_on_one_column_pushes_three_sixteenths_onto_itself():
    # With width 1, column -1 is column 0: the pixel below gets 3/16 + 5/16.
    gray = np.random.default_rng(9).random((25, 1))
    expected, carried = [], 0.0
    for value in gray[:, 0]:
        old = value + carried
        new = 1.0 if old > 0.5 else 0.0
        expected.append(new)
        error = old - new
        carried = error * (3 / 16) + error * (5 / 16)
    bad = dither.error_diffusion_wraparound(gray)
    assert np.array_equal(bad[:, 0], expected)


# --- quality -----------------------------------------------------------------


def test_mean_difference_measures_the_ordered_bias():
    # Level 0.3 shows as 3/9: 1/30 too bright; Bayer 4 rounds 0.3 * 16 = 4.8 to 5.
    gray = np.full((8, 8), 0.3)
    assert dither.mean_difference(gray, dither.ordered(gray)) == pytest.approx(1 / 3 - 0.3)
    assert dither.mean_difference(gray, dither.bayer(gray, 4)) == pytest.approx(5 / 16 - 0.3)


def test_blurred_error_ranks_error_diffusion_far_above_threshold_on_a_ramp():
    gray = ramp(128, 32)
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


# --- blue-noise mask ---------------------------------------------------------


@pytest.mark.parametrize("size", [5, 16])
def test_mask_is_a_permutation_of_the_levels(size):
    mask = bn.blue_noise_mask(size, np.random.default_rng(0))
    ranks = np.sort(mask.ravel()) * size * size - 0.5
    assert np.allclose(ranks, np.arange(size * size), atol=1e-9)


def test_mask_is_reproducible_from_the_generator():
    first = bn.blue_noise_mask(12, np.random.default_rng(3))
    assert np.array_equal(first, bn.blue_noise_mask(12, np.random.default_rng(3)))
    assert not np.array_equal(first, bn.blue_noise_mask(12, np.random.default_rng(4)))


def test_every_rank_follows_void_and_cluster_by_its_definition():
    size, sigma = 16, 1.5
    ranks = bn.void_and_cluster(size, np.random.default_rng(6), sigma)
    count = round(0.1 * size * size)
    for rank in range(size * size):
        pixel = np.unravel_index(np.flatnonzero(ranks.ravel() == rank)[0], ranks.shape)
        if rank >= count:  # added at the largest void of the lower ranks
            dots = ranks < rank
            energy = bn.cluster_energy(dots, sigma)
            assert energy[pixel] <= energy[~dots].min() + 1e-9
        else:  # removed as the tightest cluster of the ranks up to it
            dots = ranks <= rank
            energy = bn.cluster_energy(dots, sigma)
            assert energy[pixel] >= energy[dots].max() - 1e-9


def test_mask_has_far_less_low_frequency_power_than_white_noise():
    mask = bn.blue_noise_mask(32, np.random.default_rng(1))
    white = np.random.default_rng(1).random((32, 32))
    ratio = bn.low_frequency_fraction(mask) / bn.low_frequency_fraction(white)
    assert ratio < 0.01
    frequency, power = bn.radial_power_spectrum(mask)
    low, high = power[(frequency > 0) & (frequency < 0.1)], power[frequency > 0.4]
    assert low.mean() < 0.01 * high.mean()


def test_radial_power_spectrum_of_white_noise_is_flat_at_its_variance():
    white = np.random.default_rng(2).random((128, 128))
    frequency, power = bn.radial_power_spectrum(white)
    assert frequency[0] == 0 and power[0] == pytest.approx(0, abs=1e-20)
    # Rings from 0.1 to 0.5 cycles/pixel hold 40 to 200 independent
    # coefficients (the others are their conjugates): within a factor 2.
    ring = (frequency > 0.1) & (frequency < 0.5)
    assert np.all((power[ring] > 1 / 24) & (power[ring] < 1 / 6))
    assert power[ring].mean() == pytest.approx(1 / 12, rel=0.05)


def test_torus_gaussian_is_symmetric_and_wraps():
    kernel = bn.torus_gaussian(7, 1.5)
    assert np.allclose(kernel, kernel.T)
    assert np.allclose(kernel[1:], kernel[1:][::-1])
    assert kernel[0, 0] == 1.0


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


# --- exercise checker --------------------------------------------------------


def test_checker_passes_a_correct_loop_and_fails_the_wraparound_slip_naming_the_case():
    from course import check

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
