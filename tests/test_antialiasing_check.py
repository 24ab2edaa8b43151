"""Lesson 05's splat checker: a correct splat passes, the handouts' mistakes fail."""

import math

import graded_draws
import numpy as np
import pytest

from course.i18n import language
from course.lessons.l05_antialiasing import check, mistakes
from course.lessons.l05_antialiasing.splat_tables import splat_table


def correct(x, y):
    left, top = math.floor(x - 0.5), math.floor(y - 0.5)
    dx, dy = x - (left + 0.5), y - (top + 0.5)
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]


def corners_at_integers(x, y):
    # Seed 000 "middle": pixels treated as sitting at their corners.
    left, top = math.floor(x), math.floor(y)
    dx, dy = x - left, y - top
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]


def truncating(x, y):
    # int() instead of floor: right from the first pixel centre on, wrong before it.
    left, top = int(x - 0.5), int(y - 0.5)
    dx, dy = x - (left + 0.5), y - (top + 0.5)
    pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
    return pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]


def weights_swapped(x, y):
    pixels, weights = correct(x, y)
    return pixels, weights[::-1]


def test_a_correct_splat_passes_in_any_order_and_with_zero_weights():
    assert check.splat(correct)

    def reordered(x, y):
        pixels, weights = correct(x, y)
        return [*pixels[::-1], (99, 99)], [*weights[::-1], 0.0]

    assert check.splat(reordered)


@pytest.mark.parametrize(
    ("student", "case"),
    [(corners_at_integers, "case 1"), (weights_swapped, "case 1"), (truncating, "case 5")],
)
def test_typical_mistakes_fail_naming_the_case(student, case):
    result = check.splat(student)
    assert not result
    assert f"{case} is wrong" in result.message
    assert "inputs: x=" in result.message


def test_a_crashing_splat_is_reported_not_raised():
    def broken(x, y):
        raise ZeroDivisionError("oops")

    result = check.splat(broken)
    assert not result and "raised ZeroDivisionError" in result.message


def test_splat_table_merges_repeats_and_rejects_mismatches():
    table = splat_table([[1, 2], [1, 2], [0, 0]], [0.25, 0.5, 0.25])
    assert table.tolist() == [[0.0, 0.0, 0.25], [1.0, 2.0, 0.75]]
    with pytest.raises(ValueError, match="3 pixels, 2 weights"):
        splat_table([[0, 0], [1, 1], [2, 2]], [1.0, 0.0])
    with pytest.raises(ValueError, match="whole numbers"):
        splat_table([[0.5, 0]], [1.0])


def zero_offset(x, y):
    # The GAMES101 report's left addColor: corners built from the point itself, dx = 0.
    pixel = (round(x), round(y))
    return [pixel], [1.0]


def nearest_only(x, y):
    return [(round(x), round(y))], [1.0]


def swapped_xy(x, y):
    pixels, weights = correct(x, y)
    return [(row, column) for column, row in pixels], weights


@pytest.mark.parametrize(
    ("student", "mistake"),
    [
        (corners_at_integers, "pixels at their corners"),
        (weights_swapped, "each pixel its own rectangle"),
        (zero_offset, "the whole point to one pixel"),
        (swapped_xy, "x and y swapped"),
    ],
)
def test_the_handouts_splat_mistakes_are_named_and_pictured(student, mistake):
    result = check.splat(student)
    assert not result
    assert result.mistake == mistake
    assert result.picture is not None and result.picture.startswith(b"\x89PNG")
    assert "first wrong pixel:" in result.message
    assert "dx = " in result.message  # where the point lies, in the case's numbers


def test_one_pixel_for_the_whole_point_has_one_name_rounded_or_floored():
    # nearest_round and the zero-offset splat light the same pixel on every point: one name.
    def falls_in(x, y):
        return [(math.floor(x), math.floor(y))], [1.0]

    for splat in (nearest_only, falls_in):
        result = check.splat(splat)
        assert not result and result.mistake == "the whole point to one pixel"
    assert "nearest pixel only" not in {m.name for m in mistakes.SPLAT_MISTAKES}


def test_the_first_wrong_pixel_is_named_with_both_weights():
    result = check.splat(corners_at_integers)
    # Case 1, (2.5, 1.5), is pixel (2, 1)'s centre: weight 1 there; corners give (2, 1) 0.25.
    assert "first wrong pixel: (2, 1) should get 1, yours gets 0.25" in result.message


def correct_weights(samples):
    points = np.asarray(samples, dtype=float)
    chords = np.hypot(*np.diff(points, axis=0).T)
    padded = np.concatenate([[0.0], chords, [0.0]])
    return (padded[:-1] + padded[1:]) / 2


def chord_after(samples):
    points = np.asarray(samples, dtype=float)
    return np.append(np.hypot(*np.diff(points, axis=0).T), 0.0)


def chord_before(samples):
    points = np.asarray(samples, dtype=float)
    return np.insert(np.hypot(*np.diff(points, axis=0).T), 0, 0.0)


def test_arc_length_weights_pass_as_a_list_or_an_array():
    assert check.arc_length_weights(correct_weights)
    assert check.arc_length_weights(lambda samples: list(correct_weights(samples)))


@pytest.mark.parametrize(
    ("student", "mistake"),
    [
        (lambda samples: np.ones(len(samples)), "counting"),
        (chord_after, "the chord after each sample"),
        (chord_before, "the chord before each sample"),
        (lambda samples: 2 * correct_weights(samples), "whole chords on both sides"),
    ],
)
def test_arc_length_mistakes_are_named_and_plotted(student, mistake):
    result = check.arc_length_weights(student)
    assert not result
    assert result.mistake == mistake
    assert result.picture is not None and result.picture.startswith(b"\x89PNG")
    assert "first wrong value" in result.message


def test_a_lone_sample_weighted_1_is_not_called_counting():
    # Right everywhere but the last case, one sample: counting would have failed case 1.
    def lone_gets_one(samples):
        return correct_weights(samples) if len(samples) > 1 else np.array([1.0])

    result = check.arc_length_weights(lone_gets_one)
    assert not result and result.mistake is None
    assert "case 5" in result.message


def test_weights_summing_to_the_length_but_misplaced_fail():
    def all_at_the_ends(samples):
        weights = np.zeros(len(samples))
        total = correct_weights(samples).sum()
        weights[0] = weights[-1] = total / 2
        return weights if len(samples) > 1 else np.array([0.0])

    result = check.arc_length_weights(all_at_the_ends)
    assert not result and result.mistake is None


def test_a_truncated_pixel_is_not_told_it_rounds_where_both_light_the_same_pixel():
    def under_the_point(x, y):
        return [(math.floor(x), math.floor(y))], [1]

    result = check.splat(under_the_point)
    # Case 2, (3.0, 2.0): floor and round both give pixel (3, 2).
    assert not result and "case 2 is wrong" in result.message
    assert "are the same pixel" in result.message
    assert "whose corners p1..p4 are built from the point itself" not in result.message


def test_where_floor_and_round_differ_each_one_pixel_splat_gets_its_own_name():
    def first_named(x, y, splat):
        table = splat_table(*splat(x, y))
        for mistake in mistakes.SPLAT_MISTAKES:
            answer = mistake.answer(x=x, y=y)
            if answer is not None and np.array_equal(answer, table):
                return mistake
        return None

    def under(x, y):
        return [(math.floor(x), math.floor(y))], [1.0]

    def nearest(x, y):
        return [(round(x), round(y))], [1.0]

    truncated = first_named(2.75, 1.25, under)
    assert truncated.name == "the pixel under the point (truncated)"
    assert "floor(x), floor(y)" in truncated.explanation
    rounded = first_named(2.75, 1.25, nearest)
    assert rounded.name == "the whole point to one pixel"
    assert "GAMES101 report's left addColor" in rounded.explanation


def test_the_normalised_splat_names_the_vs2022_report_not_a_file():
    def normalised(x, y):
        left, top = math.floor(x - 0.5), math.floor(y - 0.5)
        pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
        near = [math.sqrt(2) - math.hypot(x - (a + 0.5), y - (b + 0.5)) for a, b in pixels]
        return pixels, [d / sum(near) for d in near]

    result = check.splat(normalised)
    assert result.mistake == "the normalised splat"
    assert "the VS2022 report's splat" in result.message
    assert "seed 003" not in result.message


@pytest.mark.parametrize(
    ("wrap", "said"),
    [
        (lambda pixels, weights: {"pixels": pixels, "weights": weights}, "yours is a dict"),
        (lambda pixels, weights: (p for p in (pixels, weights)), "yours is a generator"),
        (
            lambda pixels, weights: (iter(pixels), (w for w in weights)),
            "yours are a list_iterator and a generator",
        ),
    ],
)
def test_a_dict_or_a_generator_is_told_to_return_two_lists(wrap, said):
    result = check.splat(lambda x, y: wrap(*correct(x, y)))
    assert not result
    assert f"return two lists: pixels, weights; {said}" in result.message
    assert "could not convert" not in result.message and "float() argument" not in result.message
    assert check.splat(lambda x, y: tuple(np.asarray(v) for v in correct(x, y)))


# --- graded: cases drawn for each submission ------------------------------------------------


def under_the_point(x, y):
    return [(math.floor(x), math.floor(y))], [1.0]


#: The truncated pixel's own answer is None where rounding lights the same pixel: the
#: student's code lights it anyway.
WRITTEN_SPLAT = {1: lambda: under_the_point}
#: ... and the first case it fails, a corner, is such a point: it is named with the pixel
#: rounding lights too, on the fixed cases as on the drawn ones.
NAMED_AS_ONE_PIXEL = {"the pixel under the point (truncated)": "the whole point to one pixel"}


def test_graded_splat_cases_are_drawn_in_the_fixed_cases_families():
    for cases in graded_draws.check_drawn_cases("splat"):
        x, y = np.array([(c["x"], c["y"]) for c in cases]).T
        assert ((x * 8) % 1 == 0).all() and ((y * 8) % 1 == 0).all()
        assert (x[0] % 1, y[0] % 1, x[1] % 1, y[1] % 1) == (0.5, 0.5, 0, 0)
        assert 0.5 < x[4] < 1 and 0 < y[4] < 0.5 and x[5] == y[5] and -0.5 < x[6] < 0


def test_graded_weight_cases_are_drawn_in_the_fixed_cases_families():
    for cases in graded_draws.check_drawn_cases("arc_length_weights"):
        assert [len(c["samples"]) for c in cases] == [3, 2, 9, 12, 1]
        chords = mistakes.chords(cases[0]["samples"])
        assert chords[0] > 2 * chords[1]


@pytest.mark.parametrize(
    ("name", "written", "named_otherwise"),
    [
        ("splat", WRITTEN_SPLAT, NAMED_AS_ONE_PIXEL),
        ("arc_length_weights", {}, {}),
    ],
)
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(
    name, written, named_otherwise
):
    graded_draws.check_graded(name, written, named_otherwise)


# --- issue 34: answers written as the readers wrote them ------------------------------------


def pictures_drawn(monkeypatch):
    """Every matplotlib figure a checker turns into a PNG, in order (the pictures are bytes)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    drawn = []
    print_png = FigureCanvasAgg.print_png

    def keeping(canvas, *args, **kwargs):
        drawn.append(canvas.figure)
        return print_png(canvas, *args, **kwargs)

    monkeypatch.setattr(FigureCanvasAgg, "print_png", keeping)
    return drawn


def tick_at(axis_ticks, labels, position):
    """The label of the tick nearest ``position``."""
    nearest = int(np.argmin(np.abs(np.asarray(axis_ticks) - position)))
    return labels[nearest].get_text()


def test_the_difference_panel_numbers_each_pixel_as_the_report_does(monkeypatch):
    drawn = pictures_drawn(monkeypatch)
    result = check.splat(corners_at_integers)
    # Case 1, (2.5, 1.5): pixel (2, 1) should get 1 and gets 0.25, the one pixel 0.75 short.
    assert "first wrong pixel: (2, 1) should get 1, yours gets 0.25" in result.message
    (difference,) = [a for a in drawn[-1].axes if a.get_title() == "your result minus expected"]
    (image,) = difference.get_images()
    values = image.get_array()
    row, column = np.unravel_index(np.argmin(values), values.shape)
    assert values[row, column] == pytest.approx(-0.75)
    left, right, bottom, top = image.get_extent()
    height, width = values.shape
    x = left + (column + 0.5) * (right - left) / width
    y = top + (row + 0.5) * (bottom - top) / height
    assert tick_at(difference.get_xticks(), difference.get_xticklabels(), x) == "2"
    assert tick_at(difference.get_yticks(), difference.get_yticklabels(), y) == "1"


def test_weights_returned_before_pixels_are_named_as_such():
    def weights_first(x, y):
        left, top = math.floor(x - 0.5), math.floor(y - 0.5)
        dx, dy = x - (left + 0.5), y - (top + 0.5)
        pixels = [(left, top), (left + 1, top), (left, top + 1), (left + 1, top + 1)]
        weights = [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]
        return weights, pixels

    result = check.splat(weights_first)
    assert not result and "case 1" in result.message
    assert "you returned the weights first" in result.message
    assert "must match" not in result.message and "8 weights" not in result.message
    # One pixel and its weight, the wrong way round, is told the same.
    result = check.splat(lambda x, y: ([1.0], [(round(x), round(y))]))
    assert "you returned the weights first" in result.message


def test_the_weights_picture_numbers_samples_with_whole_numbers(monkeypatch):
    drawn = pictures_drawn(monkeypatch)
    assert not check.arc_length_weights(lambda samples: np.ones(len(samples)))
    (axes,) = drawn[-1].axes
    low, high = axes.get_xlim()
    shown = [tick for tick in axes.get_xticks() if low <= tick <= high]
    assert shown and all(float(tick).is_integer() for tick in shown), shown


# --- issue 34, the readers' own findings: the report's addColor taken at its word -----------


def right_addcolor_read_literally(x, y):
    # The GAMES101 report's right addColor, with its first version's dx = point.x - p1.x.
    center_x, center_y = round(x), round(y)
    p1 = (center_x - 1, center_y - 1)
    dx, dy = x - p1[0], y - p1[1]
    pixels = [p1, (center_x, center_y - 1), (center_x - 1, center_y), (center_x, center_y)]
    return pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]


def right_addcolor_with_std_round(x, y):
    # The same with C++'s std::round (halves away from 0): at a pixel centre, the corners' splat.
    center_x, center_y = math.floor(x + 0.5), math.floor(y + 0.5)
    p1 = (center_x - 1, center_y - 1)
    dx, dy = x - p1[0], y - p1[1]
    pixels = [p1, (center_x, center_y - 1), (center_x - 1, center_y), (center_x, center_y)]
    return pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]


def right_addcolor_from_the_centre(x, y):
    # The report's right addColor with dx from p1's centre: Exercise 1's splat.
    center_x, center_y = round(x), round(y)
    p1 = (center_x - 1, center_y - 1)
    dx, dy = x - (p1[0] + 0.5), y - (p1[1] + 0.5)
    pixels = [p1, (center_x, center_y - 1), (center_x - 1, center_y), (center_x, center_y)]
    return pixels, [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]


def times_255(x, y):
    # The report's img.at<cv::Vec3b>(p1) += color * weight, with color (0, 255, 0).
    pixels, weights = correct(x, y)
    return pixels, [255 * weight for weight in weights]


def normalised(x, y):
    pixels, weights = correct(x, y)
    return pixels, [weight / sum(weights) for weight in weights]


def on_the_canvas_only(x, y):
    pixels, weights = correct(x, y)
    kept = [(p, w) for p, w in zip(pixels, weights, strict=True) if p[0] >= 0 and p[1] >= 0]
    return [p for p, _ in kept], [w for _, w in kept]


def on_the_canvas_normalised(x, y):
    pixels, weights = on_the_canvas_only(x, y)
    return pixels, [weight / sum(weights) for weight in weights]


@pytest.mark.parametrize(
    ("student", "mistake", "said"),
    [
        (right_addcolor_read_literally, "the right addColor read literally", "dx = point.x - (p1"),
        (right_addcolor_with_std_round, "pixels at their corners", "report's right addColor"),
        (times_255, "weights times 255", "255 times too large"),
        (on_the_canvas_only, "pixels off the canvas left out", "Return all four pixels"),
        (on_the_canvas_normalised, "pixels off the canvas left out", "normalised the rest"),
    ],
)
def test_the_reports_addcolor_taken_at_its_word_is_named(student, mistake, said):
    result = check.splat(student)
    assert result.mistake == mistake
    assert said in str(result)


@pytest.mark.parametrize("student", [correct, right_addcolor_from_the_centre, normalised])
def test_right_splats_written_other_ways_pass(student):
    # Bilinear weights add up to 1: normalising them changes nothing.
    assert check.splat(student)


def test_a_splat_in_words_joins_its_pixels_as_the_language_does():
    table = np.array([[2, 1, 0.75], [3, 1, 0.25]])
    assert check._show_splat(table) == "pixel (2, 1) gets 0.75, pixel (3, 1) gets 0.25"
    with language("zh-CN"):
        chinese = check._show_splat(table)
    assert chinese == "像素 (2, 1) 得 0.75、像素 (3, 1) 得 0.25"
