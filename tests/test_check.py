"""The checkers speak Chinese: the reports of lessons 01, 02, 04, 05 and 08's checkers, with
no sentence of ours left in English.

Each checker gets a wrong answer with a known mistake, twice (the second report says more);
the English report is the reference. Every message of the checkers' own modules (the
catalog's entries for them, cut at their placeholders) that the English report shows must be
gone from the Chinese one, which must hold Chinese. The report's frame ("case 1 is wrong",
"inputs:", "Hint:") comes from course.check.base, whose messages are translated there.
"""

import re
from pathlib import Path
from unittest import mock

import numpy as np
import pytest
from babel.messages.pofile import read_po

import course
from course.check import base, pictures, sandbox
from course.check.pictures import curve_picture
from course.lessons.l01_de_casteljau import check as de_casteljau
from course.lessons.l02_bernstein import check as bernstein
from course.lessons.l04_supersampling import check as supersampling
from course.lessons.l05_antialiasing import check as antialiasing
from course.lessons.l08_poisson import check as poisson

CATALOG = Path(__file__).resolve().parent.parent / "course/locale/zh_CN/LC_MESSAGES/course.po"
OURS = tuple(
    f"course/lessons/{chapter}/check.py"
    for chapter in (
        "l01_de_casteljau",
        "l02_bernstein",
        "l04_supersampling",
        "l05_antialiasing",
        "l08_poisson",
    )
)
OURS += ("course/check/sandbox.py", "course/check/budget.py", "course/check/views.py")
OURS += (  # lesson 05's splats as tables, and its checkers' mistakes
    "course/lessons/l05_antialiasing/splat_tables.py",
    "course/lessons/l05_antialiasing/mistakes.py",
)
OURS += (  # the drawing loop's mistakes
    "course/lessons/l01_de_casteljau/drawing_loop.py",
    "course/lessons/l01_de_casteljau/mistakes.py",
)
CJK = re.compile(r"[\u4e00-\u9fff]")


def _fragments() -> set[str]:
    """Our messages' English, cut at their placeholders, the pieces long enough to be words."""
    with CATALOG.open("rb") as file:
        catalog = read_po(file)
    pieces = set()
    for message in catalog:
        if not message.id or not any(path in OURS for path, _ in message.locations):
            continue
        for text in message.id if isinstance(message.id, tuple) else (message.id,):
            pieces.update(p.strip() for p in re.split(r"\{\w*\}", text) if len(p.strip()) >= 12)
    # The pointer to more help is the report frame's too (course.check.base), in its language.
    return {p for p in pieces if "check.hint(" not in p}


@pytest.fixture(autouse=True)
def english_after():
    yield
    course.use_language("en")


def _reversed_level(control_points, t):
    points = np.asarray(control_points, dtype=float)
    return t * points[:-1] + (1 - t) * points[1:]


def _reversed_point(control_points, t):
    points = np.asarray(control_points, dtype=float)
    while len(points) > 1:
        points = _reversed_level(points, t)
    return points[0]


def _point(control_points, t):
    points = np.asarray(control_points, dtype=float)
    while len(points) > 1:
        points = (1 - t) * points[:-1] + t * points[1:]
    return points[0]


def _copy_painter(control_points, window):
    window = window.copy()
    height, width = window.shape[:2]
    for k in range(1001):
        x, y = _point(control_points, k / 1000)
        if 0 <= x < width and 0 <= y < height:
            window[int(y), int(x)] = (0, 1, 0)
    return window


def _float_comb(m, n):
    return 1.0


def _whole_centres(image, x, y):
    image = np.asarray(image, dtype=float)
    height, width = image.shape[:2]
    u, v = min(max(x, 0.0), width - 1.0), min(max(y, 0.0), height - 1.0)
    left, top = min(int(u), width - 2), min(int(v), height - 2)
    fx, fy = u - left, v - top
    upper = image[top, left] * (1 - fx) + image[top, left + 1] * fx
    lower = image[top + 1, left] * (1 - fx) + image[top + 1, left + 1] * fx
    return upper * (1 - fy) + lower * fy


def _divided_by_rate(image, out_shape, rate):
    image = np.asarray(image, dtype=float)
    height, width = out_shape
    result = np.zeros((height, width, *image.shape[2:]))
    for row in range(height):
        for column in range(width):
            for j in range(rate):
                for i in range(rate):
                    x = (column + (i + 0.5) / rate) * image.shape[1] / width
                    y = (row + (j + 0.5) / rate) * image.shape[0] / height
                    result[row, column] += _centred(image, x, y) / rate
    return result


def _centred(image, x, y):
    return _whole_centres(image, x - 0.5, y - 0.5)


def _one_pixel(x, y):
    return [(int(x), int(y))], [1.0]


def _counting(samples):
    return np.ones(len(samples))


def _flipped_ring(background, foreground, offset):
    x, y = offset
    height, width = np.shape(foreground)[:2]
    g = np.asarray(foreground, dtype=float) - np.asarray(background)[y : y + height, x : x + width]
    g[1:-1, 1:-1] = 0
    return g


def _sweep_then_test(g, tolerance):
    g = np.array(g, dtype=float)
    sweeps = 0
    while True:
        g[1:-1, 1:-1] = (g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]) / 4
        sweeps += 1
        n = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
        if np.abs(n - 4 * g[1:-1, 1:-1]).max() < tolerance:
            return g, sweeps


CHECKS = [
    (de_casteljau.next_level, _reversed_level),
    (de_casteljau.recursive_bezier, _reversed_point),
    (de_casteljau.bezier, _copy_painter),
    (bernstein.comb, _float_comb),
    (bernstein.naive_bezier, _reversed_point),
    (supersampling.bilinear_sample, _whole_centres),
    (supersampling.supersample, _divided_by_rate),
    (antialiasing.splat, _one_pixel),
    (antialiasing.arc_length_weights, _counting),
    (poisson.boundary_ring, _flipped_ring),
    (poisson.jacobi_solve, _sweep_then_test),
]


@pytest.mark.parametrize(("checker", "answer"), CHECKS, ids=[c.__name__ for c, _ in CHECKS])
def test_a_report_in_chinese_keeps_no_english_sentence_of_its_checker(checker, answer, monkeypatch):
    fragments = _fragments()
    reports = {}
    for language in ("en", "zh-CN"):
        course.use_language(language)
        monkeypatch.setattr(base, "_FAILURES", base.Counter())
        first, second = checker(answer), checker(answer)
        assert not first and first.mistake is not None
        reports[language] = f"{first}\n{second}"
    shown = [f for f in fragments if f in reports["en"]]
    assert shown, "the English report shows none of the checker's own messages"
    assert CJK.search(reports["zh-CN"])
    assert [f for f in shown if f in reports["zh-CN"]] == []


def test_the_sandbox_speaks_chinese_too():
    course.use_language("zh-CN")
    problem = sandbox.arity_problem(lambda p: p, ("control_points", "t"))
    assert problem == "应有 2 个参数（control_points, t）；你的函数接受 1 个（p）"
    course.use_language("en")
    assert sandbox.arity_problem(lambda p: p, ("control_points", "t")) == (
        "expected 2 parameters, (control_points, t); your function takes 1, (p)"
    )


def test_the_hints_follow_the_language_of_the_moment():
    # Hints are registered once, at import, in English, and translated where they are shown.
    english = str(base.hint("bezier"))
    assert de_casteljau.BEZIER_HINTS.where in english
    course.use_language("zh-CN")
    try:
        chinese = str(base.hint("bezier"))
        assert CJK.search(chinese) and de_casteljau.BEZIER_HINTS.where not in chinese
        assert CJK.search(str(base.hint("bezier", recipe=True)))
    finally:
        course.use_language("en")
    assert str(base.hint("bezier")) == english


def test_a_single_point_s_picture_marks_where_it_should_be():
    control = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]])
    curve = np.array([[0.0, 0.0], [7.5, 2.5], [10.0, 10.0]])
    mine = np.array([[7.5, 2.5]])  # on the curve, at the wrong t: it looks right alone
    plain = curve_picture(control, curve, mine, "t = 0.25")
    marked = curve_picture(control, curve, mine, "t = 0.25", expected_point=[[2.8, 0.3]])
    assert plain.startswith(b"\x89PNG") and marked != plain
    with pytest.raises(ValueError, match="expected_point must be finite"):
        curve_picture(control, curve, mine, expected_point=[[np.nan, 0.0]])


def tick_labels(axes, axis):
    """The ticks of ``axes``' x or y axis, as {position: label}."""
    ticks = getattr(axes, f"get_{axis}ticks")()
    labels = [label.get_text() for label in getattr(axes, f"get_{axis}ticklabels")()]
    return dict(zip(ticks.tolist(), labels, strict=True))


def test_a_pixel_picture_numbers_pixels_as_the_lessons_figures_do():
    # The lessons' figures draw pixel (x, y) as the square from (x, y) to (x + 1, y + 1), with
    # whole ticks on pixel corners: a triangle's vertex at (0, 0) shows at the ticks (0, 0).
    triangle = [(0, 0), (6, 0), (0, 4)]
    figure = pictures._pixel_figure([[0, 0], [1, 0]], [[0, 0]], 16, 18, "", triangle)
    axes = figure.axes[0]
    for axis in ("x", "y"):
        assert all(float(label) == tick for tick, label in tick_labels(axes, axis).items())
    assert 0.0 in tick_labels(axes, "x") and 0.0 in tick_labels(axes, "y")
    (outline,) = axes.lines
    assert tuple(outline.get_xydata()[0]) == (0.0, 0.0)
    left, right, bottom, top = axes.images[0].get_extent()
    assert (axes.get_xlim(), axes.get_ylim()) == ((left, right), (bottom, top))
    assert (right - left, bottom - top) == axes.images[0].get_array().shape[::-1]


def test_a_pixel_picture_frames_a_small_case_whole_and_a_large_one_at_its_first_difference():
    # The picture: a 16 x 16 window around a triangle in one corner, mostly empty.
    corners = [(1, 1), (9, 2), (5, 8)]
    pixels = [[x, y] for y in range(2, 8) for x in range(3, 8)]
    axes = pictures._pixel_figure(pixels, pixels[1:], 16, 18, "", corners).axes[0]
    assert axes.get_xlim() == (0.0, 10.0) and axes.get_ylim() == (9.0, 0.0)
    line = [[x, 3] for x in range(40)]
    axes = pictures._pixel_figure(line, line[:30] + line[31:], 16, 18, "", None).axes[0]
    low, high = axes.get_xlim()
    assert high - low == 16 and low <= 30 < high  # the missing pixel (30, 3), in a 16 window


def test_an_image_pictures_difference_panel_puts_its_ticks_on_pixel_corners():
    picture = np.zeros((4, 6))
    figure = mock_figure_of(pictures.image_picture, picture, picture)
    difference = next(a for a in figure.axes if a.get_title() == "your result minus expected")
    assert tuple(difference.images[0].get_extent()) == (0, 6, 4, 0)
    assert list(difference.get_xticks()) == [0, 2, 4, 6]
    assert list(difference.get_yticks()) == [0, 1, 2, 3, 4]


def mock_figure_of(function, *arguments):
    """The figure ``function`` draws, caught where it is turned into a PNG."""
    caught = []
    with mock.patch.object(pictures, "figure_png", lambda figure: caught.append(figure) or b""):
        function(*arguments)
    return caught[0]


def test_a_colour_answers_difference_shows_swapped_channels_and_a_gray_answer_is_gray():
    from course.check.pictures import shown_difference

    rng = np.random.default_rng(7)
    want = rng.random((4, 5, 3))
    swapped = want[..., ::-1]
    _, difference = shown_difference(want, swapped)
    # The mean over channels of a swap is (b - r + 0 + r - b) / 3 = 0: the old map was blank.
    assert np.allclose((swapped - want).mean(axis=2), 0)
    largest = np.abs(swapped - want).max(axis=2)
    assert np.allclose(np.abs(difference), largest) and largest.max() > 0.1
    gray = want.mean(axis=2)
    shown, difference = shown_difference(want, gray)
    assert shown.shape == want.shape and np.allclose(shown[..., 0], gray)
    assert np.allclose(np.abs(difference), np.abs(gray[..., None] - want).max(axis=2))
    shown, difference = shown_difference(want, np.zeros((2, 2)))
    assert np.isnan(shown).all() and np.isnan(difference).all() and shown.shape == (4, 5)
