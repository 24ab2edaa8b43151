"""Grading mode: cases drawn for each submission, and reports that give no answer away.

A student meets an exercise's fixed cases in the notebook, and a failure's report shows the
expected answer beside theirs. Graded, the checker runs inside :func:`grading`: its cases
are drawn by the exercise's declared ``draw(rng)`` (:func:`course.check.exercises.exercise`),
from a seed of the submission (:func:`submission_seed`: the student, the assignment and the
teacher's secret), so a table of answers memorised from the notebook's reports, or drawn
in the student's kernel, is no use; and a failure's report
keeps the case's inputs, the diagnosis and the named mistake, not the expected values.

Unchecked: the grader, not a student, calls these (``UNCHECKED = True``).
"""

from __future__ import annotations

import hashlib
import zlib
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any

import numpy as np

__all__ = ["drawn_cases", "grading", "grading_seed", "submission_seed"]

UNCHECKED = True  # see the module docstring

_SEED: ContextVar[int | None] = ContextVar("course_grading_seed", default=None)


def submission_seed(student: str, assignment: str, secret: str = "") -> int:
    """The seed of one student's submission of one assignment: the same every time it is
    graded. ``secret`` is the teacher's (``nbgrader_config.py``): without it, a student who
    knows the names could draw their own graded cases.

    Examples
    --------
    >>> submission_seed("alice", "01_de_casteljau") == submission_seed("alice", "01_de_casteljau")
    True
    >>> submission_seed("alice", "01_de_casteljau") == submission_seed("bob", "01_de_casteljau")
    False
    >>> submission_seed("alice", "01", "x") == submission_seed("alice", "01", "y")
    False
    """
    digest = hashlib.sha256(f"{student}\0{assignment}\0{secret}".encode()).digest()
    return int.from_bytes(digest[:8], "little")


@contextmanager
def grading(seed: int) -> Iterator[None]:
    """Within the block, checkers draw their cases from ``seed`` and hide expected values."""
    token = _SEED.set(int(seed))
    try:
        yield
    finally:
        _SEED.reset(token)


def grading_seed() -> int | None:
    """The seed of the submission being graded, or None outside :func:`grading`."""
    return _SEED.get()


def drawn_cases(exercise: str, fixed: list[Mapping[str, Any]]) -> list[Mapping[str, Any]]:
    """The cases of ``exercise`` to run: drawn from the grading seed by its declared ``draw``,
    or ``fixed`` outside grading (or for an exercise that declares no ``draw``).

    Examples
    --------
    >>> drawn_cases("no such exercise", [{"x": 1}])
    [{'x': 1}]
    """
    seed = _SEED.get()
    if seed is None:
        return fixed
    from course.check.exercises import declared

    try:
        draw = declared(exercise).draw
    except LookupError:
        return fixed
    if draw is None:
        return fixed
    rng = np.random.default_rng([seed, zlib.crc32(exercise.encode())])
    return list(draw(rng))
