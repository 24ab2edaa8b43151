"""course.check.base: reports that name the difference, recognise mistakes and show pictures."""

import sys

import pytest

from course.check.base import (
    CallBudget,
    CheckResult,
    Mistake,
    call_budget,
    close,
    run_cases,
    same_pixels,
)

CASES = [{"x": 1.0}, {"x": 2.0}, {"x": 3.0}]


def run(student, **options):
    options.setdefault("hint", "double it")
    return run_cases("double", student, CASES, lambda x: 2 * x, close(), **options)


def test_a_pass_is_one_line_and_a_failure_ends_with_the_hint():
    assert str(run(lambda x: 2 * x)) == "PASS double: all 3 cases pass"
    failed = run(lambda x: 2 * x if x < 3 else x + 2)
    assert str(failed).splitlines() == [
        "FAIL double: case 3 is wrong",
        "  inputs: x=3.0",
        "  expected: 6.0",
        "  given:    5.0",
        "Hint: double it",
    ]
    assert failed.cases_run == 3 and not failed


def test_a_known_mistake_is_named_only_when_the_answer_is_its_answer():
    squared = Mistake("squared", "you multiplied x by itself", lambda x: x * x)
    result = run(lambda x: x * x, mistakes=[squared])
    assert result.mistake == "squared" and "known mistake, squared: you multiplied" in str(result)
    other = run(lambda x: x + 5, mistakes=[squared])
    assert other.mistake is None and "known mistake" not in str(other)


def test_a_mistake_may_match_by_its_own_rule():
    rounded = Mistake("rounded", "r", lambda x: 2 * x, matches=lambda want, got: round(got) == want)
    result = run(lambda x: 2 * x + 0.25, mistakes=[rounded])
    assert result.mistake == "rounded"


def test_the_picture_is_drawn_for_the_failing_case_only():
    drawn = []

    def picture(case, expected, given):
        drawn.append((case["x"], expected, given))
        return b"png"

    assert run(lambda x: 2 * x, picture=picture).picture is None
    result = run(lambda x: 3 * x, picture=picture)
    assert result.picture == b"png" and drawn == [(1.0, 2.0, 3.0)]


def test_in_a_notebook_the_report_shows_as_text_then_picture(monkeypatch):
    shown = []
    monkeypatch.setattr("IPython.display.display", lambda data, raw: shown.append(data))
    CheckResult("x", False, 1, "case 1 is wrong", picture=b"\x89PNG")._ipython_display_()
    assert shown == [{"text/plain": "FAIL x: case 1 is wrong"}, {"image/png": b"\x89PNG"}]
    shown.clear()
    CheckResult("x", True, 3, "all 3 cases pass")._ipython_display_()
    assert shown == [{"text/plain": "PASS x: all 3 cases pass"}]


def test_the_budget_stops_runaway_recursion_and_forbidden_calls_then_steps_aside():
    def forever(n):
        return 1 if n == 0 else forever(n - 1) + forever(n - 1)

    before = sys.getprofile()
    with pytest.raises(CallBudget, match="more than 100 Python function calls"):
        with call_budget(max_calls=100):
            forever(20)
    assert sys.getprofile() is before
    with pytest.raises(CallBudget, match="no sorted here"):
        with call_budget(forbidden={sorted: "no sorted here"}):
            sorted([2, 1])
    assert sys.getprofile() is before


def test_the_budget_reports_its_mistake_and_the_case():
    slow = Mistake("slow", "it recomputes", lambda x: None)

    def watch():
        return call_budget(max_calls=50, too_many=slow)

    def student(x):
        return 2 * x if x < 3 else sum(abs(i) for i in range(1000)) * 0 + 2 * x

    result = run(student, watch=watch)
    assert result.mistake == "slow"
    lines = str(result).splitlines()
    assert lines[:3] == [
        "FAIL double: case 3 was stopped: more than 50 Python function calls",
        "  inputs: x=3.0",
        "This is a known mistake, slow: it recomputes",
    ]


def test_pixel_sets_compare_in_any_order_without_repeats():
    assert same_pixels([[1, 2], [3, 4]], [[3, 4], [1, 2], [1, 2]])
    assert not same_pixels([[1, 2]], [[2, 1]])


def test_assert_passed_raises_the_whole_report_for_a_grader_and_returns_a_pass():
    failed = CheckResult("blur", False, 2, "case 2 is wrong\n  expected: 1, given: 2")
    with pytest.raises(AssertionError, match="FAIL blur: case 2 is wrong\n  expected: 1, given: 2"):
        failed.assert_passed()
    passed = CheckResult("blur", True, 3, "all 3 cases pass")
    assert passed.assert_passed() is passed
