"""Lesson 08's checkers: the lab's boundary ring and its Jacobi sweep, right and wrong."""

import itertools

import graded_draws
import numpy as np
import pytest

from course.i18n import language
from course.lessons.l08_poisson import check, mistakes
from course.poisson import correction_boundary


def lab_style_boundary(background, foreground, offset):
    """The lab's C++ boundary loops, transcribed (a correct student answer)."""
    height, width = foreground.shape[:2]
    x0, y0 = offset
    g = np.zeros_like(foreground)
    for y in range(height):
        g[y, 0] = background[y0 + y, x0] - foreground[y, 0]
        g[y, width - 1] = background[y0 + y, x0 + width - 1] - foreground[y, width - 1]
    for x in range(width):
        g[0, x] = background[y0, x0 + x] - foreground[0, x]
        g[height - 1, x] = background[y0 + height - 1, x0 + x] - foreground[height - 1, x]
    return g


def test_the_checker_passes_the_lab_loops():
    result = check.boundary_ring(lab_style_boundary)
    assert result and result.cases_run == 4


def flipped_sign(background, foreground, offset):
    """foreground - background: the sign the handout's formula invites."""
    return -lab_style_boundary(background, foreground, offset)


def swapped_offset(background, foreground, offset):
    """x and y swapped: only shows when they differ."""
    return lab_style_boundary(background, foreground, offset[::-1])


def filled_inside(background, foreground, offset):
    """background - foreground everywhere: the inside must start at 0."""
    x, y = offset
    height, width = foreground.shape[:2]
    return background[y : y + height, x : x + width] - foreground


@pytest.mark.parametrize(
    ("wrong", "case"),
    [(flipped_sign, "case 1 is wrong"), (swapped_offset, "case 2"), (filled_inside, "case 1")],
)
def test_the_checker_names_the_case_a_typical_mistake_fails(wrong, case):
    result = check.boundary_ring(wrong)
    assert not result
    assert case in result.message


def jacobi(g, tolerance):
    g = np.array(g, dtype=float)
    for sweeps in itertools.count():
        neighbours = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
        if np.abs(neighbours - 4 * g[1:-1, 1:-1]).max() < tolerance:
            return g, sweeps
        g[1:-1, 1:-1] = neighbours / 4


def in_place(g, tolerance):
    g = np.array(g, dtype=float)
    height, width = g.shape[:2]
    for sweeps in itertools.count():
        neighbours = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
        if np.abs(neighbours - 4 * g[1:-1, 1:-1]).max() < tolerance:
            return g, sweeps
        for y in range(1, height - 1):
            for x in range(1, width - 1):
                g[y, x] = (g[y - 1, x] + g[y + 1, x] + g[y, x - 1] + g[y, x + 1]) / 4


def sweep_first(g, tolerance):
    g = np.array(g, dtype=float)
    sweeps = 0
    while True:
        neighbours = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
        g[1:-1, 1:-1] = neighbours / 4
        sweeps += 1
        neighbours = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
        if np.abs(neighbours - 4 * g[1:-1, 1:-1]).max() < tolerance:
            return g, sweeps


def test_jacobi_solve_passes_the_slices_and_a_loop_over_a_copy():
    assert check.jacobi_solve(jacobi)

    def loop_over_a_copy(g, tolerance):
        g = np.array(g, dtype=float)
        height, width = g.shape[:2]
        for sweeps in itertools.count():
            old = g.copy()
            inside = old[:-2, 1:-1] + old[2:, 1:-1] + old[1:-1, :-2] + old[1:-1, 2:]
            if np.abs(inside - 4 * old[1:-1, 1:-1]).max() < tolerance:
                return g, sweeps
            for y in range(1, height - 1):
                for x in range(1, width - 1):
                    g[y, x] = (old[y - 1, x] + old[y + 1, x] + old[y, x - 1] + old[y, x + 1]) / 4

    assert check.jacobi_solve(loop_over_a_copy)


@pytest.mark.parametrize(
    ("student", "mistake"), [(in_place, "in place: Gauss-Seidel"), (sweep_first, "one sweep late")]
)
def test_jacobi_solve_recognises_the_labs_loop_and_a_late_stop(student, mistake):
    result = check.jacobi_solve(student)
    assert not result
    assert result.mistake == mistake
    # The late stop sweeps an all-zero g once: g is still right, only the count is not.
    assert "sweeps: expected" in result.message or (
        "g is right; only the number of sweeps differs (expected 0, given 1)" in result.message
    )
    assert result.picture is not None


def test_jacobi_solve_reports_a_ring_that_moves_and_a_missing_count():
    def ring_swept_too(g, tolerance):
        g = np.array(g, dtype=float)
        for sweeps in itertools.count():
            neighbours = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
            if np.abs(neighbours - 4 * g[1:-1, 1:-1]).max() < tolerance or sweeps > 500:
                return g, sweeps
            rolled = sum(np.roll(g, shift, axis) for shift in (1, -1) for axis in (0, 1))
            g = rolled / 4  # wraps around and moves the fixed ring

    result = check.jacobi_solve(ring_swept_too)
    assert not result and result.mistake == "the ring changed"
    assert "Sweep the inside only, g[1:-1, 1:-1]" in result.message
    result = check.jacobi_solve(lambda g, tolerance: jacobi(g, tolerance)[0])
    assert not result and "return two things" in result.message


@pytest.mark.parametrize(
    ("student", "mistake"),
    [
        (flipped_sign, "the sign flipped"),
        (
            lambda background, foreground, offset: lab_style_boundary(
                background, foreground * 0, offset
            ),
            "the background alone",
        ),
        (swapped_offset, "x and y swapped"),
    ],
)
def test_boundary_mistakes_are_named_with_a_picture(student, mistake):
    result = check.boundary_ring(student)
    assert not result
    assert result.mistake == mistake
    assert result.picture is not None


def test_the_lab_loops_are_the_librarys_ring():
    rng = np.random.default_rng(4)
    background, foreground = rng.random((9, 11, 3)), rng.random((4, 6, 3))
    np.testing.assert_array_equal(
        lab_style_boundary(background, foreground, (3, 2)),
        correction_boundary(background, foreground, (3, 2)),
    )


def test_a_call_to_the_librarys_ring_is_told_to_write_it():
    result = check.boundary_ring(
        lambda background, foreground, offset: -correction_boundary(background, foreground, offset)
    )
    assert not result and result.mistake is None
    assert result.message.startswith(
        "your function calls course.poisson.correction_boundary, the library's own answer: "
        "this exercise writes it"
    )


def until_the_change_is_small(g, tolerance):
    g = np.array(g, dtype=float)
    for sweeps in itertools.count(1):
        new = g.copy()
        new[1:-1, 1:-1] = (g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]) / 4
        if np.abs(new - g).max() < tolerance:
            return new, sweeps
        g = new


def test_a_stop_on_the_change_between_sweeps_is_named_as_stopping_early():
    result = check.jacobi_solve(until_the_change_is_small)
    assert result.mistake == "a stop on the change between sweeps"
    assert "sweeps: expected 16, given 14" in result.message
    assert "up to four times the tolerance" in result.message


def test_the_reports_name_the_exercises_as_the_lesson_does():
    zero = np.zeros((3, 3))
    assert str(check.boundary_ring(lambda background, foreground, offset: zero)).startswith(
        "FAIL boundary_ring:"
    )
    assert str(check.jacobi_solve(lambda g, tolerance: (g, 0))).startswith("FAIL jacobi_solve:")


def test_a_residual_equal_to_the_tolerance_still_gets_a_sweep():
    g = np.array([[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]])
    swept, sweeps = mistakes.jacobi_until(g, 4.0)
    assert sweeps == 1 and np.array_equal(swept, np.zeros((3, 3)))

    def stops_at_or_below(g, tolerance):
        g = np.array(g, dtype=float)
        sweeps = 0
        while True:
            n = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
            if np.abs(n - 4 * g[1:-1, 1:-1]).max() <= tolerance:
                return g, sweeps
            g[1:-1, 1:-1] = n / 4
            sweeps += 1

    result = check.jacobi_solve(stops_at_or_below)
    assert not result and "case 5 is wrong" in result.message


def stopping_on(size):
    """A Jacobi loop over a copy that tests ``size(|residual|)`` before each sweep."""

    def sweep(g, tolerance):
        g = np.array(g, dtype=float)
        for sweeps in itertools.count():
            neighbours = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
            if size(np.abs(neighbours - 4 * g[1:-1, 1:-1])) < tolerance:
                return g, sweeps
            g[1:-1, 1:-1] = neighbours / 4

    return sweep


def first_channel(size):
    return (size[..., 0] if size.ndim == 3 else size).max()


@pytest.mark.parametrize(
    ("size", "mistake", "counts", "said"),
    [
        (
            np.mean,
            "the mean of the residual instead of its largest value",
            "sweeps: expected 16, given 15",
            "the exercise compares its largest value",
        ),
        (
            lambda size: size.max() / 4,
            "a quarter of the residual",
            "sweeps: expected 16, given 13",
            "the change the next sweep makes",
        ),
        (
            first_channel,
            "the residual of the first channel only",
            "sweeps: expected 33, given 23",
            "your residual looks at channel 0 only",
        ),
    ],
)
def test_a_residual_measured_otherwise_is_named(size, mistake, counts, said):
    result = check.jacobi_solve(stopping_on(size))
    assert not result and result.mistake == mistake
    assert counts in result.message and said in result.message


def test_the_first_channel_alone_passes_every_case_but_the_rgb_one_whose_red_settles_first():
    result = check.jacobi_solve(stopping_on(first_channel))
    assert "case 6 is wrong" in result.message
    assert check.jacobi_solve(stopping_on(np.max))


def test_the_mean_and_the_change_between_sweeps_are_told_apart():
    mean = check.jacobi_solve(stopping_on(np.mean))
    change = check.jacobi_solve(until_the_change_is_small)
    assert mean.mistake != change.mistake
    assert "a stop on the change between sweeps" not in mean.message


def test_a_stop_at_or_below_the_tolerance_is_named():
    result = check.jacobi_solve(stopping_on(lambda size: np.nextafter(size.max(), -np.inf)))
    assert result.mistake == "a stop at a residual equal to the tolerance"
    assert "case 5 is wrong" in result.message


def test_a_count_from_one_says_g_is_right_and_only_the_count_differs():
    def counted_from_one(g, tolerance):
        g, sweeps = jacobi(g, tolerance)
        return g, sweeps + 1

    result = check.jacobi_solve(counted_from_one)
    assert not result
    assert "g is right; only the number of sweeps differs (expected 16, given 17)" in (
        result.message
    )
    assert "largest difference" not in result.message


# --- graded: cases drawn for each submission ------------------------------------------------


def a_thousand_sweeps(g, tolerance):
    """The lab's fixed count of sweeps (8000 there), whatever the residual."""
    g = np.array(g, dtype=float)
    for _sweep in range(1000):
        g[1:-1, 1:-1] = (g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]) / 4
    return g, 1000


#: A fixed count is recognised by its count, whatever g: its own answer says (g, 0).
WRITTEN_SWEEP = {1: lambda: a_thousand_sweeps}


def test_graded_boundary_cases_are_drawn_in_the_fixed_cases_families():
    fixed = check._cases()
    for cases in graded_draws.check_drawn_cases("boundary_ring"):
        for case, like in zip(cases, fixed, strict=True):
            assert case["background"].shape == like["background"].shape
            assert case["foreground"].shape == like["foreground"].shape
            for image in (case["background"], case["foreground"]):
                assert ((image * 16) % 1 == 0).all() and 0 <= image.min() <= image.max() <= 1
        x, y = cases[1]["offset"]
        assert x != y and max(x, y) <= 3
        assert [c["offset"] for c in cases[::2]] == [(1, 1), (2, 3)] and cases[3]["offset"] == (
            0,
            0,
        )


def test_graded_sweep_cases_are_drawn_in_the_fixed_cases_families():
    fixed = check._sweep_cases()
    for cases in graded_draws.check_drawn_cases("jacobi_solve"):
        assert [c["g"].shape for c in cases] == [c["g"].shape for c in fixed]
        assert not any(cases[number]["g"][1:-1, 1:-1].any() for number in (0, 1, 2, 5))
        assert [c["tolerance"] for c in cases[:4]] == [1e-4, 1e-6, 1e-4, 1e-6]
        assert mistakes.jacobi_until(**cases[3])[1] == 0  # already harmonic
        g, tolerance = cases[4]["g"], cases[4]["tolerance"]
        assert abs(g[0, 1] + g[2, 1] + g[1, 0] + g[1, 2] - 4 * g[1, 1]) == tolerance
        red, green = np.abs(cases[5]["g"][..., 0]).max(), np.abs(cases[5]["g"][..., 1]).max()
        assert red <= 1 / 16 and green <= 1


@pytest.mark.parametrize(
    ("name", "written"), [("boundary_ring", {}), ("jacobi_solve", WRITTEN_SWEEP)]
)
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(name, written):
    graded_draws.check_graded(name, written)


# --- RGB, the pair's order, and the picture of a wrong count (issue 34) ----------------------


def each_channel_on_its_own(count):
    """Each channel swept until its own residual is small; ``count`` makes the count returned
    from the channels' counts (the largest, their sum, the last one)."""

    def sweep(g, tolerance):
        g = np.array(g, dtype=float)
        planes = [g] if g.ndim == 2 else [g[..., channel] for channel in range(g.shape[2])]
        counts = []
        for plane in planes:  # a view: sweeping it sweeps g
            sweeps = 0
            while True:
                neighbours = plane[:-2, 1:-1] + plane[2:, 1:-1] + plane[1:-1, :-2] + plane[1:-1, 2:]
                if np.abs(neighbours - 4 * plane[1:-1, 1:-1]).max() < tolerance:
                    break
                plane[1:-1, 1:-1] = neighbours / 4
                sweeps += 1
            counts.append(sweeps)
        return g, count(counts)

    return sweep


@pytest.mark.parametrize("count", [max, sum, lambda counts: counts[-1]])
def test_each_channel_stopped_on_its_own_is_named(count):
    result = check.jacobi_solve(each_channel_on_its_own(count))
    assert not result and result.mistake == "each channel stopped on its own"
    assert "case 3 is wrong" in result.message
    assert "sweeps the three channels together" in result.message


def test_a_right_count_with_a_wrong_g_says_the_count_is_right():
    result = check.jacobi_solve(each_channel_on_its_own(max))
    assert "the number of sweeps is right (52); g is not" in result.message
    assert "sweeps: expected 52, given 52" not in result.message
    assert "largest difference in g at [row, column, channel] [2, 4, 1]" in result.message


def test_the_place_of_the_largest_difference_reads_as_rows_and_columns_in_chinese():
    with language("zh-CN"):
        result = check.jacobi_solve(each_channel_on_its_own(max))
    assert "g 中差别最大的位置是第 2 行第 4 列的通道 1，期望 " in result.message
    assert "[行" not in result.message and "[2, 4, 1]" not in result.message


def test_the_count_returned_first_is_named_and_g_is_not_printed():
    def count_first(g, tolerance):
        g, sweeps = jacobi(g, tolerance)
        return sweeps, g

    result = check.jacobi_solve(count_first)
    assert not result and result.mistake == "the number of sweeps first"
    assert "given:    (16, an array of shape (4, 5)): expected g, then the number of sweeps" in (
        result.message
    )
    assert "you returned the number of sweeps first: return g, sweeps" in result.message
    assert "[[" not in result.message.split("given:")[1]  # no array printed whole
    assert "of shape ()" not in result.message


def drawn(student, monkeypatch):
    """The report of ``student`` and the figure its picture was drawn from."""
    from course.lessons.l08_poisson import sweep_picture

    figures = []
    drawing = sweep_picture.figure_png
    monkeypatch.setattr(sweep_picture, "figure_png", lambda f: figures.append(f) or drawing(f))
    result = check.jacobi_solve(student)
    assert result.picture is not None and len(figures) == 1
    return result, figures[0]


def test_the_gauss_seidel_picture_shows_both_counts_and_no_text_overlaps(monkeypatch):
    result, figure = drawn(in_place, monkeypatch)
    assert result.mistake == "in place: Gauss-Seidel"
    assert figure._suptitle.get_text() == "Jacobi stops after 16 sweeps, yours after 10"
    plot = figure.axes[0]
    stops = {line.get_label(): line.get_xdata()[0] for line in plot.get_lines()[1:]}
    assert stops["Jacobi stops: 16"] == 16 and stops["your loop stops: 10"] == 10
    # The difference, 3.1e-05 at most, in its own scale: no "1e-5" offset above the bar.
    bar = figure.axes[-1]
    assert bar.yaxis.get_offset_text().get_text() == ""
    renderer = figure.canvas.get_renderer()
    texts = [figure._suptitle] + [axes.title for axes in figure.axes]
    texts += [label for label in bar.get_yticklabels() if label.get_text()]
    boxes = [text.get_window_extent(renderer) for text in texts if text.get_text()]
    for first, box in enumerate(boxes):
        for other in boxes[first + 1 :]:
            assert not box.overlaps(other), (box, other)


def test_the_picture_of_a_fixed_count_says_it_is_off_the_axis(monkeypatch):
    _result, figure = drawn(a_thousand_sweeps, monkeypatch)
    assert figure._suptitle.get_text() == "Jacobi stops after 16 sweeps, yours after 1000"
    said = [text.get_text() for text in figure.axes[0].texts]
    assert "your loop: 1000 sweeps,\noff this axis" in said


# --- the readers' students (issue 34): the ring in the wrong place, and a ring that moves ----


def offset_ignored(background, foreground, offset):
    height, width = foreground.shape[:2]
    g = background[:height, :width] - foreground  # the background's corner, whatever the offset
    g[1:-1, 1:-1] = 0
    return g


def ring_outside(background, foreground, offset):
    """The ring read from the background's pixels just outside the foreground."""
    height, width = foreground.shape[:2]
    x, y = offset
    g = np.zeros_like(foreground)
    g[0] = background[y - 1, x : x + width] - foreground[0]
    g[-1] = background[y + height, x : x + width] - foreground[-1]
    g[:, 0] = background[y : y + height, x - 1] - foreground[:, 0]
    g[:, -1] = background[y : y + height, x + width] - foreground[:, -1]
    return g


def ring_outside_rows_last(background, foreground, offset):
    """The same ring, its corners taken from the rows (written after the columns)."""
    height, width = foreground.shape[:2]
    x, y = offset
    g = np.zeros_like(foreground)
    g[:, 0] = background[y : y + height, x - 1] - foreground[:, 0]
    g[:, -1] = background[y : y + height, x + width] - foreground[:, -1]
    g[0] = background[y - 1, x : x + width] - foreground[0]
    g[-1] = background[y + height, x : x + width] - foreground[-1]
    return g


def ring_inside(background, foreground, offset):
    """b - f on the ring one pixel in; the outer ring left at 0."""
    height, width = foreground.shape[:2]
    x, y = offset
    difference = background[y : y + height, x : x + width] - foreground
    g = np.zeros_like(foreground)
    g[1:-1, 1:-1] = difference[1:-1, 1:-1]
    g[2:-2, 2:-2] = 0
    return g


@pytest.mark.parametrize(
    ("student", "mistake", "words"),
    [
        (offset_ignored, "the offset ignored", "background[0 : height, 0 : width]"),
        (ring_outside, "the ring one pixel out", "one pixel outside the foreground"),
        (ring_outside_rows_last, "the ring one pixel out", "the row under the foreground's top"),
        (ring_inside, "the ring one pixel in", "left the outer ring at 0"),
    ],
    ids=["offset ignored", "out, corners from the columns", "out, from the rows", "in"],
)
def test_a_ring_in_the_wrong_place_is_named(student, mistake, words):
    result = check.boundary_ring(student)
    assert not result and result.mistake == mistake
    assert f"This is a known mistake, {mistake}: " in result.message and words in result.message


def ring_swept_with_the_edge_repeated(g, tolerance):
    """Every pixel swept, the ring too, past the array's edge its nearest pixel."""
    g = np.array(g, dtype=float)
    for sweeps in itertools.count():
        padded = np.pad(g, [(1, 1), (1, 1)] + [(0, 0)] * (g.ndim - 2), mode="edge")
        neighbours = padded[:-2, 1:-1] + padded[2:, 1:-1] + padded[1:-1, :-2] + padded[1:-1, 2:]
        if np.abs(neighbours - 4 * g)[1:-1, 1:-1].max() < tolerance:
            return g, sweeps
        g = neighbours / 4


def test_a_sweep_that_moves_the_ring_is_named_and_the_right_sweep_still_passes():
    result = check.jacobi_solve(ring_swept_with_the_edge_repeated)
    assert not result and result.mistake == "the ring changed"
    assert "those are the boundary values b - f, fixed" in result.message
    assert check.jacobi_solve(jacobi)
    assert check.boundary_ring(lab_style_boundary)
