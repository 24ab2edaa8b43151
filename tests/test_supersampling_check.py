"""course.lessons.l04_supersampling.check: the lab's loop passes, the report's version is named."""

import math

import graded_draws
import numpy as np
import pytest

from course.lessons.l04_supersampling import check
from course.sampling.resample import (
    bilinear,
    supersample,
    supersample_shifted,
    supersample_without_offset,
)


def bilinear_sample(image, x, y, pixel_centre=0.5):
    """The lab's lookup, written as a student would: the checker fails a call to the library's."""
    image = np.asarray(image, dtype=float)
    height, width = image.shape[:2]
    u = min(max(x - pixel_centre, 0.0), width - 1.0)
    v = min(max(y - pixel_centre, 0.0), height - 1.0)
    left, top = min(int(np.floor(u)), max(width - 2, 0)), min(int(np.floor(v)), max(height - 2, 0))
    right, bottom = min(left + 1, width - 1), min(top + 1, height - 1)
    fx, fy = u - left, v - top
    upper = image[top, left] * (1 - fx) + image[top, right] * fx
    lower = image[bottom, left] * (1 - fx) + image[bottom, right] * fx
    return upper * (1 - fy) + lower * fy


def test_the_test_lookup_agrees_with_the_library():
    image = np.random.default_rng(1).random((3, 4, 3))
    for x, y in ((1.3, 0.9), (-0.4, 1.1), (3.9, 2.95), (0.5, 0.5), (2.0, 1.5)):
        np.testing.assert_allclose(bilinear_sample(image, x, y), bilinear(image, x, y), atol=1e-12)


def test_the_supersampling_checker_passes_a_loop_and_names_the_reports_version():
    def student(image, out_shape, rate):
        height, width = out_shape
        result = np.zeros((height, width, *image.shape[2:]))
        for row in range(height):
            for column in range(width):
                for j in range(rate):
                    for i in range(rate):
                        x = (column + (i + 0.5) / rate) * image.shape[1] / width
                        y = (row + (j + 0.5) / rate) * image.shape[0] / height
                        result[row, column] += bilinear_sample(image, x, y) / rate**2
        return result

    assert check.supersample(student)
    assert check.bilinear_sample(bilinear_sample)
    result = check.supersample(reports_version)
    assert not result and "case 1 is wrong" in result.message
    assert result.mistake == "the report's two shifts"
    result = check.supersample(lambda image, out_shape, rate: image[: out_shape[0]])
    assert not result and "case 1 is wrong" in result.message


def corner_samples(image, out_shape, rate):
    """A student's loop that starts each sample at its sub-pixel's corner."""
    height, width = out_shape
    in_height, in_width = image.shape[:2]
    result = np.zeros((height, width, *image.shape[2:]))
    for row in range(height):
        for column in range(width):
            for j in range(rate):
                for i in range(rate):
                    x = (column + i / rate) * in_width / width
                    y = (row + j / rate) * in_height / height
                    result[row, column] += bilinear_sample(image, x, y) / rate**2
    return result


def _shifted_loop(image, out_shape, rate, sample_offset, pixel_centre):
    height, width = out_shape
    in_height, in_width = image.shape[:2]
    result = np.zeros((height, width, *image.shape[2:]))
    for row in range(height):
        for column in range(width):
            for j in range(rate):
                for i in range(rate):
                    x = (column + (i + sample_offset) / rate) * in_width / width
                    y = (row + (j + sample_offset) / rate) * in_height / height
                    result[row, column] += bilinear_sample(image, x, y, pixel_centre) / rate**2
    return result


def integer_centres(image, out_shape, rate):
    """A student's loop whose lookup takes pixel k to sit at x = k."""
    return _shifted_loop(image, out_shape, rate, sample_offset=0.5, pixel_centre=0.0)


def reports_version(image, out_shape, rate):
    """The lab report's loop: samples at the sub-pixel corners, pixel k centred at k."""
    return _shifted_loop(image, out_shape, rate, sample_offset=0.0, pixel_centre=0.0)


def test_the_test_loops_agree_with_the_librarys_shifted_versions():
    image = np.random.default_rng(2).random((9, 12, 3))
    for out_shape, rate in (((4, 5), 2), ((3, 3), 3), ((12, 14), 2)):
        np.testing.assert_allclose(
            reports_version(image, out_shape, rate),
            supersample_without_offset(image, out_shape, rate),
            atol=1e-12,
        )
        np.testing.assert_allclose(
            integer_centres(image, out_shape, rate),
            supersample_shifted(image, out_shape, rate, pixel_centre=0.0),
            atol=1e-12,
        )
        np.testing.assert_allclose(
            corner_samples(image, out_shape, rate),
            supersample_shifted(image, out_shape, rate, sample_offset=0.0),
            atol=1e-12,
        )


def test_each_half_of_the_reports_shift_is_named_with_a_difference_picture():
    corners = check.supersample(corner_samples)
    assert corners.mistake == "samples at the sub-pixel corners" and corners.picture is not None
    centres = check.supersample(integer_centres)
    assert centres.mistake == "pixel centres at whole numbers"
    assert "first wrong value: [0, 1]" in str(centres)


def test_a_call_to_the_librarys_supersampling_or_lookup_is_told_to_write_it():
    for student in (
        supersample,
        supersample_without_offset,
        lambda image, out_shape, rate: supersample_shifted(image, out_shape, rate),
        lambda image, out_shape, rate: bilinear(image, 0.5, 0.5) + 0 * image[: out_shape[0]],
    ):
        result = check.supersample(student)
        assert not result
        assert result.message.startswith("your function calls course.sampling.")
        assert "the library's own answer: this exercise writes it" in result.message


def test_pixel_centres_at_whole_numbers_are_named_not_called_the_nearest_pixel():
    result = check.bilinear_sample(
        lambda image, x, y: bilinear_sample(image, x, y, pixel_centre=0.0)
    )
    assert not result and result.mistake == "pixel centres at whole numbers"
    assert str(result).startswith("FAIL bilinear_sample: case 1 is wrong")


def test_x_and_y_swapped_differs_from_the_answer_and_is_named():
    image = check._lookup_cases()[0]["image"]
    assert not np.isclose(bilinear(image, 0.8, 1.3), bilinear(image, 1.3, 0.8))
    result = check.bilinear_sample(lambda image, x, y: bilinear_sample(image, y, x))
    assert not result and result.mistake == "x and y swapped"


def test_the_reports_name_the_exercises_as_the_lesson_does():
    assert str(check.bilinear_sample(lambda image, x, y: 0.0)).startswith("FAIL bilinear_sample:")
    assert str(check.supersample(lambda image, out_shape, rate: image)).startswith(
        "FAIL supersample:"
    )


def _blend(swap: bool = False, flip: bool = False):
    """A student's bilinear lookup, with x and y swapped or the weights flipped if asked."""

    def lookup(image, x, y):
        image = np.asarray(image, dtype=float)
        height, width = image.shape[:2]
        if swap:
            x, y = y, x
        u, v = min(max(x - 0.5, 0), width - 1), min(max(y - 0.5, 0), height - 1)
        left, top = min(int(u), width - 2), min(int(v), height - 2)
        fx, fy = u - left, v - top
        if flip:
            fx, fy = 1 - fx, 1 - fy
        upper = image[top, left] * (1 - fx) + image[top, left + 1] * fx
        lower = image[top + 1, left] * (1 - fx) + image[top + 1, left + 1] * fx
        return upper * (1 - fy) + lower * fy

    return lookup


def test_flipped_weights_and_swapped_axes_are_told_apart():
    # At (1.3, 0.8) both give 0.575: the first case is one where they differ.
    assert check.bilinear_sample(_blend())
    assert check.bilinear_sample(_blend(swap=True)).mistake == "x and y swapped"
    assert check.bilinear_sample(_blend(flip=True)).mistake == "the weights flipped"


def _index_clamped(whole):
    """A lookup that clamps the four centres' indices, not u and v, taking ``whole`` of u."""

    def lookup(image, x, y):
        height, width = len(image), len(image[0])
        u, v = x - 0.5, y - 0.5
        left, top = whole(u), whole(v)
        fx, fy = u - left, v - top

        def at(row, column):
            return np.asarray(image[min(max(row, 0), height - 1)][min(max(column, 0), width - 1)])

        upper = (1 - fx) * at(top, left) + fx * at(top, left + 1)
        lower = (1 - fx) * at(top + 1, left) + fx * at(top + 1, left + 1)
        return (1 - fy) * upper + fy * lower

    return lookup


def test_int_for_floor_is_named_and_the_same_lookup_with_floor_passes():
    assert check.bilinear_sample(_index_clamped(math.floor))
    result = check.bilinear_sample(_index_clamped(int))
    assert result.mistake == "int() where floor belongs"
    assert "x=-0.4" in str(result)


def test_offsets_left_unscaled_are_named_and_not_blamed_on_a_correct_lookup():
    # Only the corner is scaled by W / w; the report's two shifts would send the student to
    # "fix" a lookup that passes its own check.
    def unscaled(image, out_shape, rate):
        height, width = out_shape
        sx, sy = image.shape[1] / width, image.shape[0] / height
        result = np.zeros((height, width, *image.shape[2:]))
        for row in range(height):
            for column in range(width):
                for j in range(rate):
                    for i in range(rate):
                        x, y = column * sx + (i + 0.5) / rate, row * sy + (j + 0.5) / rate
                        result[row, column] += bilinear_sample(image, x, y) / rate**2
        return result

    result = check.supersample(unscaled)
    assert result.mistake == "the sub-pixel offsets not scaled"
    assert "x = (c + (i + 0.5) / rate) W / w" in str(result)
    assert check.supersample(reports_version).mistake == "the report's two shifts"


def test_swapped_scales_are_named_not_taken_for_a_whole_scale():
    def swapped(image, out_shape, rate):
        height, width = out_shape
        sx, sy = image.shape[0] / height, image.shape[1] / width  # x by H / h: the slip
        result = np.zeros((height, width, *image.shape[2:]))
        for row in range(height):
            for column in range(width):
                for j in range(rate):
                    for i in range(rate):
                        x, y = (column + (i + 0.5) / rate) * sx, (row + (j + 0.5) / rate) * sy
                        result[row, column] += bilinear_sample(image, x, y) / rate**2
        return result

    assert check.supersample(swapped).mistake == "the two scales swapped"


# --- graded: cases drawn for each submission ------------------------------------------------


def test_graded_supersampling_cases_are_drawn_in_the_fixed_cases_families():
    fixed = check._cases()
    for cases in graded_draws.check_drawn_cases("supersample"):
        for case, like in zip(cases, fixed, strict=True):
            assert case["image"].shape == like["image"].shape
            assert (case["out_shape"], case["rate"]) == (like["out_shape"], like["rate"])
            assert 0 <= case["image"].min() and case["image"].max() <= 1
        stripes = cases[0]["image"]
        assert all(c["image"] is stripes for c in cases[:3])
        low, high = sorted(set(stripes[0, :2]))
        assert low <= 0.4 and high >= 0.6 and (stripes == np.tile(stripes[0, :2], (6, 6))).all()


def test_graded_lookup_cases_are_drawn_in_the_fixed_cases_families():
    for cases in graded_draws.check_drawn_cases("bilinear_sample"):
        gray, colour = cases[0]["image"], cases[-1]["image"]
        assert gray.shape == (3, 4) and colour.shape == (2, 3, 3)
        assert all(c["image"] is gray for c in cases[:10])
        x, y = np.array([(c["x"], c["y"]) for c in cases]).T
        assert (x[2] % 1, y[2] % 1, x[3] % 1, y[3] % 1) == (0.5, 0.5, 0, 0.5)
        inside = (0.5 < x) & (x < 3.5) & (0.5 < y) & (y < 2.5)
        assert inside[[0, 1]].all() and not inside[[4, 5, 6, 7, 8, 9]].any()
        assert (x[[4, 7, 9]] > 3.5).all() and (y[[4, 8, 9]] > 2.5).all()
        assert -0.5 < x[5] < 0.5 and y[6] < 0.5


@pytest.mark.parametrize("name", ["supersample", "bilinear_sample"])
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(name):
    graded_draws.check_graded(name)


def loop_supersample(image, out_shape, rate, scale=lambda size, out: size / out):
    """The lab's loop over the test lookup; ``scale`` makes the input size per output pixel."""
    (height, width), (in_height, in_width) = out_shape, image.shape[:2]
    sx, sy = scale(in_width, width), scale(in_height, height)
    result = np.zeros((height, width, *image.shape[2:]))
    for row in range(height):
        for column in range(width):
            for j in range(rate):
                for i in range(rate):
                    x, y = (column + (i + 0.5) / rate) * sx, (row + (j + 0.5) / rate) * sy
                    result[row, column] += bilinear_sample(image, x, y) / rate**2
    return result


def test_the_scale_made_whole_is_named_with_no_sizes_of_another_case():
    # The student: W // w and H // h. Case 1 (12 -> 5 wide, 6 -> 4 high) fails first,
    # so the words must not speak of 25 // 3, another case's sizes.
    whole = check.supersample(
        lambda image, out_shape, rate: loop_supersample(image, out_shape, rate, lambda a, b: a // b)
    )
    assert whole.mistake == "the scale made whole" and "case 1 is wrong" in str(whole)
    assert "25 // 3" not in str(whole) and "8.33" not in str(whole)
    assert "W // w for W / w, H // h for H / h" in str(whole)


def test_an_input_changed_by_one_part_in_ten_million_is_shown_changed():
    # The report said "element [0, 1] was 1, is now 1": six digits hid the change.
    def scales_its_input(image, out_shape, rate):
        image *= 1.0000001
        return loop_supersample(image, out_shape, rate)

    result = check.supersample(scales_its_input)
    assert not result
    assert "changed its input image: element [0, 1] was 1.0, is now 1.0000001" in str(result)


# --- the readers' students ------------------------------------------------------------------


def lookup(image, x, y, base=math.floor, clamp="centres"):
    """A student's lookup: ``base`` takes the top-left centre of x - 1/2; ``clamp`` is where the
    point is kept: "centres" (x - 1/2 in [0, W - 1], the lesson's), "point" (x in [0, W - 1],
    then the shift), "image" (x in [0, W]) or "none"."""
    height, width = image.shape[:2]
    if clamp == "point":
        x, y = min(max(x, 0), width - 1), min(max(y, 0), height - 1)
    if clamp == "image":
        x, y = min(max(x, 0), width), min(max(y, 0), height)
    u, v = x - 0.5, y - 0.5
    if clamp == "centres":
        u, v = min(max(u, 0), width - 1), min(max(v, 0), height - 1)
    left, top = base(u), base(v)
    if clamp != "none":
        left, top = min(max(left, 0), width - 2), min(max(top, 0), height - 2)
    fx, fy = u - left, v - top
    upper = image[top, left] * (1 - fx) + image[top, left + 1] * fx
    lower = image[top + 1, left] * (1 - fx) + image[top + 1, left + 1] * fx
    return upper * (1 - fy) + lower * fy


def test_the_students_lookup_with_floor_and_the_lessons_clamp_passes():
    assert check.bilinear_sample(lookup)


@pytest.mark.parametrize(
    ("options", "case", "mistake", "said"),
    [
        ({"base": round}, 1, "round() where floor belongs", "c = math.floor(x - 0.5)"),
        ({"clamp": "point"}, 5, "clamped before the half-pixel shift", "Clamp after the shift"),
        ({"clamp": "image"}, 5, "no clamp at the right or bottom edge", "x <= W, is not enough"),
    ],
)
def test_a_lookups_base_and_clamp_slips_are_named_with_a_picture(options, case, mistake, said):
    result = check.bilinear_sample(lambda image, x, y: lookup(image, x, y, **options))
    assert not result and result.mistake == mistake, str(result)
    assert f"case {case} is wrong" in str(result) and said in str(result)
    assert result.picture.startswith(b"\x89PNG")


def test_a_lookup_with_no_clamp_that_reads_past_the_image_is_named():
    result = check.bilinear_sample(lambda image, x, y: lookup(image, x, y, clamp="none"))
    assert "case 5 raised IndexError" in str(result) and "at line" in str(result)
    assert result.mistake == "a read past the image", str(result)
    assert "Clamp x - 0.5 to [0, W - 1]" in str(result)


def test_an_index_error_the_missing_clamp_cannot_cause_is_not_named_as_it():
    def reads_a_row_too_far(image, x, y):
        image[len(image)]  # on every case, the point inside or not
        return lookup(image, x, y)

    result = check.bilinear_sample(reads_a_row_too_far)
    assert "case 1 raised IndexError" in str(result) and result.mistake is None


def test_a_wrong_lookup_draws_the_point_its_four_centres_and_both_values(monkeypatch):
    drawn = []
    monkeypatch.setattr(check, "figure_png", lambda figure: drawn.append(figure) or b"\x89PNG")
    result = check.bilinear_sample(lambda image, x, y: lookup(image, x, y, clamp="point"))
    assert result.picture == b"\x89PNG"
    (figure,) = drawn
    assert figure._suptitle.get_text() == "(3.2, 2.8): expected 0.7, yours 0.5"
    (axes,) = figure.axes
    marks = {line.get_label(): line.get_xydata().tolist() for line in axes.lines}
    assert marks["the point (x, y)"] == [[3.2, 2.8]]
    # The lesson's four centres at (3.2, 2.8): columns 2 and 3, rows 1 and 2 (y clamped to 2).
    assert sorted(map(tuple, marks["the four centres blended"])) == [
        (2.5, 1.5),
        (2.5, 2.5),
        (3.5, 1.5),
        (3.5, 2.5),
    ]


def spaced_loop(offsets, dtype=float, finish=lambda result: result):
    """A student's supersampling loop with the samples of each axis at ``offsets(rate)``, in
    output pixels from the pixel's corner, into a result of ``dtype``, passed to ``finish``."""

    def supersample_loop(image, out_shape, rate):
        (height, width), (in_height, in_width) = out_shape, image.shape[:2]
        result = np.zeros((height, width, *image.shape[2:]), dtype=dtype)
        for row in range(height):
            for column in range(width):
                for dy in offsets(rate):
                    for dx in offsets(rate):
                        x = (column + dx) * in_width / width
                        y = (row + dy) * in_height / height
                        result[row, column] += bilinear_sample(image, x, y) / rate**2
        return finish(result)

    return supersample_loop


def centres(rate):
    return [(i + 0.5) / rate for i in range(rate)]


@pytest.mark.parametrize(
    ("offsets", "mistake"),
    [
        (lambda rate: [i / rate for i in range(rate)], "samples at the sub-pixel corners"),
        (lambda rate: list(np.linspace(0, 1, rate)), "samples from edge to edge"),
        (lambda rate: [i / (rate - 1) if rate > 1 else 0.5 for i in range(rate)], None),
        (lambda rate: [(i + 1) / (rate + 1) for i in range(rate)], "samples 1 / (rate + 1) apart"),
    ],
)
def test_samples_spaced_otherwise_than_the_sub_pixel_centres_are_named(offsets, mistake):
    assert check.supersample(spaced_loop(centres))
    result = check.supersample(spaced_loop(offsets))
    # i / (rate - 1) is np.linspace(0, 1, rate) written out: the same mistake.
    assert result.mistake == (mistake or "samples from edge to edge"), str(result)
    assert "case 1 is wrong" in str(result)


ZEROS = "every pixel you returned is 0: no mean reached your result"


@pytest.mark.parametrize(
    ("student", "explanation"),
    [
        # Each sample's share, below 1, is cut to 0 as it is added into an integer result;
        # cast at the end, every mean below 1 is: the cases' answers are all zeros.
        (
            spaced_loop(centres, dtype=int),
            ZEROS,
        ),
        (
            spaced_loop(centres, dtype=np.uint8),
            ZEROS,
        ),
        (
            spaced_loop(centres, finish=lambda result: result.astype(np.uint8)),
            ZEROS,
        ),
        (
            spaced_loop(centres, finish=lambda result: np.round(result).astype(int)),
            "every value you returned is a whole number",
        ),
        # Nothing stored: the result as it was made.
        (
            lambda image, out_shape, rate: np.zeros((*out_shape, *image.shape[2:])),
            ZEROS,
        ),
    ],
    ids=["int array", "uint8 array", "astype uint8", "rounded to int", "nothing stored"],
)
def test_whole_numbers_and_lost_means_are_named(student, explanation):
    result = check.supersample(student)
    assert not result and result.mistake == "means cut to whole numbers, or never stored", str(
        result
    )
    assert explanation in str(result) and "Make the result a float array" in str(result)
