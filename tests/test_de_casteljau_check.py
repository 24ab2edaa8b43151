"""Lesson 01's checkers: right answers pass in one line; each handout mistake is named."""

import io
import itertools
import json
from pathlib import Path

import graded_draws
import numpy as np
import pytest
from PIL import Image

from course.check import base
from course.curves.bezier import de_casteljau
from course.lessons.l01_de_casteljau import check, drawing_loop


def recursive_solution(points, t):
    if len(points) == 1:
        return points[0]
    return recursive_solution([(1 - t) * a + t * b for a, b in itertools.pairwise(points)], t)


# Wrong solutions, written the way students write them.
def reversed_step(points, t):
    if len(points) == 1:
        return points[0]
    return reversed_step([t * a + (1 - t) * b for a, b in itertools.pairwise(points)], t)


def one_level_short(points, t):
    if len(points) == 2:
        return points[0]
    return one_level_short([(1 - t) * a + t * b for a, b in itertools.pairwise(points)], t)


def swapped(points, t):
    x, y = recursive_solution(points, t)
    return y, x


def picture_size(result):
    return Image.open(io.BytesIO(result.picture)).size


def test_correct_solutions_pass_in_one_line_whatever_they_name_their_arguments():
    result = check.recursive_bezier(recursive_solution)
    assert result and str(result) == "PASS recursive_bezier: all 45 cases pass"
    assert check.recursive_bezier(lambda p, t: tuple(recursive_solution(p, t)))
    assert result.mistake is None and result.picture.startswith(b"\x89PNG")
    # the pass picture: the student's points on seed 000's curve, 3 inches square at 100 dpi
    assert picture_size(result) == (300, 300)


@pytest.mark.parametrize(
    ("solution", "mistake", "words"),
    [
        (reversed_step, "the reversed step", "your curve runs backwards"),
        (one_level_short, "one level short", "you stopped when two points were left"),
        (swapped, "x and y swapped", "your point is (y, x)"),
    ],
)
def test_each_known_mistake_of_recursive_bezier_is_named_with_its_picture(
    solution, mistake, words, monkeypatch
):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    result = check.recursive_bezier(solution)
    assert not result and result.mistake == mistake
    message = str(result)
    assert message.startswith("FAIL recursive_bezier: case 1 is wrong\n")
    assert f"This is a known mistake, {mistake}: {words}" in message
    assert "first wrong value: [0]" in message or "first wrong value: [1]" in message
    assert message.splitlines()[-2:] == [
        f"Hint: {check.RECURSIVE_HINTS.where}",
        '(More: check.hint("recursive_bezier").)',
    ]
    assert picture_size(result)[0] > 300


@pytest.mark.parametrize(
    ("solution", "words"),
    [
        (reversed_step, "t of the way along each edge, from its first end"),
        (one_level_short, "when the recursion stops"),
        (swapped, "the point you return"),
    ],
)
def test_the_first_hint_after_a_named_mistake_points_where_it_lives(solution, words, monkeypatch):
    # After "the reversed step" the hint spoke only of what one call hands to the next and of
    # when the recursion stops.
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    hint_line = str(check.recursive_bezier(solution)).splitlines()[-2]
    assert hint_line.startswith("Hint: ") and words in hint_line


def test_an_unknown_mistake_gets_the_first_wrong_value_the_picture_and_the_hint():
    result = check.recursive_bezier(lambda points, t: recursive_solution(points, t) + 0.5)
    assert not result and result.mistake is None
    message = str(result)
    assert "first wrong value: [0] expected 0.625, given 1.125" in message
    assert "known mistake" not in message and "Hint: " in message
    assert result.picture is not None


def test_exceptions_and_non_functions_are_reported():
    result = check.recursive_bezier(lambda points, t: points[5])
    assert not result and "case 1 raised IndexError" in str(result) and "Hint: " in str(result)
    with pytest.raises(TypeError, match="recursive_bezier: expected a function"):
        check.recursive_bezier(np.zeros(2))


def next_level_solution(points, t):
    return [(1 - t) * points[i] + t * points[i + 1] for i in range(len(points) - 1)]


@pytest.mark.parametrize(
    ("solution", "mistake"),
    [
        (
            lambda p, t: [t * p[i] + (1 - t) * p[i + 1] for i in range(len(p) - 1)],
            "the reversed step",
        ),
        (
            lambda p, t: [(1 - t) * p[i] + t * p[i + 1] for i in range(len(p) - 2)],
            "one point short",
        ),
        (
            lambda p, t: (1 - t) * p + t * np.roll(p, -1, axis=0),
            "an edge from the last point back to the first",
        ),
        (lambda p, t: np.array(next_level_solution(p, t))[:, ::-1], "x and y swapped"),
    ],
)
def test_next_level_passes_and_names_each_mistake(solution, mistake):
    assert str(check.next_level(next_level_solution)) == "PASS next_level: all 45 cases pass"
    result = check.next_level(solution)
    assert not result and result.mistake == mistake


LESSON_01 = Path(__file__).resolve().parent.parent / "notebooks" / "01_de_casteljau.ipynb"


def bezier_solution(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = recursive_solution(control_points, k / 1000)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 1, 0)


def float_loop(control_points, window):
    height, width = window.shape[:2]
    t = 0.0
    while t <= 1:
        x, y = recursive_solution(control_points, t)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 1, 0)
        t += 0.001


def stops_at_0_999(control_points, window):
    height, width = window.shape[:2]
    for k in range(1000):
        x, y = recursive_solution(control_points, k / 1000)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 1, 0)


def rounded(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = np.round(recursive_solution(control_points, k / 1000)).astype(int)
        if 0 <= x < width and 0 <= y < height:
            window[y, x] = (0, 1, 0)


def swapped_axes(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = recursive_solution(control_points, k / 1000)
        if 0 <= x < width and 0 <= y < height:
            window[int(x), int(y)] = (0, 1, 0)


def unguarded_below(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = recursive_solution(control_points, k / 1000)
        if x < width and y < height:
            window[int(np.floor(y)), int(np.floor(x))] = (0, 1, 0)


def coarse(control_points, window):
    height, width = window.shape[:2]
    for k in range(101):
        x, y = recursive_solution(control_points, k / 100)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 1, 0)


def test_the_drawing_loop_passes_in_one_line():
    result = check.bezier(bezier_solution)
    assert str(result) == "PASS bezier: all 8 cases pass"


@pytest.mark.parametrize(
    ("solution", "mistake", "case"),
    [
        (float_loop, "t accumulated in float steps", 1),
        (stops_at_0_999, "the loop stops before t = 1", 1),
        (rounded, "rounding to the nearest pixel", 1),
        (swapped_axes, "x and y swapped", 1),
        (unguarded_below, "a negative index wraps around", 2),
        (coarse, "a step of 0.01", 1),
    ],
)
def test_each_known_mistake_of_the_drawing_loop_is_named_with_a_pixel_picture(
    solution, mistake, case
):
    result = check.bezier(solution)
    assert not result and result.mistake == mistake
    assert str(result).startswith(f"FAIL bezier: case {case} is wrong")
    # 16 x 16 pixels at 18 x 18, 30-pixel margins for the coordinates, the legend and title
    assert picture_size(result) == (16 * 18 + 2 * 30 + 150, 16 * 18 + 2 * 30 + 35)


def test_the_float_loop_report_names_the_missing_end_pixel():
    message = str(check.bezier(float_loop))
    assert "1 pixel missing, first at (x, y) = (690, 690)" in message


def test_a_loop_that_writes_off_the_window_is_told_where(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())

    def unguarded(control_points, window):
        for k in range(1001):
            x, y = recursive_solution(control_points, k / 1000)
            window[int(y), int(x)] = (0, 1, 0)

    message = str(check.bezier(unguarded))
    assert message.startswith(
        "FAIL bezier: case 2 raised IndexError: index 80 is out of bounds for axis 1 with size 80"
    )
    line = unguarded.__code__.co_firstlineno + 3
    assert f"at line {line} of unguarded: window[int(y), int(x)] = (0, 1, 0)" in message
    assert "and at points off the window." in message


def test_int_before_the_window_test_is_named_with_the_point_it_painted():
    # The natural reading of "the pixel is (int(x), int(y))": test the pixel, not the point.
    def pixel_tested(control_points, window):
        height, width = window.shape[:2]
        for k in range(1001):
            x, y = recursive_solution(control_points, k / 1000)
            column, row = int(x), int(y)
            if 0 <= column < width and 0 <= row < height:
                window[row, column] = (0, 1, 0)

    result = check.bezier(pixel_tested)
    assert not result and result.mistake == "int() before the window test"
    assert "int(-0.5) is 0" in str(result)
    assert "1 extra" in str(result)


def test_a_negative_index_through_int_is_named_as_wrapping():
    # int() truncates toward zero: (-0.5) lands in column 0, (-1.5) wraps to the last column.
    def only_upper_bounds(control_points, window):
        height, width = window.shape[:2]
        for k in range(1001):
            x, y = recursive_solution(control_points, k / 1000)
            if x < width and y < height:
                window[int(y), int(x)] = (0, 1, 0)

    result = check.bezier(only_upper_bounds)
    assert not result and result.mistake == "a negative index wraps around"
    assert "Python counts a negative index from the end" in result.message


def test_a_painted_copy_is_told_to_paint_the_window_it_was_given():
    def painted_copy(control_points, window):
        window = window.copy()
        bezier_solution(control_points, window)
        return window

    result = check.bezier(painted_copy)
    assert not result and result.mistake == "a painted copy"
    assert "Paint into window itself" in result.message
    assert "given:    0 pixels painted" in result.message


def test_the_rounding_mistake_is_worded_as_the_lesson_words_the_pixel():
    lesson = " ".join(
        "".join(cell["source"])
        for cell in json.loads(LESSON_01.read_text(encoding="utf-8"))["cells"]
    )
    # Line breaks in the Markdown fall anywhere: compare the words.
    lesson = " ".join(lesson.lower().split())
    assert "the pixel whose square holds the point $(x, y)$ is `(int(x), int(y))`" in lesson
    assert "the pixel whose square holds the point (x, y) is (int(x), int(y))" in (
        check.bezier(rounded).message
    )


@pytest.mark.parametrize(
    ("points", "slip"),
    [
        ([[0.0, 10.0], [0.0, 100.0]], "0 < x"),
        ([[650.0, 100.5], [700.0, 100.5]], "x <= width"),
        ([[100.0, 0.0], [300.0, 0.0]], "0 < y"),
        ([[100.5, 600.0], [100.5, 700.0]], "y <= height"),
        ([[100.0, -0.5], [300.0, -0.5]], "-1 <= y"),
    ],
)
def test_each_edge_of_the_window_is_a_case_that_a_test_one_off_fails(points, slip):
    cases = [c for c in drawing_loop.bezier_cases() if np.array_equal(c["control_points"], points)]
    assert len(cases) == 1 and cases[0]["window"].shape == (700, 700, 3)
    tests = {
        "0 < x": lambda x, y, w, h: 0 < x < w and 0 <= y < h,
        "x <= width": lambda x, y, w, h: 0 <= x <= w and 0 <= y < h,
        "0 < y": lambda x, y, w, h: 0 <= x < w and 0 < y < h,
        "y <= height": lambda x, y, w, h: 0 <= x < w and 0 <= y <= h,
        "-1 <= y": lambda x, y, w, h: 0 <= x < w and -1 <= y < h,
    }

    def one_off(control_points, window):
        height, width = window.shape[:2]
        for k in range(1001):
            x, y = recursive_solution(control_points, k / 1000)
            if tests[slip](x, y, width, height):
                window[int(y), int(x)] = (0, 1, 0)

    window = np.zeros((700, 700, 3))
    expected = np.zeros((700, 700, 3))
    bezier_solution(np.array(points), expected)
    try:
        one_off(np.array(points), window)
    except IndexError:
        pass  # x == width or y == height indexes past the end: the check reports it
    else:
        assert not np.array_equal(window, expected)
    assert not check.bezier(one_off)


def test_a_point_in_a_list_of_one_fails_with_its_shape_named():
    result = check.recursive_bezier(lambda p, t: np.array([recursive_solution(p, t)]))
    assert not result
    assert "the answer is the point (x, y), of shape (2,); yours has shape (1, 2)" in (
        result.message
    )
    assert check.recursive_bezier(lambda p, t: tuple(recursive_solution(p, t)))


def test_a_level_closed_by_a_modulo_index_is_told_of_the_modulo_too():
    def modulo(p, t):
        p = np.asarray(p, dtype=float)
        return [(1 - t) * p[i] + t * p[(i + 1) % len(p)] for i in range(len(p))]

    result = check.next_level(modulo)
    assert result.mistake == "an edge from the last point back to the first"
    assert "an index taken modulo N (P[(i + 1) % N]) or np.roll" in result.message


def the_games101_reports_loop(control_points, window):
    """float t advanced by 0.001 and cv::Point's rounding, both."""
    height, width = window.shape[:2]
    t = np.float32(0)
    while t <= 1:
        x, y = recursive_solution(control_points, float(t))
        column, row = round(x), round(y)
        if 0 <= column < width and 0 <= row < height:
            window[row, column] = (0, 1, 0)
        t = np.float32(t + np.float32(0.001))


def next_level_by_difference(control_points, t):
    """The VS2022 report's form of the step: P[i] + t (P[i+1] - P[i])."""
    return control_points[:-1] + t * (control_points[1:] - control_points[:-1])


def next_level_textbook(control_points, t):
    return (1 - t) * control_points[:-1] + t * control_points[1:]


#: The ways students write the loop's t: each is k / 1000 to within a unit in the last place.
LOOP_TS = {
    "k / 1000": lambda: [k / 1000 for k in range(1001)],
    "k * 0.001": lambda: [k * 0.001 for k in range(1001)],
    "linspace": lambda: np.linspace(0, 1, 1001),
    "arange to 1.0005": lambda: np.arange(0, 1.0005, 0.001),
}


def drawing_loop_with(next_level, ts):
    """A student's notebook: their next_level, recursive_bezier on it, and bezier over ts."""

    def recursive_bezier(control_points, t):
        if len(control_points) == 1:
            return control_points[0]
        return recursive_bezier(next_level(control_points, t), t)

    def bezier(control_points, window):
        height, width = window.shape[:2]
        for t in ts():
            x, y = recursive_bezier(control_points, t)
            if 0 <= x < width and 0 <= y < height:
                window[int(y), int(x)] = (0, 1, 0)

    return bezier


@pytest.mark.parametrize("ts", LOOP_TS)
@pytest.mark.parametrize("next_level", [next_level_textbook, next_level_by_difference])
def test_a_right_loop_passes_however_it_writes_the_step_and_t(next_level, ts):
    # (1 - t) 100 + t 100 is 99.99999999999999 for some t: a line on y = 100 or y = 700 made
    # the expected pixels hang on the last bit, and these right answers failed (case 5 named
    # "the float32 loop of the GAMES101 report"; case 7 "1 pixel missing, 2 extra").
    student = drawing_loop_with(next_level, LOOP_TS[ts])
    assert str(check.bezier(student)) == "PASS bezier: all 8 cases pass"


@pytest.mark.parametrize(("next_level", "ts"), [(next_level_by_difference, "k * 0.001")])
def test_a_right_loop_passes_the_graded_cases_however_it_writes_the_step_and_t(next_level, ts):
    student = drawing_loop_with(next_level, LOOP_TS[ts])
    for seed in graded_draws.SEEDS:
        result = graded_draws.graded("bezier", student, seed)
        assert result.passed, f"seed {seed}:\n{result}"


def test_no_case_leaves_a_pixel_to_the_last_bit_of_a_float():
    # The drawn families are redrawn until they put no point within rounding of a pixel edge
    # where its side matters; the fixed cases are chosen so.
    fixed = drawing_loop.bezier_cases()
    drawn = [
        case
        for seed in graded_draws.SEEDS
        for case in graded_draws.draw(graded_draws.declared("bezier"), seed)
    ]
    for case in fixed + drawn:
        points, shape = case["control_points"], case["window"].shape
        assert drawing_loop.rounding_sensitive_pixels(points, shape).size == 0, points.tolist()


@pytest.mark.parametrize(
    ("points", "row"),
    [([[650.0, 100.0], [700.0, 100.0]], 99), ([[100.0, 700.0], [300.0, 700.0]], 699)],
)
def test_a_line_on_a_pixel_edge_is_found_to_hang_on_rounding(points, row):
    found = drawing_loop.rounding_sensitive_pixels(np.array(points), (700, 700))
    assert len(found) and (found[:, 1] == row).any()
    # The pixels that differ between (1 - t) P0 + t P1 and P0 + t (P1 - P0) are among them.
    window_a, window_b = np.zeros((700, 700, 3)), np.zeros((700, 700, 3))
    drawing_loop_with(next_level_textbook, LOOP_TS["k / 1000"])(np.array(points), window_a)
    drawing_loop_with(next_level_by_difference, LOOP_TS["k / 1000"])(np.array(points), window_b)
    rows, columns = np.nonzero((window_a != window_b).any(axis=2))
    assert len(rows) and set(zip(columns.tolist(), rows.tolist(), strict=True)) <= set(
        map(tuple, found.tolist())
    )


def green_channel_only(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = recursive_solution(control_points, k / 1000)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x), 1] = 1


def test_green_is_the_whole_pixel_or_the_green_channel_alone_as_the_reports_paint():
    # Every report sets one channel (window.at<cv::Vec3b>(y, x)[1] = 255), and the homework's
    # red and green check relies on it: on the grey window the pixel keeps its red and blue.
    assert check.bezier(green_channel_only)


def test_a_loop_that_paints_a_pixel_half_green_on_the_grey_window_is_the_wrong_colour():
    def red_cleared(control_points, window):
        green_channel_only(control_points, window)
        window[..., 0][window[..., 1] == 1] = 0  # red cleared, blue kept: neither way

    result = check.bezier(red_cleared)
    assert not result and result.mistake == "the wrong colour"
    assert str(result).startswith("FAIL bezier: case 3 is wrong")


def test_the_games101_reports_own_loop_is_named_as_the_pair():
    result = check.bezier(the_games101_reports_loop)
    assert result.mistake == "the GAMES101 report's loop: float32 t and cv::Point rounding"
    assert "case 1 is wrong" in result.message


@pytest.mark.parametrize("colour", [(0, 255, 0), (1, 0, 0)])
def test_a_wrong_colour_is_named_as_the_colour_never_as_wrapping(colour):
    def painted_in(control_points, window):
        height, width = window.shape[:2]
        for k in range(1001):
            x, y = recursive_solution(control_points, k / 1000)
            if 0 <= x < width and 0 <= y < height:
                window[int(y), int(x)] = colour

    result = check.bezier(painted_in)
    assert not result and result.mistake == "the wrong colour"
    assert "the right pixels, but pixel (10, 10)" in result.message
    assert "wraps around" not in result.message


# --- graded: cases drawn for each submission ------------------------------------------------


def painted_in_8_bit_green(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = recursive_solution(control_points, k / 1000)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 255, 0)


def painted_into_a_copy(control_points, window):
    window = window.copy()
    bezier_solution(control_points, window)
    return window


#: The drawing loop's mistakes a function answering with their pixels cannot make: green
#: added, a colour, a copy, and t accumulated (recognised by what the loop paints on a probe
#: curve too).
WRITTEN_BEZIER = {
    0: lambda: green_added,
    1: lambda: painted_in_8_bit_green,
    2: lambda: painted_into_a_copy,
    3: lambda: float_loop,
}


@pytest.mark.parametrize("name", ["recursive_bezier", "next_level"])
def test_graded_curve_cases_are_drawn_in_the_fixed_cases_families(name):
    fixed = check.curve_cases(max_points=10)
    for cases in graded_draws.check_drawn_cases(name):
        assert [len(c["control_points"]) for c in cases] == [
            len(c["control_points"]) for c in fixed
        ]
        assert [c["t"] for c in cases][1::5] == [0.5] * 9
        assert [c["t"] for c in cases][2::5] == [0.0] * 9
        assert [c["t"] for c in cases][3::5] == [1.0] * 9
        assert all(0.1 <= c["t"] < 0.4 for c in cases[::5])
        assert all(0.6 <= c["t"] < 0.95 for c in cases[4::5])
        points = np.vstack([c["control_points"] for c in cases[10:]])
        assert 0 <= points.min() and points.max() <= 700


def test_graded_bezier_cases_are_drawn_in_the_fixed_cases_families():
    for cases in graded_draws.check_drawn_cases("bezier"):
        shapes = [c["window"].shape for c in cases]
        assert shapes[0] == (700, 700, 3) and shapes[2] == (24, 24, 3)
        assert 50 <= shapes[1][0] <= 70 and 70 <= shapes[1][1] <= 90
        assert shapes[3:] == [(700, 700, 3)] * 5
        assert not any(c["window"].any() for number, c in enumerate(cases) if number != 2)
        assert (cases[2]["window"] == drawing_loop.GREY).all()
        curve = de_casteljau(cases[1]["control_points"], np.linspace(0, 1, 1001))
        assert curve[:, 0].min() < -1 and curve[:, 0].max() > shapes[1][1]
        x_0, x_width, y_0, y_height, y_half = (c["control_points"] for c in cases[3:])
        assert (x_0[:, 0] == 0).all() and x_width[:, 0].max() == 700
        assert x_width[0, 1] == x_width[1, 1] and y_height[0, 0] == y_height[1, 0]
        assert (y_0[:, 1] == 0).all() and y_height[:, 1].max() == 700
        assert (y_half[:, 1] == -0.5).all()


@pytest.mark.parametrize(
    ("name", "written"),
    [("recursive_bezier", {}), ("next_level", {}), ("bezier", WRITTEN_BEZIER)],
)
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(name, written):
    graded_draws.check_graded(name, written)


# --- the readers' students (issue 34): each mistake as a student writes it, named ----------


def float32_loop_in_numpy(control_points, window):
    """The handouts' `for (float t = 0; t <= 1; t += 0.001f)`, written with np.float32: t
    reaches the student's step as float32, so 1 - t is rounded to float32 too."""
    height, width = window.shape[:2]
    t = np.float32(0)
    while t <= 1:
        x, y = recursive_solution(control_points, t)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 1, 0)
        t += np.float32(0.001)


def float32_loop_all_in_float32(control_points, window):
    """The same with the points as Python floats: np.float32 times a float stays float32."""
    height, width = window.shape[:2]
    points = [tuple(map(float, point)) for point in control_points]

    def point_at(points, t):
        if len(points) == 1:
            return points[0]
        return point_at(
            [
                ((1 - t) * a + t * c, (1 - t) * b + t * d)
                for (a, b), (c, d) in itertools.pairwise(points)
            ],
            t,
        )

    t = np.float32(0)
    while t <= 1:
        x, y = point_at(points, t)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 1, 0)
        t += np.float32(0.001)


@pytest.mark.parametrize("student", [float32_loop_in_numpy, float32_loop_all_in_float32])
def test_the_float32_loop_written_with_np_float32_is_named(student):
    # Before: "7 pixels missing, ... 6 extra" and the generic hint: its 1 - t (or the whole
    # point) in float32 moved a point a few millionths of a pixel across an edge.
    result = check.bezier(student)
    assert not result and result.mistake == "the float32 loop of the GAMES101 report"
    assert "np.float32 in Python" in result.message
    assert check.bezier(bezier_solution)


def rounded_by_hand(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = recursive_solution(control_points, k / 1000)
        column, row = int(x + 0.5), int(y + 0.5)
        if 0 <= column < width and 0 <= row < height:
            window[row, column] = (0, 1, 0)


def test_rounding_by_hand_with_int_x_plus_half_is_named_as_rounding():
    # int(x + 0.5) is not the pixel that holds the point, and it takes 392.5 to 393 where
    # round() takes it to 392: the rounding mistake missed it.
    result = check.bezier(rounded_by_hand)
    assert not result and result.mistake == "rounding half up, int(x + 0.5)"
    assert "int(x + 0.5) rounds half up" in result.message
    assert "(int(x), int(y))" in result.message
    assert check.bezier(rounded).mistake == "rounding to the nearest pixel"


def green_added(control_points, window):
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = recursive_solution(control_points, k / 1000)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x), 1] += 1


def test_adding_to_the_green_channel_is_named_not_the_8_bit_colour():
    result = check.bezier(green_added)
    assert not result and result.mistake == "green added, not set"
    assert "instead of setting it" in result.message
    assert "8-bit" not in result.message
    assert check.bezier(green_channel_only)


def test_a_next_level_failure_draws_the_expected_level_beside_the_students():
    def unknown(points, t):
        return np.asarray(next_level_solution(points, t)) + 1.0

    result = check.next_level(unknown)
    assert not result and result.mistake is None
    assert result.picture is not None and result.picture.startswith(b"\x89PNG")
    assert check.next_level(lambda points, t: np.array(points)[1:]).picture is not None
