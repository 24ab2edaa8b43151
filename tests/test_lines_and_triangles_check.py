"""Lesson 03's checkers: right lines and fills pass, typical mistakes are named."""

import math

import graded_draws
import numpy as np
import pytest

import course
from course.check import base
from course.lessons.l03_lines_and_triangles import check, mistakes
from course.raster import line, line_4connected, triangle


def bresenham_ties_toward_the_end(p0, p1):
    """A correct student answer that breaks ties the other way (>= and <=)."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx, sy = (1 if x0 < x1 else -1), (1 if y0 < y1 else -1)
    err, x, y, pixels = dx - dy, x0, y0, []
    while True:
        pixels.append((x, y))
        if (x, y) == (x1, y1):
            return pixels
        err2 = 2 * err
        if err2 >= -dy:
            err, x = err - dy, x + sx
        if err2 <= dx:
            err, y = err + dx, y + sy


def precomputed(library_function, cases, **options):
    """A student function answering each of the checker's cases from a table made beforehand.

    The checker refuses a function that calls or names the library's own answer, so the
    library's pixels for a case are computed here, outside the call being checked.
    """
    table = {tuple(case): library_function(*case, **options) for case in cases}

    def answer(*points):
        return table[points]

    return answer


LIBRARY_REFUSED = (
    "your function calls course.raster.{}, the library's own answer: this exercise writes it"
)


def test_draw_line_accepts_bresenham_with_either_tie_rule():
    result = check.draw_line(bresenham_ties_toward_the_end)
    assert result and result.message == "all 15 cases pass"


def test_draw_line_rejects_the_reports_staircase():
    staircase = precomputed(lambda p0, p1: line_4connected(p0, p1).tolist(), check._LINE_CASES)
    result = check.draw_line(staircase)
    assert not result and result.mistake == "the report's staircase"
    assert "case 1 is wrong" in result.message and "p0=(2, 3)" in result.message


@pytest.mark.parametrize("library_line", [line_4connected, line])
def test_draw_line_refuses_the_librarys_own_line(library_line):
    result = check.draw_line(lambda p0, p1: library_line(p0, p1).tolist())
    assert not result
    assert result.message.splitlines()[0] == LIBRARY_REFUSED.format(library_line.__name__)


def test_draw_line_rejects_a_rounded_dda_that_skips_steep_pixels():
    def dda_in_x_only(p0, p1):
        (x0, y0), (x1, y1) = p0, p1
        step = 1 if x1 >= x0 else -1
        if x0 == x1:
            return [(x0, y0)]
        return [
            (x, round(y0 + (y1 - y0) * (x - x0) / (x1 - x0))) for x in range(x0, x1 + step, step)
        ]

    result = check.draw_line(dda_in_x_only)
    assert not result and "case 3 is wrong" in result.message


def test_draw_line_reports_a_crash_with_its_case():
    def crashes_on_vertical_lines(p0, p1):
        slope = (p1[1] - p0[1]) / (p1[0] - p0[0])
        assert math.isfinite(slope)
        return bresenham_ties_toward_the_end(p0, p1)

    result = check.draw_line(crashes_on_vertical_lines)
    assert not result and "raised ZeroDivisionError" in result.message
    assert "p0=(0, 7)" in result.message


def point_in_triangle_with_top_left_rule(p0, p1, p2):
    """A correct student answer: test every centre of the bounding box."""
    (ax, ay), (bx, by), (cx, cy) = p0, p1, p2
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if area == 0:
        return []
    if area < 0:
        (bx, by), (cx, cy) = (cx, cy), (bx, by)
    edges = [((ax, ay), (bx, by)), ((bx, by), (cx, cy)), ((cx, cy), (ax, ay))]
    pixels = []
    for row in range(math.floor(min(ay, by, cy)), math.ceil(max(ay, by, cy))):
        for column in range(math.floor(min(ax, bx, cx)), math.ceil(max(ax, bx, cx))):
            px, py = column + 0.5, row + 0.5
            inside = True
            for (x0, y0), (x1, y1) in edges:
                value = (x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)
                top_left = y1 < y0 or (y1 == y0 and x1 > x0)
                inside &= value > 0 or (value == 0 and top_left)
            if inside:
                pixels.append((column, row))
    return pixels


def test_draw_triangle_filled_accepts_a_correct_answer_in_any_order():
    assert check.draw_triangle_filled(point_in_triangle_with_top_left_rule)
    library = precomputed(triangle, check._TRIANGLE_CASES)
    assert check.draw_triangle_filled(lambda p0, p1, p2: library(p0, p1, p2)[::-1])


def test_draw_triangle_filled_refuses_the_librarys_own_fill():
    result = check.draw_triangle_filled(lambda p0, p1, p2: triangle(p0, p1, p2))
    assert not result
    assert result.message.splitlines()[0] == LIBRARY_REFUSED.format("triangle")


def test_draw_triangle_filled_names_the_shared_edge_case_for_the_closed_rule():
    result = check.draw_triangle_filled(precomputed(triangle, check._TRIANGLE_CASES, rule="closed"))
    assert not result and "case 5 is wrong" in result.message
    assert result.mistake == "every edge closed"


def test_draw_triangle_filled_rejects_pixels_painted_twice():
    library = precomputed(triangle, check._TRIANGLE_CASES)

    def twice(p0, p1, p2):
        pixels = library(p0, p1, p2).tolist()
        return pixels + pixels[:1]

    result = check.draw_triangle_filled(twice)
    assert not result and "case 1 is wrong" in result.message


def test_draw_triangle_filled_reports_the_handouts_division_by_zero():
    library = precomputed(triangle, check._TRIANGLE_CASES)

    def scanline_without_special_cases(p0, p1, p2):
        top, middle, _ = sorted([p0, p1, p2], key=lambda p: p[1])
        # The handout's warning: the slope of top -> middle divides by zero
        # when the two share a y.
        (middle[0] - top[0]) / (middle[1] - top[1])
        return library(p0, p1, p2).tolist()

    result = check.draw_triangle_filled(scanline_without_special_cases)
    assert not result and "case 3 raised ZeroDivisionError" in result.message


def the_reports_loop(p0, p1):
    """The lab report's Task 4 loop, with its `else`: a step moves x or y, never both."""
    (x, y), (x1, y1) = p0, p1
    dx, dy = abs(x1 - x), abs(y1 - y)
    sx, sy = (1 if x < x1 else -1), (1 if y < y1 else -1)
    err, pixels = dx - dy, [(x, y)]
    while (x, y) != (x1, y1):
        if 2 * err > -dy:
            err, x = err - dy, x + sx
        else:
            err, y = err + dx, y + sy
        pixels.append((x, y))
    return pixels


@pytest.mark.parametrize(
    ("solution", "mistake"),
    [
        (the_reports_loop, "the report's staircase"),
        (lambda p0, p1: bresenham_ties_toward_the_end(p1, p0), "drawn backwards"),
        (lambda p0, p1: bresenham_ties_toward_the_end(p0, p1)[:-1], "the last pixel missing"),
        (lambda p0, p1: bresenham_ties_toward_the_end(p0, p1)[1:], "the first pixel missing"),
    ],
)
def test_draw_line_names_each_known_mistake_and_draws_the_difference(solution, mistake):
    result = check.draw_line(solution)
    assert not result and result.mistake == mistake
    if mistake == "drawn backwards":
        # the same pixels in the other order: the words say it, a picture of pixels cannot
        assert "\n  the same pixels\n" in str(result) and result.picture is None
    else:
        assert result.picture.startswith(b"\x89PNG")
        assert "missing" in str(result) or "extra" in str(result)


def scanline(p0, p1, p2, closed=False):
    """A scanline fill, as the lab asks; ``closed`` takes the right edge and bottom row too."""
    top, middle, bottom = sorted([p0, p1, p2], key=lambda p: p[1])
    first, last = math.ceil(top[1] - 0.5), math.ceil(bottom[1] - 0.5) + (1 if closed else 0)
    pixels = set()
    for row in range(first, last):
        y = row + 0.5
        if not top[1] <= y <= bottom[1] or bottom[1] == top[1]:
            continue
        x_long = top[0] + (y - top[1]) * (bottom[0] - top[0]) / (bottom[1] - top[1])
        a, b = (top, middle) if y < middle[1] else (middle, bottom)
        if b[1] == a[1]:
            continue
        x_short = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        left, right = min(x_long, x_short), max(x_long, x_short)
        end = math.floor(right - 0.5) + 1 if closed else math.ceil(right - 0.5)
        pixels.update((column, row) for column in range(math.ceil(left - 0.5), end))
    return sorted(pixels)


def test_a_scanline_fill_with_half_open_spans_is_the_top_left_rule():
    assert check.draw_triangle_filled(scanline)


def test_draw_triangle_filled_names_each_known_mistake_with_a_pixel_picture():
    closed = check.draw_triangle_filled(lambda p0, p1, p2: scanline(p0, p1, p2, closed=True))
    assert not closed and closed.mistake == "every edge closed"
    corners = check.draw_triangle_filled(
        precomputed(
            lambda p0, p1, p2: triangle(*(np.subtract(p, 0.5) for p in (p0, p1, p2))),
            check._TRIANGLE_CASES,
        )
    )
    assert corners.mistake == "pixel corners for centres" and corners.picture is not None
    assert "far corner (x + 1, y + 1)" in str(corners)
    opened = check.draw_triangle_filled(precomputed(triangle, check._TRIANGLE_CASES, rule="open"))
    assert opened.mistake == "every edge open" and "case 5 is wrong" in str(opened)


def fill_by_rule(p0, p1, p2, left=True, right=False, top=True, bottom=False, snap=None):
    """A centre-by-centre fill that says, per kind of edge, whether a centre on it is in.

    Written independently of the library: each centre is tested against the three edges of the
    triangle sorted by y, with a left, right, top and bottom edge told apart by their direction.
    """
    corners = [
        tuple(map(float, p if snap is None else (snap(p[0]), snap(p[1])))) for p in (p0, p1, p2)
    ]
    (ax, ay), (bx, by), (cx, cy) = corners
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if area == 0:
        return []
    if area < 0:  # clockwise on screen (y down): the inside is left of each edge
        corners = [corners[0], corners[2], corners[1]]
    pixels = []
    xs, ys = [c[0] for c in corners], [c[1] for c in corners]
    for row in range(math.floor(min(ys)) - 1, math.ceil(max(ys)) + 1):
        for column in range(math.floor(min(xs)) - 1, math.ceil(max(xs)) + 1):
            px, py = column + 0.5, row + 0.5
            inside = True
            for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1], strict=True):
                side = (x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)
                if side == 0:
                    if y0 == y1:  # horizontal: a top edge has the inside below it
                        keep = top if x1 > x0 else bottom
                    else:  # going down the screen on the right side: a right edge
                        keep = right if y1 > y0 else left
                    inside = inside and keep
                else:
                    inside = inside and side > 0
            if inside:
                pixels.append((column, row))
    return pixels


def test_the_reference_rule_written_independently_passes():
    assert check.draw_triangle_filled(fill_by_rule)


@pytest.mark.parametrize(
    ("options", "mistake"),
    [
        ({"bottom": True}, "the bottom row filled"),
        ({"top": False}, "the top row left out"),
        ({"left": False, "right": True}, "the rule mirrored"),
        ({"left": False, "top": False}, "every edge open"),
        ({"left": False}, "a centre on a left edge left out"),
        ({"snap": round}, "the vertices rounded"),
        ({"snap": int}, "the vertices made whole"),
    ],
)
def test_each_fill_rule_mistake_gets_the_name_of_what_the_student_did(options, mistake):
    result = check.draw_triangle_filled(lambda p0, p1, p2: fill_by_rule(p0, p1, p2, **options))
    assert not result and result.mistake == mistake, str(result)


def test_a_mirrored_rule_is_told_from_an_open_one_where_a_case_can_tell_them_apart():
    # (0, 0), (8, 8), (0, 8) has centres only on its right edge: open leaves them out,
    # the mirrored rule keeps them, so each is named for what it did.
    case = {"p0": (0, 0), "p1": (8, 8), "p2": (0, 8)}
    mirrored = mistakes.unless_same(mistakes.mirrored_rule, mistakes.open_rule, **case)
    opened = mistakes.unless_same(mistakes.open_rule, mistakes.mirrored_rule, **case)
    assert mirrored is not None and opened is not None
    expected = fill_by_rule(**case, left=False, right=True)
    assert mistakes.same_or_nothing(mirrored, np.array(expected))
    assert mistakes.same_or_nothing(opened, np.array(fill_by_rule(**case, left=False, top=False)))
    same = {"p0": (1, 1), "p1": (9, 2), "p2": (4, 8)}
    assert mistakes.unless_same(mistakes.mirrored_rule, mistakes.open_rule, **same) is None


@pytest.mark.parametrize("number", range(1, len(check._TRIANGLE_CASES) + 1))
def test_left_edges_open_is_the_lessons_rule_with_the_left_edges_left_out(number):
    case = dict(zip(("p0", "p1", "p2"), check._TRIANGLE_CASES[number - 1], strict=True))
    assert sorted(map(tuple, mistakes.left_edges_open(**case).tolist())) == sorted(
        fill_by_rule(**case, left=False)
    )


def test_the_first_case_an_edge_rule_fails_tells_each_rule_from_the_others():
    # The three rules that leave out a centre on a left edge differ on the right and top edges;
    # the first case with a centre on an edge has centres on all three kinds.
    rules = {
        "the rule mirrored": {"left": False, "right": True},
        "every edge open": {"left": False, "top": False},
        "a centre on a left edge left out": {"left": False},
        "every edge closed": {"right": True, "bottom": True},
        "the top row left out": {"top": False},
    }
    for mistake, options in rules.items():
        result = check.draw_triangle_filled(
            lambda p0, p1, p2, o=options: fill_by_rule(p0, p1, p2, **o)
        )
        assert result.mistake == mistake and "case 5 is wrong" in str(result), str(result)


def corner_sampling(p0, p1, p2, corner=(0, 0), rule="top-left"):
    """A student's fill that tests a pixel's corner (x + corner), not its centre, by edge
    functions: each edge keeps a point on it by ``rule`` ("top-left", "closed", "open", or
    "mirrored": right and top edges in)."""
    (ax, ay), (bx, by), (cx, cy) = p0, p1, p2
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if area == 0:
        return []
    if area < 0:
        (bx, by), (cx, cy) = (cx, cy), (bx, by)
    edges = [((ax, ay), (bx, by)), ((bx, by), (cx, cy)), ((cx, cy), (ax, ay))]
    pixels = []
    for row in range(math.floor(min(ay, by, cy)) - 1, math.ceil(max(ay, by, cy)) + 1):
        for column in range(math.floor(min(ax, bx, cx)) - 1, math.ceil(max(ax, bx, cx)) + 1):
            px, py = column + corner[0], row + corner[1]
            inside = True
            for (x0, y0), (x1, y1) in edges:
                value = (x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)
                keep = {
                    "top-left": y1 < y0 or (y1 == y0 and x1 > x0),
                    "closed": True,
                    "open": False,
                    "mirrored": y1 > y0 or (y1 == y0 and x1 > x0),
                }[rule]
                inside &= value > 0 or (value == 0 and keep)
            if inside:
                pixels.append((column, row))
    return pixels


def scanline_through_corners(p0, p1, p2):
    """The lab's scanline fill with the rows' y at each row's top, y = row, not row + 0.5."""
    top, middle, bottom = sorted([p0, p1, p2], key=lambda p: p[1])
    pixels = []
    for row in range(math.ceil(top[1]), math.ceil(bottom[1])):
        y = row
        x_long = top[0] + (y - top[1]) * (bottom[0] - top[0]) / (bottom[1] - top[1])
        a, b = (top, middle) if y < middle[1] else (middle, bottom)
        x_short = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        left, right = min(x_long, x_short), max(x_long, x_short)
        pixels += [(x, row) for x in range(math.ceil(left), math.ceil(right))]
    return pixels


@pytest.mark.parametrize("rule", ["top-left", "closed", "open", "mirrored"])
@pytest.mark.parametrize(
    ("corner", "said"), [((0, 0), "corner (x, y)"), ((1, 1), "far corner (x + 1, y + 1)")]
)
def test_a_pixel_corner_tested_for_its_centre_is_named_under_any_edge_rule(rule, corner, said):
    result = check.draw_triangle_filled(
        lambda p0, p1, p2: corner_sampling(p0, p1, p2, corner=corner, rule=rule)
    )
    assert result.mistake == "pixel corners for centres", str(result)
    assert f"you tested the pixel's {said}, not its centre" in str(result)


def test_a_scanline_through_the_rows_tops_is_named_pixel_corners():
    result = check.draw_triangle_filled(scanline_through_corners)
    assert result.mistake == "pixel corners for centres" and "corner (x, y)" in str(result)
    assert "moved half a pixel right and down" in str(result)


def test_the_bottom_row_mistake_adds_the_flat_bottom_row_over_half_open_spans():
    # The case: (0.5, 0.5), (0.5, 5.5), (7.5, 5.5) has 16 pixels, 7 more with row 5.
    pixels = mistakes.bottom_row_filled((0.5, 0.5), (0.5, 5.5), (7.5, 5.5))
    assert len(pixels) == 23
    assert sorted(map(tuple, pixels.tolist())) == sorted(
        fill_by_rule((0.5, 0.5), (0.5, 5.5), (7.5, 5.5), bottom=True)
    )


def test_the_lessons_first_octant_pseudocode_used_as_is_is_named_and_its_first_pixel_is_p0():
    def first_octant(p0, p1):
        (x0, y0), (x1, y1) = p0, p1
        dx, dy = x1 - x0, y1 - y0
        decision, y, pixels = 2 * dy - dx, y0, []
        for x in range(x0, x1 + 1):
            pixels.append((x, y))
            if decision > 0:
                y, decision = y + 1, decision - 2 * dx
            decision += 2 * dy
        return pixels

    result = check.draw_line(first_octant)
    assert not result and result.mistake == "the first octant only"
    # Case 2 runs from (9, 5) to (2, 3): the first missing pixel along the line is p0.
    assert "8 pixels missing, first at (x, y) = (9, 5)" in str(result)


def test_a_dda_that_truncates_with_int_is_named():
    def truncating(p0, p1):
        (x0, y0), (x1, y1) = p0, p1
        n = max(abs(x1 - x0), abs(y1 - y0))
        return [(int(x0 + i / n * (x1 - x0)), int(y0 + i / n * (y1 - y0))) for i in range(n + 1)]

    result = check.draw_line(lambda p0, p1: truncating(p0, p1) if p0 != p1 else [p0])
    assert not result and result.mistake == "truncated, not rounded"


def test_a_line_returned_as_a_set_is_told_that_order_matters():
    as_set = precomputed(lambda p0, p1: set(map(tuple, line(p0, p1).tolist())), check._LINE_CASES)
    result = check.draw_line(as_set)
    assert not result and "no order" in str(result)


def test_pixels_returned_as_ints_are_shown_as_ints():
    short = precomputed(
        lambda p0, p1: [tuple(p) for p in line(p0, p1).tolist()][:-1], check._LINE_CASES
    )
    result = check.draw_line(short)
    assert "given:    [[2, 3], [3, 3]," in str(result) and "2., 3." not in str(result)
    assert str(result).startswith("FAIL draw_line:")


def separate_steps(p0, p1):
    """Bresenham with x and y stepped and painted one after the other: every diagonal step
    becomes two, an extra pixel in its corner (a 4-connected staircase of its own kind)."""
    (x, y), (x1, y1) = p0, p1
    dx, dy = abs(x1 - x), abs(y1 - y)
    sx, sy = (1 if x1 >= x else -1), (1 if y1 >= y else -1)
    error, pixels = dx - dy, [(x, y)]
    while (x, y) != (x1, y1):
        e2 = 2 * error
        if e2 > -dy:
            error, x = error - dy, x + sx
            pixels.append((x, y))
        if e2 < dx:
            error, y = error + dx, y + sy
            pixels.append((x, y))
    return pixels


def test_any_4_connected_staircase_is_named_not_only_the_librarys():
    # Its corners turn otherwise than course.raster.line_4connected's on case 1, so it is not
    # the report's loop, and the report's cause is not said.
    assert separate_steps((2, 3), (9, 5)) != line_4connected((2, 3), (9, 5)).tolist()
    result = check.draw_line(separate_steps)
    assert result.mistake == "a 4-connected staircase"
    assert "2 extra, first at (x, y) = (4, 3)" in str(result)
    assert "left an extra pixel in the corner: a 4-connected staircase" in str(result)
    assert "report" not in str(result)


def fine_t_loop(p0, p1, samples=1000, rounding=round):
    """The issue's float t loop: t in small steps from 0 to 1, a pixel kept when it is new."""
    (x0, y0), (x1, y1) = p0, p1
    pixels = []
    for k in range(samples + 1):
        t = k / samples
        pixel = (rounding(x0 + t * (x1 - x0)), rounding(y0 + t * (y1 - y0)))
        if not pixels or pixels[-1] != pixel:
            pixels.append(pixel)
    return pixels


@pytest.mark.parametrize(
    "loop",
    [
        fine_t_loop,
        lambda p0, p1: fine_t_loop(p0, p1, samples=100),
        lambda p0, p1: fine_t_loop(p0, p1, samples=37),
        lambda p0, p1: fine_t_loop(p0, p1, rounding=lambda v: math.floor(v + 0.5)),
    ],
)
def test_a_float_t_loop_with_its_repeats_dropped_is_named_for_what_it_does(loop):
    result = check.draw_line(loop)
    assert result.mistake == "every pixel the line crosses", str(result)
    assert "a float t stepped finely" in str(result) and "report" not in str(result)
    assert "2 extra, first at (x, y) = (4, 3)" in str(result)


def test_the_reports_loop_is_named_with_the_reports_test():
    result = check.draw_line(the_reports_loop)
    assert result.mistake == "the report's staircase"
    assert "if (err2 > -dy) ... else ..." in str(result)


@pytest.fixture
def in_chinese(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    course.use_language("zh-CN")
    yield
    course.use_language("en")


def test_line_and_triangle_report_in_chinese(in_chinese):
    backwards = check.draw_line(
        precomputed(lambda p0, p1: line(p0, p1)[::-1].tolist(), check._LINE_CASES)
    )
    assert str(backwards).startswith(
        "draw_line 未通过：第 1 个用例结果错误\n  输入：p0=(2, 3), p1=(9, 5)"
    )
    assert "常见错误：画反了方向。你的像素是从 p1 画到 p0 的" in str(backwards)
    assert "  像素集合相同，只是顺序不同\n" in str(backwards)  # the order, not the set
    assert backwards.mistake == "drawn backwards"  # the name stays an identifier
    staircase = str(check.draw_line(separate_steps))
    assert "多出 2 个像素，第一个在 (x, y) = (4, 3)" in staircase and "4 连通的阶梯" in staircase
    report = str(check.draw_line(the_reports_loop))
    assert "从不同时移动，画出的像素和实验报告里的循环完全一样。那个循环只有一个判断" in report
    one = str(check.draw_triangle_filled(lambda p0, p1, p2: [p0]))
    assert "缺少 " in one and "提示：看看你的循环填了哪些行" in one and "Hint" not in one

    def stub(p0, p1):
        raise NotImplementedError

    assert str(check.draw_line(stub)).startswith(
        "draw_line 未通过：你还没有写这个函数（它抛出了 NotImplementedError"
    )
    refused = str(check.draw_line(lambda p0, p1: line(p0, p1).tolist()))
    assert "你的函数调用了课程库自己的答案 course.raster.line" in refused


# --- graded: cases drawn for each submission ------------------------------------------------


def octant_of(case):
    (x0, y0), (x1, y1) = case["p0"], case["p1"]
    return (abs(y1 - y0) > abs(x1 - x0), x1 > x0, y1 > y0)


def test_graded_line_cases_are_drawn_in_the_fixed_cases_families():
    fixed = [{"p0": p0, "p1": p1} for p0, p1 in check._LINE_CASES]
    for cases in graded_draws.check_drawn_cases("draw_line"):
        assert [octant_of(c) for c in cases[:8]] == [octant_of(c) for c in fixed[:8]]
        for first, reversed_ in zip(cases[:8:2], cases[1:8:2], strict=True):
            assert (first["p0"], first["p1"]) == (reversed_["p1"], reversed_["p0"])
        (x0, y0), (x1, y1) = cases[8]["p0"], cases[8]["p1"]
        assert y0 == y1 and x1 > x0
        (x0, y0), (x1, y1) = cases[9]["p0"], cases[9]["p1"]
        assert x0 == x1 and y1 < y0
        assert cases[10]["p0"] == cases[10]["p1"]
        for case, slope in zip(cases[11:14], (1, -1, 0.5), strict=True):
            (x0, y0), (x1, y1) = case["p0"], case["p1"]
            assert (y1 - y0) == slope * (x1 - x0) != 0
        (x0, y0), (x1, y1) = cases[14]["p0"], cases[14]["p1"]
        dx, dy = x1 - x0, y1 - y0
        assert 0 < dy < dx and any(2 * dy * k % (2 * dx) == dx for k in range(1, dx))


def twice_area(case):
    (ax, ay), (bx, by), (cx, cy) = case["p0"], case["p1"], case["p2"]
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def test_graded_triangle_cases_are_drawn_in_the_fixed_cases_families():
    fixed = [{"p0": p0, "p1": p1, "p2": p2} for p0, p1, p2 in check._TRIANGLE_CASES]
    for cases in graded_draws.check_drawn_cases("draw_triangle_filled"):
        corners = [np.array([c["p0"], c["p1"], c["p2"]], dtype=float) for c in cases]
        wound = [np.sign(twice_area(c)) for c in cases]
        assert wound[:10] + wound[11:] == [1, -1, 1, -1, 1, 1, 1, 1, 0, 0, -1, 1]
        assert all((c == np.round(c)).all() for c in corners[:4] + corners[5:7] + corners[8:10])
        for number in (4, 11):  # vertices on pixel centres
            assert (corners[number] % 1 == 0.5).all()
        for number in (7, 12):  # float vertices: no centre within the library's snap of an edge
            assert check._centres_clear_of_edges(corners[number])
        assert (corners[10][:, 1].max() - corners[10][:, 1].min()) < 0.5
        # The same pixels, each case, as in the fixed case: none, a few, or many.
        assert [len(triangle(**c)) == 0 for c in cases] == [len(triangle(**c)) == 0 for c in fixed]


@pytest.mark.parametrize("name", ["draw_line", "draw_triangle_filled"])
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(name):
    graded_draws.check_graded(name)


# --- the readers' students: the lesson's loop extended to every octant, with one slip ------


def lessons_loop(p0, p1, swap_steep=True, swap_back=True, step_back=2, ties=">"):
    """The lesson's pseudocode as a student extends it to all eight octants, with a slip if
    asked: no swap of x and y for a steep line, the swap not undone when plotting, or D going
    back by ``step_back`` dx when y steps. ``ties`` is the test that steps y."""
    (x0, y0), (x1, y1) = p0, p1
    steep = swap_steep and abs(y1 - y0) > abs(x1 - x0)
    if steep:
        x0, y0, x1, y1 = y0, x0, y1, x1
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx, sy = (1 if x1 >= x0 else -1), (1 if y1 >= y0 else -1)
    D, y, pixels = 2 * dy - dx, y0, []
    for x in range(x0, x1 + sx, sx):
        pixels.append((y, x) if steep and swap_back else (x, y))
        if (D > 0) if ties == ">" else (D >= 0):
            y += sy
            D -= step_back * dx
        D += 2 * dy
    return pixels


@pytest.mark.parametrize("ties", [">", ">="])
def test_the_lessons_loop_extended_to_every_octant_passes(ties):
    assert check.draw_line(lambda p0, p1: lessons_loop(p0, p1, ties=ties))


@pytest.mark.parametrize(
    ("slip", "mistake", "said"),
    [
        ({"swap_steep": False}, "no swap for a steep line", "a steep line takes one pixel per"),
        ({"swap_back": False}, "the steep swap not undone", "Swap each pixel back when you plot"),
        ({"step_back": 1}, "D stepped back by dx, not 2 dx", "D = D - 2 dx"),
    ],
)
@pytest.mark.parametrize("ties", [">", ">="])
def test_each_slip_in_the_lessons_loop_is_named_for_what_the_student_did(slip, mistake, said, ties):
    result = check.draw_line(lambda p0, p1: lessons_loop(p0, p1, ties=ties, **slip))
    assert not result and result.mistake == mistake, str(result)
    assert said in str(result)
    # A loop without the swap was told it handled only the first octant: it handles four.
    assert "the first octant" not in str(result)


def test_pixels_returned_as_y_x_are_named():
    result = check.draw_line(lambda p0, p1: [(y, x) for x, y in lessons_loop(p0, p1)])
    assert not result and result.mistake == "pixels as (y, x)", str(result)
    assert "case 1 is wrong" in str(result) and "a pixel is (x, y), x first" in str(result)


def test_a_single_pixel_left_empty_is_not_told_its_last_pixel_is_missing():
    def nothing_for_a_point(p0, p1):
        if p0 == p1:
            return []  # "a line of length zero has no pixels"
        return bresenham_ties_toward_the_end(p0, p1)

    result = check.draw_line(nothing_for_a_point)
    assert not result and result.mistake == "a single pixel left empty", str(result)
    assert "case 11 is wrong" in str(result) and "Return [p0]" in str(result)
    assert "stops one pixel before p1" not in str(result)
    # A loop that always stops short is still told so, at case 1.
    short = check.draw_line(lambda p0, p1: bresenham_ties_toward_the_end(p0, p1)[:-1])
    assert short.mistake == "the last pixel missing" and "case 1 is wrong" in str(short)


def the_reports_fill(p0, p1, p2):
    """The report's scanline fill: the three edges' slopes first, then the rows of each half;
    a half of zero height has no rows, but its slope was divided already."""
    top, middle, bottom = sorted([p0, p1, p2], key=lambda p: p[1])
    slope_short_top = (middle[0] - top[0]) / (middle[1] - top[1])
    slope_short_bottom = (bottom[0] - middle[0]) / (bottom[1] - middle[1])
    slope_long = (bottom[0] - top[0]) / (bottom[1] - top[1])
    pixels = []
    for row in range(math.ceil(top[1] - 0.5), math.ceil(bottom[1] - 0.5)):
        y = row + 0.5
        x_long = top[0] + (y - top[1]) * slope_long
        if y < middle[1]:
            x_short = top[0] + (y - top[1]) * slope_short_top
        else:
            x_short = middle[0] + (y - middle[1]) * slope_short_bottom
        left, right = min(x_long, x_short), max(x_long, x_short)
        pixels += [(x, row) for x in range(math.ceil(left - 0.5), math.ceil(right - 0.5))]
    return pixels


def test_the_reports_slopes_before_the_flat_edge_test_are_named_as_its_mistake():
    result = check.draw_triangle_filled(the_reports_fill)
    assert not result and "case 3 raised ZeroDivisionError" in str(result)
    assert result.mistake == "the slopes divided before the flat-edge test", str(result)
    assert "the slopes are divided by the height before testing for a flat edge" in str(result)

    def tested_first(p0, p1, p2):
        heights = [p[1] for p in (p0, p1, p2)]
        if len(set(heights)) < 3:
            return fill_by_rule(p0, p1, p2)  # the flat halves, skipped before any slope
        return the_reports_fill(p0, p1, p2)

    assert check.draw_triangle_filled(tested_first)


def test_a_division_by_zero_elsewhere_is_not_blamed_on_the_slopes():
    def divides_by_the_area(p0, p1, p2):
        (ax, ay), (bx, by), (cx, cy) = p0, p1, p2
        1 / ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
        return fill_by_rule(p0, p1, p2)

    result = check.draw_triangle_filled(divides_by_the_area)
    assert "case 9 raised ZeroDivisionError" in str(result) and result.mistake is None
