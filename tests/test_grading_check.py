"""course.check.grading: graded cases are drawn per submission, and reports keep the answer."""

from __future__ import annotations

import numpy as np

from course.check.base import close, run_cases
from course.check.exercises import declared
from course.check.grading import drawn_cases, grading, grading_seed, submission_seed
from course.classroom.exercise_list import course_exercises

course_exercises()  # every chapter's exercises declared


def test_a_submission_s_seed_is_its_own_and_stable():
    seeds = {submission_seed(s, a) for s in ("alice", "bob") for a in ("01", "02")}
    assert len(seeds) == 4
    assert submission_seed("alice", "01") == submission_seed("alice", "01")


def test_outside_grading_the_fixed_cases_run_and_inside_the_drawn_ones():
    fixed = [{"control_points": np.zeros((2, 2)), "t": 0.5}]
    assert grading_seed() is None and drawn_cases("next_level", fixed) is fixed
    with grading(7):
        first = drawn_cases("next_level", fixed)
        again = drawn_cases("next_level", fixed)
    with grading(8):
        other = drawn_cases("next_level", fixed)
    if declared("next_level").draw is None:  # no draw declared: the fixed cases
        assert first is fixed
        return
    assert [list(case) for case in first] == [list(case) for case in again]
    assert all(
        np.array_equal(a["control_points"], b["control_points"])
        for a, b in zip(first, again, strict=True)
    )
    assert any(
        not np.array_equal(a["control_points"], b["control_points"])
        for a, b in zip(first, other, strict=True)
    )


def test_a_graded_failure_shows_the_inputs_and_the_answer_given_not_the_expected_one():
    def wrong(x):
        return x + 1

    shown = run_cases("twice_example", wrong, [{"x": 3.0}], lambda x: 2 * x, close(), hint="h")
    assert "expected: 6" in shown.message
    with grading(1):
        graded = run_cases("twice_example", wrong, [{"x": 3.0}], lambda x: 2 * x, close(), hint="h")
    assert "expected" not in graded.message and "given:" in graded.message
    assert "x=3" in graded.message
