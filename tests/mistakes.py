"""The checkers' named mistakes, as functions a submission can define: for the grading tests.

A checker builds its list of :class:`~course.check.base.Mistake` and hands
it to ``run_cases``; :func:`named_mistakes` records that list by calling the
checker with ``run_cases`` replaced. :func:`mistaken` then makes a function
that answers every case as the mistake does: what a student who made the
mistake would submit. The grading kernel imports this module (the tests put
``tests/`` on its ``PYTHONPATH``).
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any
from unittest import mock

import numpy as np

from course.check.base import CheckResult, Mistake


def named_mistakes(module: str, checker: str) -> tuple[list[Mistake], list[str]]:
    """The mistakes ``module.checker`` knows, and the parameter names of its cases."""
    checks = importlib.import_module(module)
    recorded: dict[str, Any] = {}

    def record(exercise: str, student: Any, cases: Any, *args: Any, **kwargs: Any) -> Any:
        recorded["mistakes"] = list(kwargs.get("mistakes", ()))
        recorded["keys"] = list(next(iter(cases)))
        return CheckResult(exercise, True, 0, "recorded")

    with mock.patch.object(checks, "run_cases", record):
        getattr(checks, checker)(lambda *args: None)
    return recorded["mistakes"], recorded["keys"]


#: The code a student with the mistake writes, where the mistake's own answer declines a case
#: that cannot tell it from a neighbour (``unless_same``): (checker, mistake) -> module:function.
WRITTEN = {
    ("draw_triangle_filled", "the rule mirrored"): "l03_lines_and_triangles.mistakes:mirrored_rule",
    ("draw_triangle_filled", "every edge open"): "l03_lines_and_triangles.mistakes:open_rule",
}


def _written(where: str) -> Callable[..., Any]:
    module, function = where.split(":")
    return getattr(importlib.import_module(f"course.lessons.{module}"), function)


def unwatched(function: Callable[..., Any], /, *args: Any, **kwargs: Any) -> Any:
    """``function(*args, **kwargs)`` in a thread of its own, out of the checker's sight.

    A mistake's answer is the library's reproduction of it, which calls the library's own
    answer (``course.raster.line``); a checker watches its thread's calls
    (``sys.setprofile``) and stops a student's code at that call, as it should. A student
    writes the mistake by hand; this stands for them, so the checker sees only the answer.
    """
    with ThreadPoolExecutor(max_workers=1) as pool:
        return pool.submit(function, *args, **kwargs).result()


def mistaken(module: str, checker: str, name: str, parameters: list[str]) -> Callable[..., Any]:
    """A function with the exercise's ``parameters`` that makes the mistake ``name``.

    The drawing loop of lesson 01 paints into ``window`` rather than
    returning pixels: there the function paints the mistake's pixels green;
    a splat (lesson 05) answers pixels and weights, the mistake its table.
    """
    mistakes, keys = named_mistakes(module, checker)
    mistake = next(m for m in mistakes if m.name == name)
    written = WRITTEN.get((checker, name))
    if written is not None:  # the mistake's answer is None where it looks like another's
        mistake = Mistake(mistake.name, mistake.explanation, _written(written))
    if "window" in parameters and "shape" in keys:

        def paint(*args: Any, **kwargs: Any) -> None:
            given = {**dict(zip(parameters, args, strict=False)), **kwargs}
            window = given.pop("window")
            pixels = np.asarray(
                unwatched(mistake.answer, **given, shape=window.shape[:2]), dtype=int
            )
            for x, y in pixels.reshape(-1, 2):
                window[y, x] = (0, 1, 0)

        return paint

    def answer(*args: Any, **kwargs: Any) -> Any:
        return unwatched(mistake.answer, **dict(zip(keys, args, strict=False)), **kwargs)

    if checker == "splat":  # a splat answers (pixels, weights); the mistake, its table

        def splat(*args: Any, **kwargs: Any) -> tuple[Any, Any]:
            table = np.asarray(answer(*args, **kwargs))
            return table[:, :2], table[:, 2]

        return splat

    return answer
