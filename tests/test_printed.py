"""course.lessons.printed, and the lines the lessons print with it (course.lessons.lNN).

In English exactly as the notebooks printed them before the printing moved into
``course.lessons``, and in Chinese under ``use_language("zh-CN")`` (English again after).
Each case is a function of a lesson module, its arguments as the lesson passes them, and
the line the notebook printed (from its committed output); where the line states a number
that is cheap to recompute, the argument is computed here from its definition instead of
copied. Nothing here draws a figure except the opening picture and a 12 x 12 blur app;
the whole file takes about 5 s.
"""

from __future__ import annotations

import math
import re
import sys

import numpy as np
import pytest

from course import filters
from course.curves.bezier import de_casteljau_recursive
from course.i18n import current_language, language
from course.lessons.l01_de_casteljau import lesson as l01
from course.lessons.l02_bernstein import lesson as l02
from course.lessons.l03_lines_and_triangles import lesson as l03
from course.lessons.l04_supersampling import lesson as l04
from course.lessons.l05_antialiasing import lesson as l05
from course.lessons.l06_dithering import lesson as l06
from course.lessons.l07_filtering import lesson as l07
from course.lessons.l07_filtering.apps import RepeatedBlurApp
from course.lessons.l08_poisson import lesson as l08
from course.lessons.printed import degree_column, degree_numeral, display_width
from course.raster import wu_line

CHINESE = re.compile("[\u4e00-\u9fff]")


def shoelace_area(p0, p1, p2) -> float:
    (x0, y0), (x1, y1), (x2, y2) = p0, p1, p2
    return abs((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)) / 2


def wu_image() -> np.ndarray:
    """Lesson 03's Wu line from (0.5, 0.5) to (7.5, 3.5), its weights added into pixels."""
    pixels, weights = wu_line((0.5, 0.5), (7.5, 3.5))
    image = np.zeros((4, 8))
    np.add.at(image, (pixels[:, 1], pixels[:, 0]), weights)
    return image


def sobel_x_row(sign: int) -> np.ndarray:
    """Lesson 07's step row filtered by Sobel's x kernel: -1 0 1 across, weights 1 2 1 down,
    summed here by hand (sign 1: correlation, the lab's; -1: convolution, the kernel flipped)."""
    step = np.array([0.0, 0, 0, 1, 1, 1])
    padded = np.concatenate([step[:1], step, step[-1:]])  # 'replicate'
    right, left = (padded[2:], padded[:-2]) if sign > 0 else (padded[:-2], padded[2:])
    return (1 + 2 + 1) * (right - left)


def recursion_error() -> RecursionError:
    """Lesson 01's RecursionError: a degree-1999 curve asks for 2000 nested calls."""
    try:
        de_casteljau_recursive(np.zeros((2000, 2)), 0.5)
    except RecursionError as error:
        return error
    raise AssertionError("de_casteljau_recursive accepted 2000 nested calls")


def float_overflow(m: int) -> OverflowError:
    """The error Python raises converting C(m, m // 2) to a float."""
    try:
        float(math.comb(m, m // 2))
    except OverflowError as error:
        return error
    raise AssertionError(f"C({m}, {m // 2}) fits a float")


CASES = [
    pytest.param(
        l01.print_yellow_check,
        ("the GAMES101 report", 0.396, "green only"),
        "    the GAMES101 report: 39.6% yellow, B(1)'s pixel green only",
        id="01-yellow",
    ),
    pytest.param(
        l01.print_yellow_check,
        ("textbook step, float t", 0.99, "dark"),
        " textbook step, float t: 99.0% yellow, B(1)'s pixel dark",
        id="01-yellow-textbook",
    ),
    pytest.param(
        l01.print_iterative_against,
        (True, True),
        "iterative == recursive: yes\niterative == last level: yes",
        id="01-iterative",
    ),
    pytest.param(
        l01.print_recursion_error,
        (recursion_error(),),
        "de_casteljau_recursive: a degree-1999 curve needs 2000 nested calls.\n"
        f"Python's recursion limit is {sys.getrecursionlimit()}. Use de_casteljau (iterative).",
        id="01-recursion",
    ),
    pytest.param(
        l01.print_step_table,
        # A step of 1/100 samples t = 0, 0.01, ..., 1: 101 points, 100 gaps between them.
        ([(0.01, round(1 / 0.01) + 1, 101, 100, 1.0), (0.0001, 10000, 1324, 0, 7.55)],),
        "    step  points  pixels  gaps  overdraw\n"
        "    0.01     101     101   100      1.00\n"
        "  0.0001   10000    1324     0      7.55",
        id="01-steps",
    ),
    pytest.param(
        l02.print_basis_properties,
        (3, 2e-16, 0.0, True),
        "degree  3: |sum - 1| below 1e-12, |mirror| below 1e-12, ends exact: yes",
        id="02-basis",
    ),
    pytest.param(
        l02.print_comb_calls,
        (11, 419, math.comb(11, 5)),
        "comb(11, 5): 419 calls for C(11, 5) = 462",
        id="02-comb-calls",
    ),
    pytest.param(
        l02.print_comb_calls_against_binomial,
        (20, 184755, math.comb(20, 10)),
        "comb(20, 10): 184,755 calls, C(20, 10) - 1 = 184,755",
        id="02-comb-binomial",
    ),
    pytest.param(
        l02.print_calls_growth,
        (20, 24, 14.6),
        "from m = 20 to 24: x14.6 (2^4 = 16)",
        id="02-growth",
    ),
    pytest.param(
        l02.print_calls_per_curve,
        (20, 1001, 1049605557),
        "naive_bezier at degree 20, 1001 points: 1,049,605,557 calls of comb",
        id="02-per-curve",
    ),
    pytest.param(
        l02.print_int32_binomial,
        # 32 bits keep C(34, 17) modulo 2^32, read as signed: 2,333,606,220 - 2^32
        (34, math.comb(34, 17) - 2**32, math.comb(34, 17)),
        "C(34, 17) in 32 bits: -1,961,361,076   exact:  2,333,606,220",
        id="02-int32",
    ),
    pytest.param(
        l02.print_horner_gap,
        (20, 3e-14),
        "degree 20: Horner against the handout's sum: below 1e-10 px",
        id="02-horner",
    ),
    pytest.param(
        l02.print_comb_timing,
        # 0.645 ms over 3431 calls: 188 ns a call
        (14, 3431, 0.000645),
        "m = 14:    3,431 calls,     0.6 ms,   188 ns a call",
        id="02-timing",
    ),
    pytest.param(
        l02.print_binomial_as_float,
        (1029, float(math.comb(1029, 514))),
        "C(1029, 514) as a float: 1.430e+308",
        id="02-float",
    ),
    pytest.param(
        l02.print_binomial_as_float,
        (1030, float_overflow(1030)),
        "C(1030, 515) as a float: int too large to convert to float",
        id="02-overflow",
    ),
    pytest.param(
        l02.print_de_casteljau_error,
        (400, 4e-15),
        "degree 400: de Casteljau's worst error below 1e-12 of the polygon's size",
        id="02-de-casteljau",
    ),
    pytest.param(
        l02.print_middle_peak,
        (10, math.comb(10, 5) / 2**10),
        "degree 10: the middle bump's peak B(n/2, n)(1/2) = 0.246",
        id="02-peak",
    ),
    pytest.param(
        l04.print_largest_difference,
        (4e-16,),
        "largest difference: below 1e-12",
        id="04-difference",
    ),
    pytest.param(
        l04.print_supersampled_row,
        # At rate 3 the samples are the stripes' pixels: each output pixel their box average.
        (3, np.array([[np.mean([0.0, 1.0, 0.0]), np.mean([1.0, 0.0, 1.0])]])),
        "rate  3: [[0.3333, 0.6667]]",
        id="04-stripes",
    ),
    pytest.param(
        l04.print_errors_by_rate,
        ("half as fine", [0.2233, 0.0208, 0.007]),
        "half as fine: 0.2233 0.0208 0.0070",
        id="04-errors",
    ),
    pytest.param(
        l04.print_measured_shift,
        (1, -0.436, (320 / 2500 - 1 / 1) / 2),
        "rate  1: measured -0.4360, (1/s - 1/rate)/2 = -0.4360",
        id="04-shift",
    ),
    pytest.param(
        l04.print_centred_against_report,
        (4, 0.0043, 0.0275),
        "rate 4: RMS centred 0.0043, the report's 0.0275",
        id="04-centred",
    ),
    pytest.param(
        l04.print_rate_against_rate,
        (1, 32, 0.2985),
        "zone plate, rate 1 against rate 32: RMS 0.2985",
        id="04-rates",
    ),
    pytest.param(
        l03.print_lines_agree,
        (16**4, 16**4),
        "65536 lines: the forms agree on 65536",
        id="03-lines",
    ),
    pytest.param(
        l03.print_triangles_agree,
        (3000, 3000),
        "the two forms agree on 3000 of 3000 triangles",
        id="03-triangles",
    ),
    pytest.param(
        l03.print_ink_per_column,
        (wu_image(),),
        "ink per column: [0.5 1.  1.  1.  1.  1.  1.  0.5]",
        id="03-ink",
    ),
    pytest.param(
        l03.print_exact_area,
        (shoelace_area((1.3, 0.7), (14.2, 5.9), (4.1, 11.6)), 47),
        "exact area 63.025; 47 edge pixels",
        id="03-area",
    ),
    pytest.param(
        l03.print_coverage_error,
        (1, 0.2452, 0.494, 61.0),
        "rate  1: RMS 0.2452, worst 0.494, total 61.0000",
        id="03-rate",
    ),
    pytest.param(
        l03.print_line_pixels,
        ("report's loop", 10 + 10 + 1, np.hypot(0.5, 0.5)),
        "report's loop: 21 pixels, farthest centre 0.71 px from the line",
        id="03-report-loop",
    ),
    pytest.param(l03.print_line_pixels, ("Wu", 11), "Wu: 11 pixels", id="03-wu"),
    pytest.param(
        l03.print_line_ends, (np.array([3, 6]), (27, 17)), "from (3, 6) to (27, 17):", id="03-ends"
    ),
    pytest.param(
        l03.print_segments_report,
        (1, {"missed": 58, "off": 29, "twice": 0}),
        " 1 segments: missed 58, off 29, twice 0",
        id="03-segments",
    ),
    pytest.param(
        l06.print_method_table,
        ([("threshold", -0.0152, 0.2204), ("Floyd-Steinberg serpentine", -0.0008, 0.0172)],),
        "method                       mean difference  blurred error\n"
        "threshold                            -0.0152         0.2204\n"
        "Floyd-Steinberg serpentine           -0.0008         0.0172",
        id="06-table",
    ),
    pytest.param(
        l06.print_ordered_error, (0.0549, 0.11), "mean error +0.0549, worst 0.1100", id="06-ordered"
    ),
    pytest.param(l06.print_pixel_count, (300 * 256,), "76,800 pixels", id="06-pixels"),
    pytest.param(
        l06.print_equal_to_loop,
        ("rows", True),
        'method="rows" (a loop along each row, its pushes to the rows below added a whole row '
        "at once): equal to the loop bit for bit: yes",
        id="06-equal",
    ),
    pytest.param(
        l06.print_wavefront_against_pillow,
        (0.0791, 0.00051),
        "wavefront 79.1 ms, Pillow 0.51 ms: 155x",
        id="06-timing",
    ),
    pytest.param(
        l07.print_loop_equals_fast, ("blur", True), "blur: loop == fast: yes", id="07-loop"
    ),
    pytest.param(
        l07.print_uniform_filter,
        ("constant", "zero", True),
        "uniform_filter constant against 'zero': equal below 1e-12: yes",
        id="07-uniform-filter",
    ),
    pytest.param(
        l07.print_report_rule_against_scipy,
        (True, 0.088),
        "the report's rule against scipy's default: inside below 1e-12: yes, "
        "on the frame up to 0.088",
        id="07-report-rule",
    ),
    pytest.param(
        l07.print_sobel_against_scipy,
        (True,),
        "sobel against hypot(ndimage.sobel): equal below 1e-12 everywhere: yes",
        id="07-sobel",
    ),
    pytest.param(
        l07.print_correlation_and_convolution,
        (sobel_x_row(1), sobel_x_row(-1)),
        "correlation (the lab): [0. 0. 4. 4. 0. 0.]\n"
        "convolution:           [ 0.  0. -4. -4.  0.  0.]",
        id="07-correlation",
    ),
    pytest.param(
        l07.print_largest_magnitude,
        (np.hypot(4, 2),),  # the window [[0 0 0] [0 0 1] [1 1 1]]: gx 3 + 1 = 4, gy 2
        "largest 4.4721 (sqrt(20) = 4.4721), on this window:",
        id="07-largest",
    ),
    pytest.param(
        l07.print_frame_depth,
        (5, 3),
        " 5 blurs: zero padding's frame is 3 px deep on the right",
        id="07-frame-depth",
    ),
    pytest.param(
        l08.print_residual_below,
        ("capacitance", True),
        " capacitance: residual below 1e-10: yes",
        id="08-residual",
    ),
    pytest.param(
        l08.print_lab_clone_time,
        (56.5e-6, 30302, 8000),
        # 56.5e-6 s x 30302 pixels = 1.712 s a sweep; x 8000 sweeps / 60 = 228.3 min
        "56.5 us per pixel per sweep: 1.712 s per sweep of the plane, 228 min for 8000",
        id="08-time",
    ),
    pytest.param(
        l08.print_plane_colour,
        (np.array([0.7249, 0.705, 0.78]),),
        "the plane itself: RGB [0.72 0.7  0.78]",
        id="08-plane",
    ),
    pytest.param(
        l08.print_cloned_colour,
        (420, 320, np.array([0.23, 0.281, 0.309])),
        "cloned at (420, 320): RGB [0.23 0.28 0.31]",
        id="08-cloned",
    ),
    pytest.param(
        l05.print_reference_against_finest,
        (16, 0.00045, 0.03125),
        "reference k=16 against k=64: RMSE 0.00045, max 0.0312",
        id="05-reference",
    ),
    pytest.param(
        l05.print_total_ink,
        (1140.0 + np.pi / 4, 1140.0),
        "total ink: exact 1140.79 ≈ length 1140.00 + the round caps' 0.785",
        id="05-ink",
    ),
    pytest.param(
        l05.print_agg_error,
        ("Agg, fine polyline", 0.0003, 0.032, 0.005),
        "Agg, fine polyline   RMSE 0.0003, max 0.032, position 0.005 px",
        id="05-agg",
    ),
    pytest.param(
        l05.print_loop_position_error,
        ("nearest_truncate", 0.267),
        "plain loop, truncated: position error 0.267 px",
        id="05-position",
    ),
    pytest.param(
        l05.print_arc_length_step,
        (0.000173, 0.35),
        "by length: step 0.000173, samples at most 0.35 px apart",
        id="05-step",
    ),
    pytest.param(
        l05.print_closed_form_difference,
        (64, 0.0002),
        "k = 64: largest difference from the closed form 0.0002",
        id="05-closed-form",
    ),
    pytest.param(
        l08.print_sor_omega,
        # Young's optimum for a square of side 100: 2 / (1 + sin(pi / 101)) = 1.94
        (2 / (1 + np.sin(np.pi / 101)),),
        "SOR's omega on this region: 1.94",
        id="08-omega",
    ),
]


@pytest.mark.parametrize(("function", "arguments", "english"), CASES)
def test_a_lesson_line_is_the_notebooks_in_english_and_chinese_in_chinese(
    function, arguments, english, capsys
):
    function(*arguments)
    assert capsys.readouterr().out == english + "\n"
    with language("zh-CN"):
        function(*arguments)
    chinese = capsys.readouterr().out
    assert current_language() == "en"
    assert CHINESE.search(chinese), chinese
    # The numbers stay, perhaps in another order; only the words change. A degree is written
    # in words in Chinese (三次曲线): it is read back as its number.
    number = r"\d+(?:\.\d+)?"
    chinese = re.sub(r"([一二三四五六七八九十百]+)次曲线", _degree_number, chinese)
    assert sorted(re.findall(number, chinese)) == sorted(re.findall(number, english))


@pytest.mark.parametrize(
    ("function", "arguments", "english"),
    [case for case in CASES if any(isinstance(value, bool) for value in case.values[1])],
)
def test_a_printed_truth_value_is_yes_or_no_in_the_lessons_language(
    function, arguments, english, capsys
):
    assert not re.search(r"\b(True|False)\b", english) and re.search(r"\b(yes|no)\b", english)
    with language("zh-CN"):
        function(*arguments)
    chinese = capsys.readouterr().out
    assert not re.search(r"True|False|\byes\b|\bno\b", chinese), chinese
    assert re.search("[是否]", chinese), chinese


def _degree_number(found: re.Match) -> str:
    with language("zh-CN"):
        numbers = {degree_numeral(n): n for n in range(1000)}
    return f"{numbers[found.group(1)]} 次曲线"


def test_lesson_02s_degree_lines_line_up_by_display_width_in_chinese(capsys):
    # The ninth reader: « 三次曲线» did not line up with «二十次曲线» (padded by characters).
    with language("zh-CN"):
        for n in (3, 9, 20):
            l02.print_horner_gap(n, 1e-13)
    heads = [line.split("次曲线")[0] for line in capsys.readouterr().out.splitlines()]
    assert heads == ["  三", "  九", "二十"]
    assert {display_width(head) for head in heads} == {4}
    # English stays exactly as {degree:>2} pads a number.
    assert all(f"{n:>2}" == f"{degree_column(n):>2}" for n in range(300))


def test_a_degree_is_written_in_words_in_chinese_not_as_a_count(capsys):
    # Issue 36: «3 次，t = 0.50» reads as "3 times"; a textbook writes 三次曲线.
    with language("zh-CN"):
        words = [degree_numeral(n) for n in (1, 3, 9, 10, 11, 20, 26, 99, 200, 1029)]
        l02.print_basis_properties(3, 2e-16, 0.0, True)
        l01.print_recursion_error(recursion_error())
    assert words == ["一", "三", "九", "十", "十一", "二十", "二十六", "九十九", "二百", "1029 "]
    assert [degree_numeral(n) for n in (3, 1029)] == [3, 1029]
    lines = capsys.readouterr().out.splitlines()
    assert (
        lines[0].startswith("  三次曲线：") and "：一条 1999 次曲线需要 2000 层嵌套调用" in lines[1]
    ), lines


def test_the_step_table_heading_lines_up_in_chinese(capsys):
    rows = [(0.0005, 2000, 1198, 1, 1.67)]
    l01.print_step_table(rows)
    english = capsys.readouterr().out.splitlines()
    with language("zh-CN"):
        l01.print_step_table(rows)
    chinese = capsys.readouterr().out.splitlines()
    assert chinese[1:] == english[1:] and CHINESE.search(chinese[0]), chinese

    def column_ends(line):
        return [display_width(line[: found.end()]) for found in re.finditer(r"\S+", line)]

    # Each heading ends where its column of right-aligned numbers ends.
    assert column_ends(chinese[0]) == column_ends(english[0]) == column_ends(english[1])


def test_the_yellow_check_names_line_up_in_chinese(capsys):
    with language("zh-CN"):
        for name in l01.LOOP_NAMES:
            l01.print_yellow_check(name, 0.5, "dark")
    lines = capsys.readouterr().out.splitlines()
    colons = {display_width(line.split("：")[0]) for line in lines}
    assert colons == {23} and all(CHINESE.search(line) for line in lines), lines


def test_the_zone_plate_names_line_up_in_chinese(capsys):
    with language("zh-CN"):
        for name in l04.ZONE_PLATE_NAMES:
            l04.print_errors_by_rate(name, [0.1, 0.2])
    lines = capsys.readouterr().out.splitlines()
    colons = {display_width(line.split("：")[0]) for line in lines}
    assert colons == {12} and all(CHINESE.search(line) for line in lines), lines


def test_a_two_line_title_is_one_line_in_either_language():
    title = "rule open: 42 + 48 pixels\n0 painted twice, 9 missed on the shared edge"
    assert l03.title_on_one_line(title) == (
        "rule open: 42 + 48 pixels: 0 painted twice, 9 missed on the shared edge"
    )
    with language("zh-CN"):
        assert l03.title_on_one_line("规则 open：42 + 48 个像素\n0 个画了两次") == (
            "规则 open：42 + 48 个像素；0 个画了两次"
        )
    assert l03.title_on_one_line("one line") == "one line"


def test_the_opening_picture_is_captioned_in_the_language():
    assert l03.opening_still().caption == (
        "two triangles sharing an edge, and their 4 x 4 supersampled coverage"
    )
    with language("zh-CN"):
        caption = l03.opening_still().caption
    assert CHINESE.search(caption), caption


def test_the_method_table_lines_up_in_chinese(capsys):
    with language("zh-CN"):
        l06.print_method_table([("threshold", -0.0152, 0.2204), ("Atkinson", -0.0325, 0.0592)])
    lines = capsys.readouterr().out.splitlines()
    assert CHINESE.search(lines[0]) and CHINESE.search(lines[1]), lines
    assert len({display_width(line) for line in lines}) == 1, lines


def test_the_agg_lines_line_up_in_chinese(capsys):
    with language("zh-CN"):
        for name in l05.AGG_RENDERINGS:
            l05.print_agg_error(name, 0.0037, 0.131, 0.05)
    lines = capsys.readouterr().out.splitlines()
    columns = [display_width(line.split(" 0.")[0]) for line in lines]
    assert CHINESE.search(lines[0]) and columns[0] == columns[1], lines


def test_the_correlated_row_is_the_filters(capsys):
    step = np.zeros((3, 6))
    step[:, 3:] = 1
    sobel_x = filters.SOBEL_X
    assert np.array_equal(
        filters.convolve(step, sobel_x[::-1, ::-1], "replicate")[1], sobel_x_row(1)
    )
    assert np.array_equal(filters.convolve(step, sobel_x, "replicate")[1], sobel_x_row(-1))


def test_the_two_rows_line_up_in_chinese_too(capsys):
    with language("zh-CN"):
        l07.print_correlation_and_convolution(sobel_x_row(1), sobel_x_row(-1))
    first, second = capsys.readouterr().out.splitlines()
    # A Chinese character takes two columns: the rows start at the same column.
    width = [display_width(line.split("[")[0]) for line in (first, second)]
    assert width[0] == width[1] and CHINESE.search(second), (first, second)


def test_the_border_titles_print_one_line_each(capsys):
    app = RepeatedBlurApp(np.full((12, 12), 0.5), repeats=1, corner=4)
    l07.print_border_titles(app)
    english = capsys.readouterr().out.splitlines()
    assert english == [
        app.titles[border].get_text().replace("\n", ": ") for border in filters.BORDERS
    ]
    with language("zh-CN"):
        app = RepeatedBlurApp(np.full((12, 12), 0.5), repeats=1, corner=4)
        l07.print_border_titles(app)
    chinese = capsys.readouterr().out.splitlines()
    assert len(chinese) == len(filters.BORDERS)
    assert all(CHINESE.search(line) and "\n" not in line for line in chinese), chinese
