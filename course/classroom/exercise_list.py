"""The course's exercises, found in the chapters' declarations: nothing lists them by hand.

A chapter's exercises are the checkers its ``check`` module declares with
:func:`course.check.exercises.exercise`; the mutation tests, the counts and the teacher's tools
take the list from :func:`course_exercises`. Reads the course's own chapters, never a
student's input, and checks none (``UNCHECKED = True``).
"""

from __future__ import annotations

import importlib

from course.check.exercises import Exercise, declared_in
from course.classroom.registry import lesson_modules

__all__ = ["course_exercises"]

UNCHECKED = True  # see the module docstring


def course_exercises() -> dict[str, list[Exercise]]:
    """Every chapter's declared exercises, by lesson number, in lesson order.

    A lesson without a ``check`` module has none.

    Examples
    --------
    >>> [e.name for e in course_exercises()["01"]][:2]
    ['recursive_bezier', 'next_level']
    """
    found = {}
    for number, entry in lesson_modules().items():
        chapter = entry.rsplit(".", 1)[0]
        try:
            module = importlib.import_module(f"{chapter}.check")
        except ModuleNotFoundError as error:
            if error.name != f"{chapter}.check":
                raise
            continue
        found[number] = declared_in(module)
    return found
