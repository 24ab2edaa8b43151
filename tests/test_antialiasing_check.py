"""course.check.antialiasing.bilinear_splat: a correct splat passes, the handouts' mistakes fail."""

import math

import pytest

from course.check import antialiasing as check
from course.check.antialiasing import splat_table


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
    assert check.bilinear_splat(correct)

    def reordered(x, y):
        pixels, weights = correct(x, y)
        return [*pixels[::-1], (99, 99)], [*weights[::-1], 0.0]

    assert check.bilinear_splat(reordered)


@pytest.mark.parametrize(
    ("student", "case"),
    [(corners_at_integers, "case 1"), (weights_swapped, "case 1"), (truncating, "case 5")],
)
def test_typical_mistakes_fail_naming_the_case(student, case):
    result = check.bilinear_splat(student)
    assert not result
    assert f"{case} is wrong" in result.message
    assert "inputs: x=" in result.message


def test_a_crashing_splat_is_reported_not_raised():
    def broken(x, y):
        raise ZeroDivisionError("oops")

    result = check.bilinear_splat(broken)
    assert not result and "raised ZeroDivisionError" in result.message


def test_splat_table_merges_repeats_and_rejects_mismatches():
    table = splat_table([[1, 2], [1, 2], [0, 0]], [0.25, 0.5, 0.25])
    assert table.tolist() == [[0.0, 0.0, 0.25], [1.0, 2.0, 0.75]]
    with pytest.raises(ValueError, match="3 pixels, 2 weights"):
        splat_table([[0, 0], [1, 1], [2, 2]], [1.0, 0.0])
    with pytest.raises(ValueError, match="whole numbers"):
        splat_table([[0.5, 0]], [1.0])
