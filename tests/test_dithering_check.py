"""course.lessons.l06_dithering.check: a correct loop passes, the handout's slip fails by case."""

import warnings

import graded_draws
import numpy as np
import pytest

import course
from course.check import base
from course.halftone import dither
from course.lessons.l06_dithering import check


def test_checker_passes_a_correct_loop_and_fails_the_wraparound_slip_naming_the_case():
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


M = [[6, 8, 4], [1, 0, 3], [5, 2, 7]]


def nine_ifs(gray, transposed=False, at_least=False):
    """The lab's ordered dithering as a student writes it, with the slips it invites."""
    height, width = gray.shape
    output = np.zeros((3 * height, 3 * width))
    for y in range(height):
        for x in range(width):
            for i in range(3):
                for j in range(3):
                    level = (M[j][i] if transposed else M[i][j]) / 9
                    lit = gray[y, x] >= level if at_least else gray[y, x] > level
                    output[3 * y + i, 3 * x + j] = 1.0 if lit else 0.0
    return output


def test_ordered_dithering_passes_and_its_slips_are_named():
    # Four cases: the levels on M / 9, a 2 x 3 image, noise and the small face.
    passed = check.dithering_ordered(nine_ifs)
    assert str(passed) == "PASS dithering_ordered: all 4 cases pass"
    assert passed.picture is not None and passed.picture.startswith(b"\x89PNG")
    transposed = check.dithering_ordered(lambda gray: nine_ifs(gray, transposed=True))
    assert transposed.mistake == "the matrix transposed" and transposed.picture is not None
    assert check.dithering_ordered(lambda gray: nine_ifs(gray, at_least=True)).mistake == ">= for >"


def floyd_steinberg(gray, guard_left=True, serpentine=False, read_errors=True, sign=1.0):
    height, width = gray.shape
    buffer, output = gray.copy(), np.zeros_like(gray)
    for y in range(height):
        columns = range(width - 1, -1, -1) if serpentine and y % 2 else range(width)
        step = -1 if serpentine and y % 2 else 1
        for x in columns:
            value = buffer[y, x] if read_errors else gray[y, x]
            output[y, x] = 1.0 if value > 0.5 else 0.0
            error = sign * (value - output[y, x])
            for dx, dy, weight in ((step, 0, 7), (-step, 1, 3), (0, 1, 5), (step, 1, 1)):
                inside = 0 <= x + dx < width if guard_left else x + dx < width
                if inside and y + dy < height:
                    buffer[y + dy, x + dx] += error * weight / 16
    return output


def test_error_diffusion_names_its_slips_and_what_reached_the_first_wrong_pixel():
    assert check.dithering_error_diffuse(floyd_steinberg)
    wrapped = check.dithering_error_diffuse(lambda gray: floyd_steinberg(gray, guard_left=False))
    assert wrapped.mistake == "the left edge wraps around"
    assert "first wrong pixel (x=" in str(wrapped) and "plus the error carried into it" in str(
        wrapped
    )
    serpentine = check.dithering_error_diffuse(lambda gray: floyd_steinberg(gray, serpentine=True))
    assert serpentine.mistake == "a serpentine scan"
    unread = check.dithering_error_diffuse(lambda gray: floyd_steinberg(gray, read_errors=False))
    assert unread.mistake == "the errors are never read" and unread.picture is not None


def test_a_flipped_sign_and_unread_errors_are_told_apart():
    # On a flat 0.5 both give all black; the checker's first case, a ramp, tells them apart.
    flipped = check.dithering_error_diffuse(lambda gray: floyd_steinberg(gray, sign=-1.0))
    assert flipped.mistake == "the error's sign flipped" and "case 1 is wrong" in str(flipped)
    unread = check.dithering_error_diffuse(lambda gray: floyd_steinberg(gray, read_errors=False))
    assert unread.mistake == "the errors are never read" and "case 1 is wrong" in str(unread)


def test_an_answer_in_0_and_255_is_named_in_both_checkers():
    # A student used to 8-bit images writes 255 for a lit pixel; the lesson's range is 0 and 1.
    ordered = check.dithering_ordered(lambda gray: 255 * nine_ifs(gray))
    assert ordered.mistake == "0 and 255 for 0 and 1"
    assert "your output holds the values 0, 255: the lesson's output is 0 (dark) or 1" in str(
        ordered
    )
    diffused = check.dithering_error_diffuse(lambda gray: np.uint8(255) * floyd_steinberg(gray))
    assert diffused.mistake == "0 and 255 for 0 and 1"
    assert "Write 1.0 where you wrote 255" in str(diffused)


@pytest.fixture
def in_chinese(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    course.use_language("zh-CN")
    yield
    course.use_language("en")


def test_both_checkers_report_in_chinese(in_chinese):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = check.dithering_ordered(lambda gray: 255 * nine_ifs(gray))
    assert result.picture is not None  # its titles in Chinese, every glyph in the font
    assert not [w for w in caught if "missing from font" in str(w.message)]
    ordered = str(result)
    assert ordered.startswith("dithering_ordered 未通过：第 1 个用例结果错误\n  输入：gray=")
    assert "你的输出含有这些值：0, 255。本课的输入是 [0, 1] 内的灰度，" in ordered
    assert "输出只能是 0（暗）或 1（亮）" in ordered
    assert "常见错误：用 0 和 255 代替了 0 和 1。" in ordered
    assert "提示：看看输出的大小" in ordered and "Hint" not in ordered
    unread = check.dithering_error_diffuse(lambda gray: floyd_steinberg(gray, read_errors=False))
    assert "常见错误：误差从未被读取。" in str(unread)
    assert unread.mistake == "the errors are never read"  # the name stays an identifier


def in_place(gray):
    """Floyd-Steinberg pushing its errors into the caller's image, with no copy."""
    height, width = gray.shape
    output = np.zeros_like(gray)
    for y in range(height):
        for x in range(width):
            output[y, x] = 1.0 if gray[y, x] > 0.5 else 0.0
            error = gray[y, x] - output[y, x]
            for dx, dy, weight in ((1, 0, 7), (-1, 1, 3), (0, 1, 5), (1, 1, 1)):
                if 0 <= x + dx < width and y + dy < height:
                    gray[y + dy, x + dx] += error * weight / 16
    return output


def test_diffusing_into_the_input_fails_and_points_at_the_reports_copy():
    # The output is right, but the caller's image changed. The report copies its const input,
    # so the message must not call the in-place loop the report's own slip.
    result = check.dithering_error_diffuse(in_place)
    message = str(result)
    assert not result and "gray" in message
    assert "its input is const, so it pushes the errors into a copy (inputcopy)" in message
    assert "own slip" not in message


# --- graded: cases drawn for each submission ------------------------------------------------


def test_graded_ordered_cases_are_drawn_in_the_fixed_cases_families():
    fixed = check._ordered_cases()
    for cases in graded_draws.check_drawn_cases("dithering_ordered"):
        assert [c["gray"].shape for c in cases] == [c["gray"].shape for c in fixed]
        assert sorted(cases[0]["gray"].ravel() * 9) == pytest.approx(range(10))
        assert all(0 <= c["gray"].min() and c["gray"].max() <= 1 for c in cases)


def test_graded_diffusion_cases_are_drawn_in_the_fixed_cases_families():
    fixed = check._diffusion_cases()
    for cases in graded_draws.check_drawn_cases("dithering_error_diffuse"):
        assert [c["gray"].shape for c in cases] == [c["gray"].shape for c in fixed]
        steps = np.diff(cases[0]["gray"], axis=1)
        assert (steps > 0).all() or (steps < 0).all()
        assert (cases[1]["gray"] == 0.5).all() and len(np.unique(cases[3]["gray"])) == 1
        assert all(0 <= c["gray"].min() and c["gray"].max() <= 1 for c in cases)


def test_a_graded_face_is_the_lessons_face_moved_and_toned():
    face = check._small_face()
    for cases in graded_draws.check_drawn_cases("dithering_error_diffuse", range(5)):
        drawn = cases[-1]["gray"]
        assert drawn.shape == face.shape and not np.array_equal(drawn, face)
        assert abs(drawn.mean() - face.mean()) < 0.15


@pytest.mark.parametrize("name", ["dithering_ordered", "dithering_error_diffuse"])
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(name):
    graded_draws.check_graded(name)


# --- issue 34: answers written as the readers wrote them ------------------------------------


def test_a_cell_written_with_i_and_j_swapped_is_told_what_it_wrote():
    def swapped_in_the_cell(gray):
        height, width = gray.shape
        output = np.zeros((3 * height, 3 * width))
        for y in range(height):
            for x in range(width):
                for i in range(3):
                    for j in range(3):
                        lit = gray[y, x] > M[i][j] / 9
                        output[3 * y + j, 3 * x + i] = 1.0 if lit else 0.0
        return output

    result = check.dithering_ordered(swapped_in_the_cell)
    assert result.mistake == "the matrix transposed"
    message = str(result)
    assert "output[3 y + j, 3 x + i]" in message
    # The old message's suggestion swaps the image's x and y: it crashes a 2 x 5 case.
    assert "output[3 x + i, 3 y + j]" not in message


def png_size(picture):
    """(width, height) of PNG bytes, from the IHDR chunk."""
    return int.from_bytes(picture[16:20], "big"), int.from_bytes(picture[20:24], "big")


def test_the_pass_pictures_show_each_dot_at_a_whole_zoom_large_enough_to_see():
    face = check._small_face()
    diffused = check.dithering_error_diffuse(floyd_steinberg)
    ordered = check.dithering_ordered(nine_ifs)
    # Two faces side by side, each dot at least 3 x 3 screen pixels (the face is 75 x 64):
    # the dithered pattern, not a blur of it.
    width, height = png_size(diffused.picture)
    assert width >= 2 * 3 * face.shape[1] and height >= 3 * face.shape[0]
    # The ordered face is 225 x 192, three times larger: each dot at least one screen pixel.
    width, height = png_size(ordered.picture)
    assert width >= 2 * 3 * face.shape[1] and height >= 3 * face.shape[0]


# --- issue 34, the readers' own findings: inverted dots and centred thresholds ---------------


def ordered_as_written(gray, rule):
    """The lab's nine comparisons per pixel with the student's own rule for a lit sub-pixel."""
    height, width = gray.shape
    output = np.zeros((3 * height, 3 * width))
    for y in range(height):
        for x in range(width):
            for i in range(3):
                for j in range(3):
                    output[3 * y + i, 3 * x + j] = rule(gray[y, x], M[i][j])
    return output


@pytest.mark.parametrize(
    "rule",
    [
        lambda value, m: 1.0 if value < m / 9 else 0.0,  # the comparison reversed
        lambda value, m: 0.0 if value > m / 9 else 1.0,  # the 1 and the 0 swapped
    ],
    ids=["less", "branches swapped"],
)
def test_ordered_dots_lit_where_the_pixel_is_dark_are_named_inverted(rule):
    result = check.dithering_ordered(lambda gray: ordered_as_written(gray, rule))
    assert result.mistake == "the dots inverted"
    assert "your dots are the negative" in str(result)
    assert check.dithering_ordered(
        lambda gray: ordered_as_written(gray, lambda value, m: 1.0 if value > m / 9 else 0.0)
    )


def test_the_lessons_centred_thresholds_are_named_since_the_exercise_asks_for_m_over_9():
    # The lesson shows (M + 0.5) / 9 removes the bias; Exercise 1 asks for M / 9 exactly.
    result = check.dithering_ordered(
        lambda gray: ordered_as_written(gray, lambda value, m: float(value > (m + 0.5) / 9))
    )
    assert result.mistake == "centred thresholds"
    assert "compare with M[i][j] / 9" in str(result)


@pytest.mark.parametrize("reversed_rule", ["<", "<=", "1 - output"])
def test_error_diffusion_lit_where_the_pixel_is_dark_is_named_inverted(reversed_rule):
    def diffused(gray):
        height, width = gray.shape
        buffer, output = gray.copy(), np.zeros_like(gray)
        for y in range(height):
            for x in range(width):
                value = buffer[y, x]
                if reversed_rule == "<":
                    output[y, x] = 1.0 if value < 0.5 else 0.0
                elif reversed_rule == "<=":
                    output[y, x] = 0.0 if value > 0.5 else 1.0
                else:
                    output[y, x] = 1.0 if value > 0.5 else 0.0
                error = value - output[y, x]
                for dx, dy, weight in ((1, 0, 7), (-1, 1, 3), (0, 1, 5), (1, 1, 1)):
                    if 0 <= x + dx < width and y + dy < height:
                        buffer[y + dy, x + dx] += error * weight / 16
        return 1.0 - output if reversed_rule == "1 - output" else output

    result = check.dithering_error_diffuse(diffused)
    assert result.mistake == "the dots inverted"
    assert "Light it (1) where buffer[y, x] > 0.5" in str(result)
