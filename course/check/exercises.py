"""An exercise, declared once: its checker, its hints, the library answers it refuses.

An exercise is two things and nothing else: its solution cell in the lesson's notebook
(tagged ``solution``, ending with ``check.<name>(<function>)``) and its checker in the
lesson's chapter, declared with :func:`exercise`::

    @exercise(
        hints=LINE_HINTS,
        refuses=(raster.line, raster.line_4connected),
        handout_names=("DrawLine",),
    )
    def draw_line(student):
        return run_cases("draw_line", student, cases, line, compare, ...)

An exercise has one name: the function the student writes, its checker (``check.<name>``),
the name its reports open with (``FAIL <name>: ...``, the first argument of ``run_cases``) and
its hint key (``check.hint("<name>")``) are the same word, and nbgrader's grade ids are
``<name>`` and ``<name>_test``. The declaration therefore takes every name from the checker's
(``tests/test_exercise_names.py`` holds every exercise to it). A handout's own name for the
exercise (``"DrawLine"``) is one of ``handout_names``, which ``check.hint()`` answers to as
well.

Everything else is derived from the declaration: the hint table that ``check.hint(name)``
reads (:func:`~course.check.hints.register_hints`), the messages for a call to a refused
library answer (:func:`refused_messages`, which :func:`~course.check.base.run_cases` uses when
the checker passes no ``forbidden``), the list of the course's exercises
(:func:`course.classroom.exercise_list.course_exercises`), the answers nbgrader grades a later
exercise with (``grader_reference``), and the tests that hold a notebook and its chapter
together.

Course tooling over the course's own checkers: its inputs come from the chapters, never from
a student, so it checks only what a contributor can get wrong (``UNCHECKED = True``; the fuzz
test skips it).
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from course.check.hints import Hints, register_hints
from course.i18n import N_, _

__all__ = [
    "DEFAULT_REFUSAL",
    "Exercise",
    "declared",
    "declared_in",
    "exercise",
    "public_name",
    "refused_messages",
    "what_run_cases_takes",
]

UNCHECKED = True  # see the module docstring

#: What a student whose answer calls a refused library function is told.
DEFAULT_REFUSAL = N_(
    "your function calls {function}, the library's own answer: this exercise writes it"
)


@dataclass(frozen=True)
class Exercise:
    """An exercise as its checker declares it.

    ``name`` is the checker's (``check.<name>``), and the exercise's one name: the function the
    student writes, the name its reports open with (``FAIL <name>: ...``) and the hint key
    (``check.hint("<name>")``). ``handout_names`` are the handout's names for it, which
    ``check.hint()`` accepts too.
    ``refuses`` lists the library's own answers: a student's code that calls one is told to
    write it, with :data:`DEFAULT_REFUSAL`; or it is a function that maps them to their
    messages, made in the language of the moment (:func:`refused_messages`).
    ``grader_reference`` is the grader's own answer, for a later exercise that calls this one
    (nbgrader grades it with that answer, so that a mistake is charged once). ``draw(rng)``
    draws the cases a submission is graded on, from the families of the fixed ones
    (:mod:`course.check.grading`).
    """

    name: str
    checker: Callable[..., Any]
    hints: Hints
    refuses: tuple[Any, ...] | Callable[[], Mapping[Any, str]]
    handout_names: tuple[str, ...] = ()
    grader_reference: Callable[..., Any] | None = None
    draw: Callable[[Any], Sequence[Mapping[str, Any]]] | None = None

    @property
    def module(self) -> str:
        """The module the checker is in: its chapter's ``check``."""
        return self.checker.__module__


_DECLARED: dict[str, Exercise] = {}


def exercise(
    *,
    hints: Hints,
    refuses: Sequence[Any] | Callable[[], Mapping[Any, str]],
    handout_names: Sequence[str] = (),
    grader_reference: Callable[..., Any] | None = None,
    draw: Callable[[Any], Sequence[Mapping[str, Any]]] | None = None,
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Declare the decorated checker an exercise: its hints and the library answers it refuses.

    ``hints`` and ``refuses`` are required, so a declaration that leaves one out fails at
    import, naming it; the others default as :class:`Exercise` says. The exercise's name is
    the checker's: the student's function, the report and the hint key share it.

    Examples
    --------
    >>> @exercise(hints=Hints("look at x", "thrice x", "return 3 * x"), refuses=(abs,))
    ... def tripled_example(student):
    ...     return student(2) == 6
    >>> declared("tripled_example").refuses
    (<built-in function abs>,)
    >>> from course.check.hints import hint
    >>> hint("tripled_example")
    Hint for tripled_example: look at x thrice x
    """
    if not isinstance(hints, Hints):
        raise TypeError(
            _("hints must be a Hints; got {hints_type}").format(hints_type=type(hints).__name__)
        )
    if isinstance(refuses, (str, bytes)) or not (
        isinstance(refuses, Sequence) or callable(refuses)
    ):
        raise TypeError(
            _(
                "refuses must list the library's answers to the exercise (functions), or be a "
                "function mapping them to messages; got {refuses_type}"
            ).format(refuses_type=type(refuses).__name__)
        )
    if not callable(refuses) and not refuses:
        raise ValueError(
            _(
                "refuses must name at least one library answer: a checker that refuses none "
                "passes a student who calls the library"
            )
        )

    def declare(checker: Callable[..., Any]) -> Callable[..., Any]:
        name = checker.__name__
        blank = [
            step for step in ("where", "more", "recipe") if not str(getattr(hints, step)).strip()
        ]
        if blank:
            raise ValueError(
                _("{module}.{name}: hints: every step says something; {steps} is empty").format(
                    module=checker.__module__, name=name, steps=", ".join(blank)
                )
            )
        # One name: the function's, the report's and the hint key are the checker's.
        declaration = Exercise(
            name=name,
            checker=checker,
            hints=hints,
            refuses=refuses if callable(refuses) else tuple(refuses),
            handout_names=tuple(handout_names),
            grader_reference=grader_reference,
            draw=draw,
        )
        _DECLARED[name] = declaration
        register_hints(name, hints, *declaration.handout_names)
        checker.exercise = declaration  # type: ignore[attr-defined]
        return checker

    return declare


def declared(name: str) -> Exercise:
    """The exercise declared under ``name``, its one name (the checker's).

    A LookupError naming the declared ones if none.
    """
    found = _DECLARED.get(name)
    if found is None:
        known = ", ".join(sorted(_DECLARED)) or _("none yet")
        raise LookupError(
            _(
                "{name} is not a declared exercise (declared: {known}); declare its checker "
                "with @exercise(hints=..., refuses=...)"
            ).format(name=name, known=known)
        )
    return found


def declared_in(module: Any) -> list[Exercise]:
    """The exercises a chapter's ``check`` module declares, in the module's order."""
    return [
        value.exercise
        for value in vars(module).values()
        if callable(value) and isinstance(getattr(value, "exercise", None), Exercise)
        if value.exercise.module == module.__name__
    ]


def public_name(function: Any) -> str:
    """The shortest dotted name a student imports ``function`` by.

    A topic package re-exports its main module's functions, so
    ``course.poisson.editing.seamless_clone`` is shown as ``course.poisson.seamless_clone``.

    Examples
    --------
    >>> from course.poisson import seamless_clone
    >>> public_name(seamless_clone)
    'course.poisson.seamless_clone'
    """
    module, name = function.__module__, function.__name__
    parts = module.split(".")
    for end in range(1, len(parts)):
        package = sys.modules.get(".".join(parts[:end]))
        if package is not None and getattr(package, name, None) is function:
            return f"{package.__name__}.{name}"
    return f"{module}.{name}"


def refused_messages(declaration: Exercise) -> dict[Any, str]:
    """What a student whose code calls each refused library answer is told, in their language."""
    if callable(declaration.refuses):
        return dict(declaration.refuses())
    return {
        function: _(DEFAULT_REFUSAL).format(function=public_name(function))
        for function in declaration.refuses
    }


def what_run_cases_takes(
    name: str, hint: str | Hints | None, forbidden: Mapping[Any, str] | None
) -> tuple[str | Hints, Mapping[Any, str] | None]:
    """The hint and the refused answers a check of ``name`` runs with: the declaration's.

    A checker may still pass its own (a check that is not an exercise of a lesson); an
    exercise that passes neither and is not declared is a contributor's slip, named here.
    """
    if hint is not None and forbidden is not None:
        return hint, forbidden
    declaration = _DECLARED.get(name)
    if declaration is None:
        if hint is None:
            raise TypeError(
                _(
                    "{name}: no hints: declare its checker with @exercise(hints=..., "
                    "refuses=...) (course.check.exercises), or pass hint="
                ).format(name=name)
            )
        return hint, forbidden
    return (
        declaration.hints if hint is None else hint,
        refused_messages(declaration) if forbidden is None else forbidden,
    )
