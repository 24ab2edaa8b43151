"""course.lessons.l07_filtering.check: the lab's Blur and Edge, right and wrong."""

import warnings

import graded_draws
import numpy as np
import pytest

import course
from course import filters
from course.check import base
from course.lessons.l07_filtering import check

# The students below are written here, as a student would write them: the checkers fail
# an answer that calls the library's own blur, sobel or convolve.
SOBEL_X = np.array([[-1.0, 0.0, 1.0], [-2.0, 0.0, 2.0], [-1.0, 0.0, 1.0]])


def _windows(image, border):
    """Each pixel's 3 x 3 window, shape (H, W, 3, 3, ...), and how many of its pixels exist."""
    image = np.asarray(image, dtype=float)
    pad = [(1, 1), (1, 1)] + [(0, 0)] * (image.ndim - 2)
    padded = np.pad(image, pad, mode="edge" if border == "replicate" else "constant")
    inside = np.pad(np.ones(image.shape[:2]), 1)
    height, width = image.shape[:2]
    windows = np.stack(
        [
            np.stack([padded[dy : dy + height, dx : dx + width] for dx in range(3)], axis=2)
            for dy in range(3)
        ],
        axis=2,
    )
    counts = sum(inside[dy : dy + height, dx : dx + width] for dy in range(3) for dx in range(3))
    return windows, counts


def box_blur(image, border="inside"):
    """The 3 x 3 mean; "inside" divides by the neighbours that exist, the others by 9."""
    windows, counts = _windows(image, border)
    total = windows.sum(axis=(2, 3))
    divisor = counts if border == "inside" else np.full(counts.shape, 9.0)
    return total / (divisor if total.ndim == 2 else divisor[..., None])


def correlate(image, kernel, border="replicate"):
    """The handout's dot product of ``kernel`` with each 3 x 3 window."""
    windows, _ = _windows(image, border)
    kernel = np.asarray(kernel, dtype=float)
    weights = kernel if windows.ndim == 4 else kernel[..., None]
    return (windows * weights).sum(axis=(2, 3))


def sobel_magnitude(image, border="replicate"):
    return np.hypot(correlate(image, SOBEL_X, border), correlate(image, SOBEL_X.T, border))


def numpy_reflect_sobel(image):
    """Sobel on np.pad(mode="reflect"), the mirror about the edge pixel: a naming trap."""
    array = np.asarray(image, dtype=float)
    padded = np.pad(array, [(1, 1), (1, 1)] + [(0, 0)] * (array.ndim - 2), mode="reflect")
    height, width = array.shape[:2]
    windows = [[padded[dy : dy + height, dx : dx + width] for dx in range(3)] for dy in range(3)]
    gx = sum(SOBEL_X[dy, dx] * windows[dy][dx] for dy in range(3) for dx in range(3))
    gy = sum(SOBEL_X.T[dy, dx] * windows[dy][dx] for dy in range(3) for dx in range(3))
    return np.hypot(gx, gy)


def test_the_test_students_agree_with_the_library():
    rng = np.random.default_rng(0)
    for image in (rng.random((5, 7)), rng.random((1, 1)), rng.random((4, 5, 3))):
        np.testing.assert_allclose(box_blur(image), filters.blur(image), atol=1e-12)
        for border in ("zero", "replicate"):
            np.testing.assert_allclose(
                box_blur(image, border), filters.convolve(image, filters.BOX, border), atol=1e-12
            )
            np.testing.assert_allclose(
                sobel_magnitude(image, border), filters.sobel(image, border), atol=1e-12
            )


def test_blur_checker_passes_the_loop_and_fails_zero_padding_naming_the_case():
    assert check.blur(box_blur)
    result = check.blur(lambda image: box_blur(image, "zero"))
    assert not result and "case 1 is wrong" in result.message
    assert result.mistake == "zero padding"


def test_blur_and_edge_tell_a_call_to_the_library_to_write_it():
    for student, name in (
        (lambda image: filters.blur(image, method="loop"), "blur"),
        (lambda image: filters.convolve(image, filters.BOX, "zero"), "convolve"),
    ):
        result = check.blur(student)
        assert not result
        assert result.message.startswith(
            f"your function calls course.filters.{name}, the library's own answer: "
            "this exercise writes it"
        )
    result = check.edge(lambda image: filters.sobel(image, method="loop"))
    assert not result
    assert result.message.startswith("your function calls course.filters.sobel")


def test_edge_checker_passes_sobel_and_fails_prewitt_and_a_black_border():
    assert check.edge(sobel_magnitude)
    prewitt = np.array([[-1, 0, 1], [-1, 0, 1], [-1, 0, 1]])

    def prewitt_magnitude(image):
        return np.hypot(correlate(image, prewitt), correlate(image, prewitt.T))

    assert not check.edge(prewitt_magnitude)
    result = check.edge(lambda image: sobel_magnitude(image, "zero"))
    assert not result and "case 1 is wrong" in result.message
    assert result.mistake == "zero padding"


def test_the_clipped_magnitude_names_sobels_true_range():
    # A window with Gx = 4 and Gy = 2 is the largest: sqrt(20).
    window = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.0, 1.0, 1.0]])
    assert np.hypot((SOBEL_X * window).sum(), (SOBEL_X.T * window).sum()) == np.sqrt(20)
    result = check.edge(lambda image: np.clip(sobel_magnitude(image), 0, 1))
    assert result.mistake == "clipped to 1"
    assert "up to sqrt(20), about 4.47" in result.message


def _frame_zero(function):
    def student(image):
        output = np.zeros_like(np.asarray(image, dtype=float))
        output[1:-1, 1:-1] = function(image)[1:-1, 1:-1]
        return output

    return student


def _frame_copied(image):
    output = np.array(image, dtype=float)
    output[1:-1, 1:-1] = box_blur(image)[1:-1, 1:-1]
    return output


@pytest.mark.parametrize(
    ("student", "mistake"),
    [
        (lambda image: box_blur(image, "zero"), "zero padding"),
        (_frame_zero(box_blur), "the frame skipped"),
        (_frame_copied, "the frame copied"),
        (
            lambda image: box_blur(image, "replicate"),
            "the edge pixel repeated",
        ),
    ],
)
def test_blur_mistakes_are_named_with_a_map_and_the_first_pixel(student, mistake):
    result = check.blur(student)
    assert not result
    assert result.mistake == mistake
    assert result.picture is not None and result.picture.startswith(b"\x89PNG")
    # The first case's first wrong pixel is the top-left corner: 4 of its 9 neighbours inside;
    # a border slip leaves the 4 x 4 case's inner 2 x 2 right, and the report says so.
    assert (
        "the first wrong pixel is (x, y) = (0, 0), on the border: 4 of 9 inside, and every pixel "
        "inside the image is right; 12 pixels differ" in result.message
    )


@pytest.mark.parametrize(
    ("student", "mistake"),
    [
        (lambda image: sobel_magnitude(image, "zero"), "zero padding"),
        (lambda image: np.clip(sobel_magnitude(image), 0, 1), "clipped to 1"),
        (lambda image: np.abs(correlate(image, SOBEL_X)), "Gx alone"),
        (_frame_zero(sobel_magnitude), "the frame skipped"),
        (numpy_reflect_sobel, "numpy's 'reflect' padding"),
        (lambda image: sobel_magnitude(image) ** 2, "the sum of squares, no root"),
        (
            lambda image: np.abs(correlate(image, SOBEL_X)) + np.abs(correlate(image, SOBEL_X.T)),
            "|Gx| + |Gy|",
        ),
    ],
)
def test_edge_mistakes_are_named_with_a_map(student, mistake):
    result = check.edge(student)
    assert not result
    assert result.mistake == mistake
    assert result.picture is not None
    assert "pixels differ" in result.message


def running_blur(image):
    """The box blur written into a copy that it also reads: later windows see blurred pixels."""
    output = np.array(image, dtype=float)
    for y in range(output.shape[0]):
        for x in range(output.shape[1]):
            window = output[max(y - 1, 0) : y + 2, max(x - 1, 0) : x + 2]
            output[y, x] = window.mean(axis=(0, 1))
    return output


def test_a_blur_reading_its_own_updated_values_is_named():
    result = check.blur(running_blur)
    assert not result and result.mistake == "a blur that reads its own updated values"
    assert "Read every window from the input as it was" in result.message
    # Its first wrong pixel, (1, 0), is on the border, but the cause is not: (1, 1) is wrong too.
    assert "the first wrong pixel is (x, y) = (1, 0), on the border, but pixels inside" in str(
        result
    )


def _kernel_sum(kernel_x, kernel_y, combine):
    return lambda image: combine(correlate(image, kernel_x), correlate(image, kernel_y))


PREWITT_X = np.array([[-1.0, 0.0, 1.0]] * 3)


@pytest.mark.parametrize(
    "student",
    [
        _kernel_sum(SOBEL_X, SOBEL_X.T, lambda gx, gy: np.abs(gx) + np.abs(gy)),
        _kernel_sum(SOBEL_X, SOBEL_X.T, lambda gx, gy: gx**2 + gy**2),
        _kernel_sum(SOBEL_X, SOBEL_X.T, lambda gx, gy: np.hypot(gx, gy) / 8),
        _kernel_sum(PREWITT_X, PREWITT_X.T, np.hypot),
        _kernel_sum(SOBEL_X, SOBEL_X, np.hypot),
    ],
    ids=["|Gx|+|Gy|", "no sqrt", "/8", "Prewitt", "Gy = Gx"],
)
def test_a_wrong_kernel_or_sum_is_sent_inside_the_image_not_to_the_border(student):
    # On the 4 x 4 case the first wrong pixel in reading order is the corner (0, 0); a mistake
    # unrelated to the border is wrong at (1, 1) too, and the report sends the student there.
    message = str(check.edge(student))
    assert (
        "(x, y) = (0, 0), on the border, but pixels inside the image are wrong too, the first "
        "at (x, y) = (1, 1), where all 9 neighbours exist: start there" in message
    )
    assert "every pixel inside the image is right" not in message
    assert "Hint: first check one pixel inside the image by hand" in message


def test_an_interior_error_is_placed_inside_the_image():
    def off_by_one_pixel(image):
        output = box_blur(image)
        if output.shape[:2] == (8, 10):
            output[4, 5] += 0.25
        return output

    result = check.blur(off_by_one_pixel)
    assert "(x, y) = (5, 4), inside the image; 1 pixel differs" in result.message
    assert result.mistake is None


def nan_padded(image, mean=np.mean, pad_colours=False):
    """The handout's rule through NaN padding: right with np.nanmean, NaN on the border with
    np.mean; np.pad(image, 1) also pads an RGB image's colour axis with NaN."""
    border = 1 if pad_colours else [(1, 1), (1, 1)] + [(0, 0)] * (image.ndim - 2)
    padded = np.pad(image, border, constant_values=np.nan)
    output = np.zeros_like(image)
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for y in range(image.shape[0]):
            for x in range(image.shape[1]):
                window = padded[y : y + 3, x : x + 3]
                output[y, x] = mean(window[..., :3] if image.ndim == 3 else window, axis=(0, 1))
    return output


def test_a_nan_output_says_which_pixel_where_and_why():
    assert check.blur(lambda image: nan_padded(image, np.nanmean))
    border = str(check.blur(nan_padded))
    assert "case 1: your answer holds nan at [0, 0]" in border
    assert "output pixel (x, y) = (0, 0) is NaN; it lies on the border" in border
    assert "only 4 of its 9 neighbours are inside the image" in border
    assert "12 of the 12 border pixels are NaN, 0 inside" in border
    assert "np.nanmean skips it" in border
    colours = str(check.blur(lambda image: nan_padded(image, np.nanmean, pad_colours=True)))
    assert "case 8:" in colours  # the gray cases pass: only the RGB padding is wrong
    assert "output pixel (x, y) = (0, 0), channel 0 (red), is NaN" in colours
    assert "red at every pixel, inside the image too" in colours
    assert "((1, 1), (1, 1), (0, 0))" in colours


@pytest.fixture
def in_chinese(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    course.use_language("zh-CN")
    yield
    course.use_language("en")


def test_blur_and_edge_report_in_chinese(in_chinese):
    blurred = str(check.blur(lambda image: image))
    assert blurred.startswith("blur 未通过：第 1 个用例结果错误\n  输入：image=")
    assert (
        "个像素不同；第一个出错的像素是 (x, y) = (0, 0)，在边界上。但图像内部也有像素出错"
        in blurred
    )
    border = str(check.blur(lambda image: box_blur(image, "zero")))
    assert (
        "(0, 0)，在边界上（3 × 3 邻域的 9 个像素中有 4 个在图像内），而图像内部的每个像素都是对的"
        in border
    )
    edge = str(check.edge(lambda image: sobel_magnitude(image, "zero")))
    assert "常见错误：零填充。" in edge and "Hint" not in edge
    nan = str(check.blur(nan_padded))
    assert "第 1 个用例：你的答案在 [0, 0] 处是 nan，而每个值都必须是有限数" in nan
    assert "输出像素 (x, y) = (0, 0) 是 NaN。它在边界上，9 个相邻像素中只有 4 个在图像内" in nan
    colours = str(check.blur(lambda image: nan_padded(image, np.nanmean, pad_colours=True)))
    assert "输出像素 (x, y) = (0, 0) 的通道 0（红） 是 NaN，而且每个像素的红通道都是 NaN" in colours


# --- graded: cases drawn for each submission ------------------------------------------------


@pytest.mark.parametrize("name", ["blur", "edge"])
def test_graded_cases_are_drawn_in_the_fixed_cases_families(name):
    fixed = check._cases()
    for cases in graded_draws.check_drawn_cases(name):
        assert [c["image"].shape for c in cases] == [c["image"].shape for c in fixed]
        assert all(0 <= c["image"].min() and c["image"].max() <= 1 for c in cases)
        square = cases[1]["image"]
        dark, bright = np.unique(square)
        inside = np.argwhere(square == bright)
        assert dark <= 0.3 and bright >= 0.7 and inside.min() >= 1
        assert (inside.max(axis=0) <= (6, 8)).all() and len(inside) >= 12


@pytest.mark.parametrize("name", ["blur", "edge"])
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(name):
    graded_draws.check_graded(name)


# --- the readers' students (issue 34): the border read another way, and 8-bit sums ---------


def padded_blur(image, mode):
    """The 3 x 3 mean of a window of the image padded by np.pad(mode=...), divided by 9."""
    padded = np.pad(image, [(1, 1), (1, 1)] + [(0, 0)] * (image.ndim - 2), mode=mode)
    output = np.zeros_like(image)
    for y in range(image.shape[0]):
        for x in range(image.shape[1]):
            output[y, x] = padded[y : y + 3, x : x + 3].mean(axis=(0, 1))
    return output


def rolled_blur(image):
    """The nine shifted copies of np.roll, summed and divided by 9: the image wraps around."""
    total = sum(np.roll(image, (dy, dx), axis=(0, 1)) for dy in (-1, 0, 1) for dx in (-1, 0, 1))
    return total / 9


def uint8_blur(image, overflow=True):
    """The report's rule on the image as 8-bit grey levels, as the lab's C++ holds it; the sum
    kept in uint8 (0 + a uint8 is a uint8 in NumPy 2) wraps past 255."""
    pixels = (image * 255).astype(np.uint8)
    height, width = pixels.shape[:2]
    output = np.zeros(image.shape)
    with np.errstate(over="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for y in range(height):
            for x in range(width):
                window = pixels[max(y - 1, 0) : y + 2, max(x - 1, 0) : x + 2]
                if not overflow:
                    output[y, x] = window.mean(axis=(0, 1)) / 255
                    continue
                total, count = 0, 0
                for row in window:
                    for value in row:
                        total += value
                        count += 1
                output[y, x] = total / count / 255
    return output


@pytest.mark.parametrize(
    ("student", "mistake", "words"),
    [
        (lambda image: padded_blur(image, "reflect"), "numpy's 'reflect' padding", "d c b | a b"),
        (lambda image: padded_blur(image, "wrap"), "the image wrapped around", "np.roll"),
        (rolled_blur, "the image wrapped around", "the opposite side of the image"),
        (uint8_blur, "8-bit sums that overflow", "200 + 100 gives 44"),
        (lambda image: uint8_blur(image, overflow=False), "the image cut to 8 bits", "1/255"),
    ],
    ids=["reflect", "pad wrap", "np.roll", "uint8 sums", "uint8 mean"],
)
def test_a_blur_that_reads_past_the_edge_or_sums_in_8_bits_is_named(student, mistake, words):
    result = check.blur(student)
    assert not result and result.mistake == mistake
    assert f"This is a known mistake, {mistake}: " in result.message
    assert words in result.message


def test_a_float32_blur_is_not_taken_for_an_8_bit_one():
    # Off by float32's rounding, below a grey level but not on the 8-bit grid.
    result = check.blur(lambda image: box_blur(image.astype(np.float32)))
    assert not result and result.mistake is None
    assert check.blur(lambda image: box_blur(image))


def edge_frame_copied(image):
    """Sobel on the inside only, the output started as a copy of the input."""
    output = np.array(image, dtype=float)
    output[1:-1, 1:-1] = sobel_magnitude(image)[1:-1, 1:-1]
    return output


def test_an_edge_that_copies_its_frame_from_the_input_is_named_not_zero_padding():
    result = check.edge(edge_frame_copied)
    assert not result and result.mistake == "the frame copied"
    assert "leave the input's values there" in result.message
    assert "as 0" not in result.message
