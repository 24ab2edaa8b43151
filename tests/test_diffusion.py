"""course.halftone.diffusion: three forms equal bit for bit, worked values, the wraparound slip."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from course.halftone import dither
from course.images import ramp

# Gray images of exact binary fractions, and of arbitrary floats in [0, 1].
shapes = st.tuples(st.integers(1, 9), st.integers(1, 11))


float_grays = arrays(
    np.float64, shapes, elements=st.floats(0, 1, allow_nan=False, allow_subnormal=False)
)


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
    from course.halftone.diffusion import _error_diffusion_wavefront

    values = dither.error_diffusion_values(gray, kernel, method="loop")
    banded = _error_diffusion_wavefront(gray, dither.diffusion_offsets(kernel), band=band)[1]
    assert np.array_equal(banded, values)


# Tall, wide and one-pixel images: a band's buffer is L cells a wavefront, L set
# by the width (tall) or by the band's rows (wide); both, and bands of any height.
extreme_grays = arrays(
    np.float64,
    st.one_of(
        st.tuples(st.integers(1, 40), st.integers(1, 4)),
        st.tuples(st.integers(1, 4), st.integers(1, 40)),
    ),
    elements=st.floats(0, 1, allow_nan=False, allow_subnormal=False),
)


@given(extreme_grays, st.sampled_from(sorted(dither.KERNELS)), st.none() | st.integers(1, 20))
def test_wavefront_on_tall_and_wide_images_gives_the_same_values_bit_for_bit(gray, kernel, band):
    # Cells beside the image and past a band's last row are zeroed before they
    # push (one ulp off, or one pixel, would fail); the sign of zero counts too.
    from course.halftone.diffusion import _error_diffusion_wavefront

    values = dither.error_diffusion_values(gray, kernel, method="loop")
    banded = _error_diffusion_wavefront(gray, dither.diffusion_offsets(kernel), band=band)[1]
    assert np.array_equal(banded.view(np.int64), values.view(np.int64))


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
    for method in dither.ERROR_DIFFUSION_METHODS:
        assert np.array_equal(dither.error_diffusion_values(gray, method=method), expected)
        assert np.array_equal(dither.error_diffusion(gray, method=method), [[1, 0], [0, 1]])


@pytest.mark.parametrize("kernel", ["floyd-steinberg", "jarvis-judice-ninke", "stucki"])
def test_error_diffusion_keeps_the_mean_of_a_gradient_within_one_percent(kernel):
    gray = ramp((64, 256))
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
    from course.halftone.diffusion import _wavefront_skew

    assert _wavefront_skew(dither.diffusion_offsets(kernel)) == skew


def test_kernel_weights_sum_to_one_except_atkinson():
    for kernel in dither.KERNELS:
        total = sum(weight for _, _, weight in dither.diffusion_offsets(kernel))
        assert total == pytest.approx(0.75 if kernel == "atkinson" else 1.0)


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
