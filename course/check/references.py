"""Answers that call what the exercise forbids: the library's own reference, or ``math.comb``.

:func:`call_budget` watches the student's code as it runs (a profile hook sees
every call, however it was imported), and :func:`named_reference` reads the
code before it runs, for a call made from C (``map(math.comb, ...)``) that
the hook cannot see.
"""

from __future__ import annotations

import builtins
import dis
import os
import sys
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any

from course.i18n import _

__all__ = ["CallBudget", "call_budget", "call_limits", "forbidden_message", "known_mistake"]

# Held from import: a cell that rebinds sys.setprofile does not keep the watch from starting.
_getprofile, _setprofile = sys.getprofile, sys.setprofile
# The checker's own files, whose calls of sys.setprofile (starting and ending a watch) are its.
_OWN_FILES = frozenset(
    os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    for name in ("references.py", "budget.py")
)


class CallBudget(Exception):
    """Raised inside the student's code when it calls what the exercise forbids, or too often.

    ``mistake`` names the known mistake this stands for, if any.
    """

    def __init__(self, message: str, mistake: str | None = None) -> None:
        super().__init__(message)
        self.mistake = mistake


@contextmanager
def call_budget(
    max_calls: int | None = None,
    forbidden: Mapping[Any, str] | None = None,
    too_many: Any = None,
) -> Iterator[None]:
    """Stop the student's code after ``max_calls`` Python calls, or at a forbidden call.

    Every Python function call counts (the student's own, their helpers',
    a comprehension's), so a recursion that recomputes the same values is
    stopped however it is written. ``forbidden`` maps functions
    (``math.comb``, a library function) to the message the report gives when
    one is called. A profile hook sees every call of a Python function, and
    every call of a C function made from Python, however the student
    imported them. With ``too_many``, running out of calls is reported as
    that known mistake.

    A budget entered inside another keeps the outer one watching too. The
    student's code may not switch the watch off: its call of ``sys.setprofile``
    is refused, and a watch found switched off when the code returns fails the
    case, so a forbidden call cannot hide behind ``sys.setprofile(None)``.
    """
    forbidden = dict(forbidden or {})
    forbidden_codes = {getattr(f, "__code__", None): text for f, text in forbidden.items()}
    forbidden_codes.pop(None, None)
    calls = 0
    previous = _getprofile()
    outer = previous if getattr(previous, "course_call_budget", False) else None

    def watch(frame: Any, event: str, argument: Any) -> None:
        nonlocal calls
        if outer is not None:
            outer(frame, event, argument)
        if event == "c_call":
            if argument is _setprofile and frame.f_code.co_filename not in _OWN_FILES:
                raise CallBudget(_switched_off())
            for function, text in forbidden.items():
                if argument is function:
                    raise CallBudget(text)
        elif event == "call":
            if frame.f_code in forbidden_codes:
                raise CallBudget(forbidden_codes[frame.f_code])
            calls += 1
            if max_calls is not None and calls > max_calls:
                message = _("more than {count:,} Python function calls").format(count=max_calls)
                if too_many is None:
                    raise CallBudget(message)
                raise CallBudget(f"{message}\n{known_mistake(too_many)}", too_many.name)

    watch.course_call_budget = True  # type: ignore[attr-defined]
    _setprofile(watch)
    limits = _LIMITS.set((max_calls, too_many))
    try:
        yield
        if _getprofile() is not watch:
            raise CallBudget(_switched_off())
    finally:
        _LIMITS.reset(limits)
        _setprofile(previous)


def _switched_off() -> str:
    return _(
        "your code switched off the checker's watch (sys.setprofile): leave it on, and write "
        "the exercise's answer yourself"
    )


# The innermost call_budget's (max_calls, too_many): a student's code run in another process
# (course.check.outside) is held to it there.
_LIMITS: ContextVar[tuple[int | None, Any]] = ContextVar("course_call_budget", default=(None, None))


def call_limits() -> tuple[int | None, Any]:
    """The innermost :func:`call_budget`'s ``max_calls`` and ``too_many``; (None, None) outside."""
    return _LIMITS.get()


def known_mistake(mistake: Any) -> str:
    """The report's line naming a known mistake (a :class:`~course.check.base.Mistake`).

    Examples
    --------
    >>> from course.check.base import Mistake
    >>> known_mistake(Mistake("drawn backwards", "your pixels run from p1 to p0.", abs))
    'This is a known mistake, drawn backwards: your pixels run from p1 to p0.'
    """
    name, explanation = getattr(mistake, "name", None), getattr(mistake, "explanation", None)
    if not isinstance(name, str) or not isinstance(explanation, str):
        raise TypeError(
            _("mistake must be a Mistake; got {mistake_type}").format(
                mistake_type=type(mistake).__name__
            )
        )
    return _("This is a known mistake, {name}: {explanation}").format(
        name=_(name), explanation=_(explanation)
    )


def forbidden_message(function: Any, forbidden: Mapping[Any, str]) -> str | None:
    """The message of ``forbidden`` for ``function``, if it is one or its code names one.

    Examples
    --------
    >>> import math
    >>> forbidden_message(lambda m, n: math.comb(m, n), {math.comb: "write comb"})
    'write comb'
    """
    if not isinstance(forbidden, Mapping):
        raise TypeError(
            _("forbidden must be a mapping; got {forbidden_type}").format(
                forbidden_type=type(forbidden).__name__
            )
        )
    named = forbidden.get(function) if _hashable(function) else None
    return named or _references(function, forbidden)


def _references(function: Any, forbidden: Mapping[Any, str], depth: int = 3) -> str | None:
    """The message of a forbidden callable that ``function``'s code names, or None.

    Reads the globals and attributes the code loads (``math.comb`` in
    ``map(math.comb, ...)``, a ``from scipy.special import comb``), in the
    function, its nested functions and the functions of its own module it
    calls: a call made from C (through ``map``) is invisible to the profile
    hook.
    """
    seen: set[int] = set()
    targets = {id(f): text for f, text in forbidden.items()}

    def loaded(candidate: Any) -> list[Any]:
        space = getattr(candidate, "__globals__", {})
        cells = getattr(candidate, "__closure__", None) or ()
        free = dict(zip(candidate.__code__.co_freevars, cells, strict=False))
        values, codes = [], [candidate.__code__]
        while codes:
            code = codes.pop()
            codes.extend(c for c in code.co_consts if hasattr(c, "co_code"))
            current: Any = None
            for instruction in dis.get_instructions(code):
                name = instruction.argval
                if instruction.opname in ("LOAD_GLOBAL", "LOAD_NAME"):
                    current = space.get(name, getattr(builtins, str(name), None))
                elif instruction.opname == "LOAD_DEREF" and name in free and _full(free[name]):
                    current = free[name].cell_contents
                elif instruction.opname in ("LOAD_ATTR", "LOAD_METHOD") and current is not None:
                    current = getattr(current, str(name), None) if _module_like(current) else None
                else:
                    current = None
                    continue
                if current is not None:
                    values.append(current)
        return values

    def visit(candidate: Any, level: int) -> str | None:
        code = getattr(candidate, "__code__", None)
        if code is None or id(code) in seen or level < 0:
            return None
        seen.add(id(code))
        values = loaded(candidate)
        for value in values:
            if id(value) in targets:
                return targets[id(value)]
        module = getattr(candidate, "__module__", None)
        for value in values:
            if getattr(value, "__module__", 0) == module and hasattr(value, "__code__"):
                text = visit(value, level - 1)
                if text is not None:
                    return text
        return None

    try:
        return visit(function, depth)
    except Exception:  # an unusual callable: the profile hook still watches it
        return None


def _module_like(value: Any) -> bool:
    return isinstance(value, (type(sys), type))


def _full(cell: Any) -> bool:
    try:
        cell.cell_contents  # noqa: B018
    except ValueError:
        return False
    return True


def _hashable(value: Any) -> bool:
    try:
        hash(value)
    except TypeError:
        return False
    return True
