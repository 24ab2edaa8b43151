"""course.sampling.resample and the zone plate: bilinear, supersampling, the report's shift."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from course.images import zone_plate, zone_plate_box
from course.sampling.resample import (
    bilinear,
    measure_shift,
    supersample,
    supersample_shifted,
    supersample_without_offset,
)

rng = np.random.default_rng(4)


# --- bilinear ----------------------------------------------------------------


def test_bilinear_at_pixel_centres_returns_the_pixels():
    image = rng.random((5, 7, 3))
    y, x = np.mgrid[0:5, 0:7] + 0.5
    np.testing.assert_array_equal(bilinear(image, x, y), image)


# A ramp a + b x + c y with binary-fraction coefficients is exact in floats.
eighths = st.integers(0, 8).map(lambda v: v / 8)


@given(
    st.integers(2, 9),
    st.integers(2, 9),
    st.lists(st.tuples(st.integers(0, 64), st.integers(0, 64)), min_size=1, max_size=20),
)
def test_bilinear_reproduces_a_linear_ramp_exactly(height, width, points):
    a, b, c = 1 / 4, 1 / 64, 1 / 128
    y, x = np.mgrid[0:height, 0:width] + 0.5
    image = a + b * x + c * y
    # Points between the outermost centres, on a 1/8 grid: exact arithmetic.
    px = np.array([0.5 + (width - 1) * i / 64 for i, _ in points])
    py = np.array([0.5 + (height - 1) * j / 64 for _, j in points])
    np.testing.assert_array_equal(bilinear(image, px, py), a + b * px + c * py)


def test_bilinear_clamps_beyond_the_outer_centres():
    image = np.array([[0.0, 0.25], [0.5, 1.0]])
    np.testing.assert_array_equal(bilinear(image, [-3.0, 0.2, 0.5], 0.0), [0.0, 0.0, 0.0])
    np.testing.assert_array_equal(bilinear(image, [2.0, 9.0], [9.0, 2.0]), [1.0, 1.0])
    assert bilinear(np.array([[0.3]]), 5.0, -2.0) == 0.3


def test_bilinear_broadcasts_and_keeps_channels():
    image = rng.random((4, 4, 3))
    assert bilinear(image, np.ones((2, 3)), 1.5).shape == (2, 3, 3)
    assert bilinear(image[..., 0], [1.0, 2.0], [[1.0], [2.0], [3.0]]).shape == (3, 2)


# --- supersample ---------------------------------------------------------------

shapes = st.tuples(st.integers(1, 12), st.integers(1, 12))


@given(shapes, shapes, st.integers(1, 6), st.floats(0, 1))
def test_a_constant_image_stays_constant(in_shape, out_shape, rate, value):
    image = np.full(in_shape, value)
    for resample in (supersample, supersample_without_offset):
        np.testing.assert_allclose(resample(image, out_shape, rate), value, rtol=0, atol=1e-15)


@given(shapes, shapes, st.integers(1, 5), st.booleans())
def test_the_loop_and_the_separable_form_agree(in_shape, out_shape, rate, rgb):
    image = rng.random((*in_shape, 3) if rgb else in_shape)
    np.testing.assert_allclose(
        supersample(image, out_shape, rate),
        supersample(image, out_shape, rate, method="loop"),
        rtol=0,
        atol=1e-14,
    )


def report_supersample(image, out_shape, rate):
    """The report's C++ (seed 001, Task 6), transcribed line by line."""
    in_h, in_w = image.shape[:2]
    out_h, out_w = out_shape
    output = np.zeros((out_h, out_w, *image.shape[2:]))
    for y in range(out_h):
        for x in range(out_w):
            color_sum = 0.0
            for dx in range(rate):
                for dy in range(rate):
                    fx = (x + (dx * 1.0) / rate) * in_w / out_w
                    fy = (y + (dy * 1.0) / rate) * in_h / out_h
                    ix, iy = int(fx), int(fy)
                    tx, ty = fx - ix, fy - iy
                    ix1, iy1 = min(ix + 1, in_w - 1), min(iy + 1, in_h - 1)
                    c0 = image[iy, ix] * (1 - tx) + image[iy, ix1] * tx
                    c1 = image[iy1, ix] * (1 - tx) + image[iy1, ix1] * tx
                    color_sum = color_sum + c0 * (1 - ty) + c1 * ty
            output[y, x] = color_sum / rate**2
    return output


@given(shapes, shapes, st.integers(1, 5))
def test_the_pitfall_is_the_reports_code(in_shape, out_shape, rate):
    image = rng.random(in_shape)
    np.testing.assert_allclose(
        supersample_without_offset(image, out_shape, rate),
        report_supersample(image, out_shape, rate),
        rtol=0,
        atol=1e-14,
    )


def test_a_ramp_is_read_at_the_pixel_centres():
    y, x = np.mgrid[0:40, 0:50] + 0.5
    image = (x + y) / 100
    result = supersample(image, (8, 10), rate=3)
    centre_y, centre_x = (np.mgrid[0:8, 0:10] + 0.5) * 5
    # Away from the border, where no sample is clamped.
    np.testing.assert_allclose(result[1:-1, 1:-1], ((centre_x + centre_y) / 100)[1:-1, 1:-1])


def test_error_against_the_exact_box_filter_falls_as_the_rate_grows():
    """The lab's 2500 -> 320 at a fifth of the size: same ratio, same rings."""
    image = zone_plate((500, 500))
    exact = zone_plate_box((500, 500), (64, 64))
    errors = [
        np.sqrt(np.mean((supersample(image, (64, 64), rate) - exact) ** 2)) for rate in range(1, 13)
    ]
    assert errors[0] > 0.25  # one sample per pixel: the rings alias
    assert errors[0] > errors[1] > errors[2] > max(errors[3:])
    assert max(errors[3:]) < 0.01 and errors[-1] < errors[0] / 100


@pytest.mark.parametrize(("in_size", "out_size"), [(2500, 320), (500, 64), (100, 30)])
@pytest.mark.parametrize("rate", [1, 2, 3, 7, 12])
def test_the_reports_shift_is_measured_and_explained(in_size, out_size, rate):
    assert abs(measure_shift(supersample, in_size, out_size, rate)) < 1e-9
    scale = in_size / out_size
    expected = (1 / scale - 1 / rate) / 2
    assert measure_shift(supersample_without_offset, in_size, out_size, rate) == pytest.approx(
        expected, abs=1e-9
    )


# --- zone plate ------------------------------------------------------------------


@pytest.mark.parametrize("max_frequency", [0.05, 0.25, 0.45])
def test_zone_plate_box_is_the_mean_over_each_output_pixel(max_frequency):
    shape, out_shape = (60, 75), (7, 9)
    exact = zone_plate_box(shape, out_shape, max_frequency)
    # Midpoint rule, 200 x 200 points per output pixel: error well below 1e-4.
    k = max_frequency / 75
    for row, column in [(0, 0), (3, 4), (6, 8), (2, 7)]:
        n = 200
        height, width = 60 / 7, 75 / 9
        ys = (row + (np.arange(n) + 0.5) / n) * height
        xs = (column + (np.arange(n) + 0.5) / n) * width
        values = 0.5 + 0.5 * np.cos(np.pi * k * (ys[:, None] ** 2 + xs[None, :] ** 2))
        assert exact[row, column] == pytest.approx(values.mean(), abs=1e-4)


def test_zone_plate_samples_the_same_function_at_pixel_centres():
    plate = zone_plate((30, 40), max_frequency=0.3)
    k = 0.3 / 40
    assert plate[7, 22] == pytest.approx(0.5 + 0.5 * np.cos(np.pi * k * (7.5**2 + 22.5**2)))
    assert plate.min() >= 0 and plate.max() <= 1


# --- bad input ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("call", "error", "words"),
    [
        (lambda: supersample(np.zeros((4, 4)), (0, 2), 2), ValueError, r"out_shape\[0\]"),
        (lambda: supersample(np.zeros((4, 4)), (2, -3), 2), ValueError, r"out_shape\[1\]"),
        (lambda: supersample(np.zeros((4, 4)), (2, 2), 0), ValueError, "rate must be >= 1"),
        (lambda: supersample(np.zeros((4, 4)), (2, 2), 1.5), TypeError, "rate must be an int"),
        (lambda: supersample(np.zeros((4, 4, 4)), (2, 2), 2), ValueError, r"image must be a gray"),
        (lambda: supersample(np.full((2, 2), np.nan), (1, 1), 2), ValueError, "finite"),
        (lambda: supersample(np.zeros((4, 4)), 2, 2), ValueError, "out_shape must be a pair"),
        (lambda: supersample(np.zeros((4, 4)), (2, 2), 2, method="x"), ValueError, "method"),
        (
            lambda: supersample_without_offset(np.zeros(4), (2, 2), 2),
            ValueError,
            r"image must be a gray",
        ),
        (lambda: bilinear(np.zeros((2, 2)), np.nan, 0.0), ValueError, "x must be finite"),
        (lambda: bilinear(np.zeros((2, 2)), 0.0, [np.inf]), ValueError, "y must be finite"),
        (lambda: bilinear(np.zeros((2, 2)), [1, 2], [1, 2, 3]), ValueError, "broadcast"),
        (lambda: bilinear(np.full((2, 2), 2.0), 0, 0), ValueError, r"in \[0, 1\]"),
        (lambda: zone_plate((4, 4), max_frequency=-1), ValueError, "max_frequency must be > 0"),
        (lambda: zone_plate_box((4, 4), (0, 1)), ValueError, r"out_shape\[0\]"),
        (lambda: measure_shift(supersample, 100, 2, 1), ValueError, "out_size must be >= 3"),
    ],
)
def test_bad_input_is_named(call, error, words):
    with pytest.raises(error, match=words):
        call()


def test_inputs_are_not_modified():
    image = rng.random((6, 6, 3))
    before = image.copy()
    supersample(image, (3, 3), 2)
    supersample_without_offset(image, (3, 3), 2)
    bilinear(image, 1.0, 1.0)
    np.testing.assert_array_equal(image, before)


# --- the exercise checker --------------------------------------------------------


@pytest.mark.parametrize("rate", [1, 3, 8])
def test_each_half_of_the_reports_mistake_shifts_the_picture_by_its_own_half(rate):
    image = np.random.default_rng(rate).random((23, 31))
    np.testing.assert_array_equal(
        supersample_shifted(image, (5, 7), rate), supersample(image, (5, 7), rate)
    )
    size, out = 2500, 320

    def corners(ramp, shape, r):
        return supersample_shifted(ramp, shape, r, sample_offset=0.0)

    def integer_centres(ramp, shape, r):
        return supersample_shifted(ramp, shape, r, pixel_centre=0.0)

    assert measure_shift(corners, size, out, rate) == pytest.approx(-1 / (2 * rate), abs=1e-9)
    assert measure_shift(integer_centres, size, out, rate) == pytest.approx(
        out / size / 2, abs=1e-9
    )
    with pytest.raises(ValueError, match="sample_offset"):
        supersample_shifted(image, (5, 7), rate, sample_offset=float("inf"))


@pytest.mark.parametrize(
    ("resampler", "error", "message"),
    [
        (lambda image, shape, rate: np.full(shape, np.nan), ValueError, "must be finite"),
        (lambda image, shape, rate: np.zeros((2, 3, 4)), ValueError, r"shape \(1, 8\)"),
        (lambda image, shape, rate: None, ValueError, r"shape \(1, 8\)"),
        (lambda image, shape, rate: "abc", TypeError, "resampler must return"),
    ],
)
def test_measure_shift_checks_what_the_resampler_returns(resampler, error, message):
    from course.sampling.resample import measure_shift

    with pytest.raises(error, match=message):
        measure_shift(resampler, 32, 8, 2)
