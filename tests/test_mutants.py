"""Every exercise's checker fails the single slips of its reference solution, but the listed ones.

tests/mutation.py makes every single-slip mutant of the reference solutions
(an operator, a comparison, an integer constant plus or minus one, ``and``/``or``,
a unary minus, a dropped line, an index off by one) and checks each in a process
of its own under a hard timeout. :data:`SURVIVORS` lists every mutant that
passes its checker, with the reason: "equivalent" (it computes the reference's
answer on every input the exercise allows), or "acceptable" (a tie between two
pixels equally near the line, which the checker accepts by design). A mutant
that is neither is a checker to fix, with a case that fails it, not an entry
here: the edge slips of ``bezier`` (``0 < x``, ``x <= width``, ``0 < y``,
``y <= height``, ``-1 <= y``) and the ``<=`` of ``jacobi_solve`` were listed
until the checkers got the cases that fail them.

A listed survivor that no longer survives, or a survivor that is not listed,
fails the test: the list stays exact. So does a mutant that hangs (the checker
did not stop it) or makes the checker raise.

All of them (``make mutants`` counts them) take about 15 minutes on two busy cores, too long for
``make test``:
there, a fixed sample of them (every :data:`SAMPLE_STEP`-th of each exercise)
and every listed survivor run. ``COURSE_MUTANTS=all`` (``make mutants`` runs
benchmarks/bench_mutants.py, the same with a table) runs them all.
"""

from __future__ import annotations

import os
import re

import mutation
import pytest

from course.classroom.exercise_list import course_exercises

ALL = os.environ.get("COURSE_MUTANTS", "") == "all"
SAMPLE_STEP = 12  # in make test, every 12th mutant of each exercise, beside the listed ones
# Under pytest-xdist (make test: two workers on two cores) one mutant at a time, not two.
WORKERS = 1 if os.environ.get("PYTEST_XDIST_WORKER") else mutation.WORKERS

#: (exercise, the slip as Mutant.diff writes it, why it passes): every mutant that passes.
SURVIVORS: list[tuple[str, str, str]] = [
    (
        "recursive_bezier",
        "line 4: return control_points[0]  ->  return control_points[-1]",
        "equivalent: the line runs only when one point is left, and then [0] and [-1] are that "
        "point",
    ),
    (
        "draw_line",
        "line 3: x < x1 else  ->  x <= x1 else",
        "equivalent: x == x1 only on a vertical line, where dx = 0 and x never steps, so sx is "
        "never read",
    ),
    (
        "draw_line",
        "line 3: y < y1 else  ->  y <= y1 else",
        "equivalent: y == y1 only on a horizontal line, where dy = 0 and y never steps",
    ),
    (
        "draw_line",
        "line 7: double > -dy:  ->  double >= -dy:",
        "acceptable: it differs only where 2 error == -dy, a tie between two pixels equally near "
        "the line ((0, 0) to (1, 2): (1, 1) instead of (0, 1)); the checker accepts either, as its"
        " docstring says",
    ),
    (
        "draw_line",
        "line 9: double < dx:  ->  double <= dx:",
        "acceptable: it differs only where 2 error == dx, a tie between two equally near pixels, "
        "which the checker accepts either way",
    ),
    (
        "supersample",
        "line 11: / rate ** 2  ->  / (-rate) ** 2",
        "equivalent: (-rate) ** 2 == rate ** 2",
    ),
    (
        "edge",
        "line 3: [(1, 1), (1,  ->  [(1, 2), (1,",
        "equivalent: an extra padded row at the bottom, which no 3 x 3 window (rows y to y + 2 of "
        "the padded image) reaches",
    ),
    (
        "edge",
        "line 3: (1, 1)] +  ->  (1, 2)] +",
        "equivalent: an extra padded column at the right, which no 3 x 3 window reaches",
    ),
    (
        "edge",
        "line 10: = np.sqrt(gx ** 2  ->  = np.sqrt((-gx) ** 2",
        "equivalent: (-gx) ** 2 == gx ** 2",
    ),
    (
        "edge",
        "line 10: + gy ** 2)  ->  + (-gy) ** 2)",
        "equivalent: (-gy) ** 2 == gy ** 2",
    ),
]

#: (exercise, the slip): mutants the checker does not stop, so the harness's timeout does. None
#: since the checkers run each case under a time and memory budget (course/check/sandbox.py):
#: on main before it, 42 slips of draw_line and 18 of jacobi_solve hung.
HANGS: list[tuple[str, str]] = []


@pytest.fixture(scope="module")
def exercises() -> list[mutation.Exercise]:
    return mutation.find_exercises()


@pytest.fixture(scope="module")
def work(exercises: list[mutation.Exercise]) -> list[tuple[mutation.Exercise, mutation.Mutant]]:
    return mutation.everything(exercises)


def test_every_exercise_of_the_lessons_is_found(exercises: list[mutation.Exercise]) -> None:
    import importlib

    declared = [e for chapter in course_exercises().values() for e in chapter]
    assert sorted(e.checker for e in exercises) == sorted(e.name for e in declared)
    for exercise in exercises:
        chapter = re.search(r"from (course\.lessons\.l\d\d_\w+) import check\b", exercise.setup)
        checker = getattr(importlib.import_module(f"{chapter.group(1)}.check"), exercise.checker)
        assert callable(checker)
        assert exercise.call == f"check.{exercise.checker}({exercise.function})"


def test_the_bezier_loop_is_mutated_only_between_its_markers(
    exercises: list[mutation.Exercise],
) -> None:
    (bezier,) = [e for e in exercises if e.checker == "bezier"]
    lines = bezier.source.splitlines()
    first, last = bezier.lines
    assert lines[first - 2].strip() == mutation.BEGIN
    assert lines[last].strip() == mutation.END
    for mutant in mutation.mutants(bezier):
        assert first <= mutant.line <= last
        assert "height, width = window.shape[:2]" in mutant.source


def test_each_mutant_is_one_distinct_slip(
    exercises: list[mutation.Exercise],
    work: list[tuple[mutation.Exercise, mutation.Mutant]],
) -> None:
    import ast

    originals = {e.checker: ast.unparse(ast.parse(e.source)) for e in exercises}
    sources = [(m.exercise, m.source) for _, m in work]
    assert len(set(sources)) == len(sources)
    for _, mutant in work:
        assert mutant.source != originals[mutant.exercise]
        compile(mutant.source, "<mutant>", "exec")
        changed = [
            (a, b)
            for a, b in zip(
                originals[mutant.exercise].splitlines(), mutant.source.splitlines(), strict=False
            )
            if a != b
        ]
        # One slip changes one line, or (a dropped compound statement) shortens the source.
        assert len(changed) == 1 or mutant.kind == "statement"
    kinds = {m.kind for _, m in work}
    assert kinds == {
        "operator",
        "comparison",
        "constant",
        "boolean",
        "unary",
        "statement",
        "off by one",
    }


def test_the_listed_survivors_and_hangs_are_mutants_of_today(
    work: list[tuple[mutation.Exercise, mutation.Mutant]],
) -> None:
    made = {(m.exercise, m.diff) for _, m in work}
    listed = [(exercise, diff) for exercise, diff, _ in SURVIVORS] + HANGS
    assert len(set(listed)) == len(listed)
    assert [entry for entry in listed if entry not in made] == []
    assert all(why.strip() for _, _, why in SURVIVORS)


def test_the_outcomes_are_classified_from_the_report() -> None:
    from course.check.base import CheckResult

    def outcome(passed: bool, message: str, mistake: str | None = None) -> str:
        return mutation.classify(CheckResult("f", passed, 1, message, mistake=mistake))[0]

    assert outcome(True, "all 3 cases pass") == "survived"
    assert outcome(False, "case 2 is wrong") == "failed"
    assert outcome(False, "case 2 is wrong", "the curve runs backwards") == "named"
    assert outcome(False, "case 1 was stopped: more than 10 calls") == "stopped"
    assert outcome(False, "case 1 did not stop within 5 s") == "stopped"
    assert outcome(False, "case 1 raised MemoryError: ") == "memory"
    assert mutation.classify(None)[0] == "crash"


def test_the_harness_stops_what_the_checker_does_not(exercises: list[mutation.Exercise]) -> None:
    import dataclasses

    (next_level,) = [e for e in exercises if e.checker == "next_level"]
    # Called directly, not through the checker: the harness's own limits are under test.
    direct = dataclasses.replace(next_level, call="next_level(None, None)")

    def variant(body: str) -> mutation.Mutant:
        source = f"def next_level(control_points, t):\n{body}"
        return mutation.Mutant("next_level", "test", 2, "", "", source)

    loops = variant("    while True:\n        pass\n")
    grows = variant("    hoard = []\n    while True:\n        hoard.append(bytearray(2**24))\n")
    raises = variant("    raise RuntimeError('the check itself broke')\n")
    # Only the endless loop meets the short timeout; the others finish long before theirs.
    (hang,) = mutation.run([(direct, loops)], timeout=2.0)
    outcomes = mutation.run(
        [(direct, grows), (direct, raises), (direct, variant("    return 0\n"))], memory=2**28
    )
    assert [o.outcome for o in [hang, *outcomes]] == ["hang", "memory", "crash", "crash"]
    assert "the check itself broke" in outcomes[1].detail
    assert "not a CheckResult" in outcomes[2].detail


def _chosen(
    work: list[tuple[mutation.Exercise, mutation.Mutant]],
) -> list[tuple[mutation.Exercise, mutation.Mutant]]:
    if ALL:
        return work
    # Not every listed hang: each costs the whole timeout.
    listed = {(e, d) for e, d, _ in SURVIVORS}
    chosen, seen = [], {}
    for exercise, mutant in work:
        position = seen.get(mutant.exercise, 0)
        seen[mutant.exercise] = position + 1
        if position % SAMPLE_STEP == 0 or (mutant.exercise, mutant.diff) in listed:
            chosen.append((exercise, mutant))
    return chosen


# Run in each listed survivor's process when the checker's own time budget stopped it, as a
# busy machine can: the budget, twenty times longer, shows whether it passes given the time.
PATIENT = """
try:
    from course.check import sandbox
except ImportError:
    pass
else:
    sandbox.TIME_BUDGET *= 20
"""


def test_only_the_listed_mutants_survive_and_none_hangs(
    work: list[tuple[mutation.Exercise, mutation.Mutant]],
) -> None:
    chosen = _chosen(work)
    # A timeout well beyond any checker's own budget: only a mutant nothing stops meets it.
    outcomes = mutation.run(chosen, timeout=3 * mutation.TIMEOUT, workers=WORKERS)
    listed = {(e, d) for e, d, _ in SURVIVORS}
    slow = [
        index
        for index, outcome in enumerate(outcomes)
        if outcome.outcome == "stopped" and (outcome.mutant.exercise, outcome.mutant.diff) in listed
    ]
    if slow:
        slowly = [chosen[i] for i in slow]
        again = mutation.run(slowly, 30 * mutation.TIMEOUT, WORKERS, prelude=PATIENT)
        for index, outcome in zip(slow, again, strict=True):
            outcomes[index] = outcome
    by_outcome: dict[str, set[tuple[str, str]]] = {}
    for outcome in outcomes:
        key = (outcome.mutant.exercise, outcome.mutant.diff)
        by_outcome.setdefault(outcome.outcome, set()).add(key)
    ran = {(m.exercise, m.diff) for _, m in chosen}
    listed &= ran
    survived = by_outcome.get("survived", set())
    assert sorted(survived - listed) == [], "mutants that pass their checker, not listed"
    assert sorted(listed - survived) == [], "listed survivors that now fail: remove them"
    hangs = by_outcome.get("hang", set()) | by_outcome.get("memory", set())
    assert sorted(hangs ^ (set(HANGS) & ran)) == [], "hangs differ from the listed ones"
    crashes = [
        (o.mutant.exercise, o.mutant.diff, o.detail) for o in outcomes if o.outcome == "crash"
    ]
    assert crashes == []
