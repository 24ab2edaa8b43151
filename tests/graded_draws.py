"""Graded cases drawn per submission: what the chapters' tests ask of every exercise's ``draw``.

Graded, a checker runs inside :func:`course.check.grading.grading` on the cases its
exercise's ``draw(rng)`` draws from the submission's seed, not on the fixed ones a student
meets in the notebook (:func:`course.check.exercises.exercise`). A chapter's test holds each
of its exercises to these, for :data:`SEEDS`:

- :func:`check_drawn_cases`: the drawn cases have the fixed cases' keys, in their order, and
  their number; one seed draws the same cases every time, two seeds different ones; a draw
  is cheap;
- :func:`check_graded`: inside ``grading(seed)`` the notebook's reference solution passes,
  a stub fails, and every named mistake of the checker is named as it is on the fixed
  cases. A mistake is made by a function that answers every case as the mistake does
  (:func:`stand_in`), or, where that cannot stand for a student (a mistake recognised by
  its own rule, or by what the student's function does elsewhere), by the chapter's own
  written student.
"""

from __future__ import annotations

import importlib
import os
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from typing import Any
from unittest import mock

import mutation
import numpy as np
from mistakes import WRITTEN, unwatched

from course.check import base
from course.check.base import CheckResult, Mistake
from course.check.exercises import Exercise
from course.check.grading import drawn_cases, grading, grading_seed
from course.classroom.exercise_list import course_exercises

#: The seeds each exercise's drawn cases are checked on: eight in ``make test`` (each seed
#: runs every named mistake of every checker, minutes for the triangle's seventeen), more with
#: ``COURSE_GRADED_SEEDS=200`` before a term.
SEEDS = range(int(os.environ.get("COURSE_GRADED_SEEDS", "8")))


def declared(name: str) -> Exercise:
    """The declared exercise whose checker is ``check.<name>``, its chapter imported."""
    (found,) = [e for chapter in course_exercises().values() for e in chapter if e.name == name]
    return found


def recorded(declaration: Exercise) -> dict[str, Any]:
    """What the checker hands to ``run_cases``: the exercise's name, fixed cases and mistakes."""
    checks = importlib.import_module(declaration.module)
    found: dict[str, Any] = {}

    def record(exercise: str, student: Any, cases: Any, *args: Any, **kwargs: Any) -> Any:
        found.update(exercise=exercise, cases=list(cases), mistakes=list(kwargs["mistakes"]))
        return CheckResult(exercise, True, 0, "recorded")

    with mock.patch.object(checks, "run_cases", record):
        declaration.checker(lambda *args: None)
    return found


def draw(declaration: Exercise, seed: int) -> list[dict[str, Any]]:
    """The cases the checker runs when graded with ``seed``."""
    found = recorded(declaration)
    with grading(seed):
        return list(drawn_cases(found["exercise"], found["cases"]))


def canonical(value: Any) -> Any:
    """A case, or a list of them, as plain comparable values (arrays as nested lists)."""
    if isinstance(value, Mapping):
        return tuple((key, canonical(item)) for key, item in value.items())
    if isinstance(value, np.ndarray):
        return ("array", value.shape, str(value.dtype), value.tobytes())
    if isinstance(value, (list, tuple)):
        return tuple(canonical(item) for item in value)
    if isinstance(value, np.generic):
        return value.item()
    return value


def check_drawn_cases(name: str, seeds: range = SEEDS) -> list[list[dict[str, Any]]]:
    """Assert what every draw must be (see the module docstring); the drawn cases, by seed."""
    declaration = declared(name)
    assert declaration.draw is not None, f"{name}: declare its draw= (@exercise(..., draw=...))"
    found = recorded(declaration)
    fixed = found["cases"]
    declaration.draw(np.random.default_rng(0))  # a first call may fill a cache (the face)
    drawn = []
    for seed in seeds:
        with grading(seed):
            cases = list(drawn_cases(found["exercise"], fixed))
        assert len(cases) == len(fixed), f"{name}: {len(cases)} cases drawn, {len(fixed)} fixed"
        for number, (case, like) in enumerate(zip(cases, fixed, strict=True), start=1):
            assert list(case) == list(like), f"{name}: case {number} has keys {list(case)}"
        assert canonical(cases) == canonical(draw(declaration, seed)), f"{name}: seed {seed}"
        drawn.append(cases)
    different = {canonical(cases) for cases in drawn}
    assert len(different) == len(drawn), f"{name}: two seeds drew the same cases"
    assert canonical(fixed) not in different, f"{name}: a seed drew the fixed cases"
    return drawn


def reference_solution(name: str) -> Callable[..., Any]:
    """The notebook's solution of the exercise checked by ``check.<name>``."""
    (exercise,) = [e for e in mutation.find_exercises() if e.checker == name]
    namespace: dict[str, Any] = {"__name__": "__reference__"}
    exec(compile(exercise.setup, "<setup>", "exec"), namespace)
    exec(compile(exercise.source, "<reference>", "exec"), namespace)
    return namespace[exercise.function]


def stub(*arguments: Any) -> Any:
    """The student edition's stub: not written yet."""
    raise NotImplementedError


def stand_in(name: str, mistake: Mistake, keys: list[str]) -> Callable[..., Any]:
    """A function that answers each case as ``mistake`` of ``check.<name>`` does.

    A drawing loop paints the mistake's pixels green into its window; a splat answers the
    table's pixels and weights.
    """
    written = WRITTEN.get((name, mistake.name))  # module:function, the student's own code
    if written is not None:
        module, function = written.split(":")
        code = getattr(importlib.import_module(f"course.lessons.{module}"), function)
        mistake = Mistake(mistake.name, mistake.explanation, code)

    def answering(*arguments: Any) -> Any:
        # Through the mistake, not a name of its own: a checker refuses a student's function
        # that names the library's answer (course.sampling.supersample_without_offset, say).
        return unwatched(mistake.answer, **dict(zip(keys, arguments, strict=True)))

    if "window" in keys:

        def paint(control_points: Any, window: Any) -> None:
            pixels = np.asarray(answering(control_points, window), dtype=int)
            for x, y in pixels.reshape(-1, 2):
                window[y, x] = (0, 1, 0)

        return paint
    if name == "splat":

        def splat(x: float, y: float) -> tuple[Any, Any]:
            table = np.asarray(answering(x, y))
            return table[:, :2], table[:, 2]

        return splat
    return answering


def graded(name: str, student: Callable[..., Any], seed: int) -> CheckResult:
    """The checker's verdict on ``student`` when graded with ``seed``."""
    with grading(seed):
        return declared(name).checker(student)


def students(
    name: str, written: Mapping[int, Callable[[], Callable[..., Any]]] | None = None
) -> list[tuple[str, Callable[[], Callable[..., Any]]]]:
    """(mistake's name, a maker of a student who makes it) for each of the checker's named
    mistakes, in its order. ``written`` gives the chapter's own maker for a mistake (by its
    index) that :func:`stand_in` cannot stand for; a maker is called before each check, so a
    student may keep state from call to call (an accumulator never reset)."""
    found = recorded(declared(name))
    keys = list(found["cases"][0])
    written = written or {}
    return [
        (mistake.name, written.get(index) or (lambda m=mistake: stand_in(name, m, keys)))
        for index, mistake in enumerate(found["mistakes"])
    ]


@contextmanager
def drawn_once() -> Iterator[None]:
    """Inside, the checkers draw a seed's cases once and share them at every check after.

    A draw depends on the exercise and the seed alone (:func:`check_drawn_cases` asserts
    it), and drawing is most of a graded check's time: the triangle's draw runs every named
    mistake on its candidates, 0.9 s, against 0.04 s for the check itself. The shared
    cases' arrays are read-only, so a checker that wrote into one would fail loudly (a
    copy at each check cost more than the bezier's draw: five 700 x 700 windows). Only the
    last draw is kept.
    """
    last: dict[tuple[str, int], list[Any]] = {}
    draw = base.drawn_cases

    def drawn(exercise: str, fixed: list[Any]) -> list[Any]:
        key = (exercise, grading_seed())
        if key[1] is None:
            return draw(exercise, fixed)
        if key not in last:
            last.clear()
            last[key] = [_read_only(case) for case in draw(exercise, fixed)]
        return [dict(case) for case in last[key]]

    with mock.patch.object(base, "drawn_cases", drawn):
        yield


def _read_only(value: Any) -> Any:
    """``value`` with every array in it made read-only (in place: a fresh draw's)."""
    if isinstance(value, np.ndarray):
        value.flags.writeable = False
    elif isinstance(value, Mapping):
        for item in value.values():
            _read_only(item)
    elif isinstance(value, (list, tuple)):
        for item in value:
            _read_only(item)
    return value


def check_graded(
    name: str,
    written: Mapping[int, Callable[[], Callable[..., Any]]] | None = None,
    named_otherwise: Mapping[str, str] | None = None,
    seeds: range = SEEDS,
) -> dict[str, int]:
    """Assert that, graded with each seed, the reference passes, a stub fails and every named
    mistake is named as on the fixed cases: its own name, or ``named_otherwise[name]`` where
    the fixed cases cannot tell it from a neighbour either. Returns the count of graded runs
    that named each mistake."""
    reference = reference_solution(name)
    named_otherwise = named_otherwise or {}
    made = students(name, written)
    expected = []
    for index, (mistake, make) in enumerate(made):
        fixed = declared(name).checker(make())
        want = named_otherwise.get(mistake, mistake)
        assert fixed.mistake == want, (
            f"{name}: mistake {index} ({mistake!r}) is named {fixed.mistake!r} on the fixed cases, "
            f"not {want!r}:\n{fixed}"
        )
        expected.append(want)
    counts = dict.fromkeys((mistake for mistake, _student in made), 0)
    failures = []
    with drawn_once():
        for seed in seeds:
            result = graded(name, reference, seed)
            assert result.passed, f"{name}: the reference fails seed {seed}:\n{result}"
            assert not graded(name, stub, seed).passed, f"{name}: the stub passes seed {seed}"
            for (mistake, make), want in zip(made, expected, strict=True):
                result = graded(name, make(), seed)
                if result.mistake == want:
                    counts[mistake] += 1
                else:
                    failures.append(
                        f"seed {seed}: {mistake!r} is named {result.mistake!r}:\n{result}"
                    )
    assert not failures, f"{name}: " + "\n".join(failures[:5])
    return counts
