"""Graded cases drawn like the fixed ones: each tells the checker's mistakes apart as its own does.

A checker's fixed cases are chosen so that each named mistake fails at a case where the
checker recognises it, and no earlier mistake in its list looks the same there. A graded
submission meets cases drawn from its seed instead (:mod:`course.check.grading`); where a
family of cases is an edge (a centre exactly on a triangle's edge, a tie between two
pixels), a drawn case keeps those properties only if the draw checks them.
:func:`drawn_like` draws a case until it *tells* the mistakes as the fixed case does
(:func:`telling`): for each mistake, whether an answer that makes it passes the case, and
which mistake the checker would name for it. A student who makes one mistake everywhere is
then stopped at the same case, and named the same, on the drawn cases as on the fixed ones.

Only the chapters' draws call these, with their own cases, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

from course.check.base import Mistake, copies_of
from course.check.views import quiet

__all__ = ["drawn_like", "telling"]

UNCHECKED = True  # see the module docstring

#: Candidates :func:`drawn_like` tries before it keeps the fixed case (a draw that keeps it
#: is a draw to fix: the tests time every draw).
TRIES = 2000


def _quiet(function: Callable[..., Any], *arguments: Any, **keywords: Any) -> Any:
    """``function``'s answer, or None if it raises; no warning shown (a mistake's answer
    may divide by zero), and none of the student's shown again (:func:`quiet`)."""
    try:
        with quiet():
            return function(*arguments, **keywords)
    except Exception:
        return None


class _Case:
    """One case's answers, the reference's and each mistake's, computed when first asked for."""

    def __init__(
        self,
        case: Mapping[str, Any],
        reference: Callable[..., Any],
        compare: Callable[[Any, Any], bool],
        mistakes: Sequence[Mistake],
        convert: Callable[[Any], Any],
    ) -> None:
        self.case, self.compare, self.mistakes, self.convert = case, compare, mistakes, convert
        self.expected = reference(**copies_of(case))
        self._answers: dict[int, Any] = {}

    def answer(self, index: int) -> Any:
        if index not in self._answers:
            self._answers[index] = _quiet(self.mistakes[index].answer, **copies_of(self.case))
        return self._answers[index]

    def told(self, index: int) -> tuple[bool, int | None] | None:
        """None if mistake ``index`` declines the case, else (passes, the mistake named)."""
        answer = self.answer(index)
        given = None if answer is None else _quiet(self.convert, answer)
        if given is None:
            return None
        passes = bool(_quiet(self.compare, self.expected, given))
        for named, mistake in enumerate(self.mistakes):
            theirs = self.answer(named)
            if theirs is not None and _quiet(mistake.matches or self.compare, theirs, given):
                return passes, named
        return passes, None


def telling(
    case: Mapping[str, Any],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    mistakes: Sequence[Mistake],
    convert: Callable[[Any], Any] = lambda value: value,
) -> tuple[tuple[bool, int | None] | None, ...]:
    """How ``case`` tells ``mistakes`` apart, as :func:`course.check.base.run_cases` does.

    For each mistake, None if its answer is None here (it declines the case), else whether
    its answer, read as the student's (``convert``), passes the case, and the index of the
    first mistake the checker would name for it.

    Examples
    --------
    >>> halved = Mistake("halved", "", lambda x: x / 2)
    >>> negated = Mistake("negated", "", lambda x: -x)
    >>> same = lambda a, b: a == b
    >>> telling({"x": 2.0}, lambda x: x, same, [halved, negated])
    ((False, 0), (False, 1))
    >>> telling({"x": 0.0}, lambda x: x, same, [halved, negated])
    ((True, 0), (True, 0))
    """
    answers = _Case(case, reference, compare, mistakes, convert)
    return tuple(answers.told(index) for index in range(len(mistakes)))


#: How the fixed cases tell the mistakes apart, computed once: by the reference's and the
#: mistakes' names and the case's repr.
_TOLD: dict[tuple[str, tuple[str, ...], str], tuple] = {}


def _told(
    case: Mapping[str, Any],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    mistakes: Sequence[Mistake],
    convert: Callable[[Any], Any],
) -> tuple:
    key = (
        f"{reference.__module__}.{reference.__qualname__}",
        tuple(str(mistake.name) for mistake in mistakes),
        repr(sorted(case.items())),
    )
    if key not in _TOLD:
        _TOLD[key] = telling(case, reference, compare, mistakes, convert)
    return _TOLD[key]


def drawn_like(
    fixed: Sequence[Mapping[str, Any]],
    candidates: Callable[[], list[dict[str, Any]]],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    mistakes: Sequence[Mistake],
    convert: Callable[[Any], Any] = lambda value: value,
) -> list[dict[str, Any]]:
    """The first cases ``candidates()`` draws (as many as ``fixed``, drawn together: a line and
    the same line reversed, say) that each tell ``mistakes`` apart as their fixed case does
    (:func:`telling`); the fixed cases themselves after :data:`TRIES` draws.

    Examples
    --------
    >>> import numpy as np
    >>> rng = np.random.default_rng(0)
    >>> halved = Mistake("halved", "", lambda x: x / 2)
    >>> same = lambda a, b: a == b
    >>> drawn_like([{"x": 4}, {"x": 0}], lambda: [{"x": int(rng.integers(-5, 6))} for _ in "ab"],
    ...            lambda x: x, same, [halved])
    [{'x': 1}, {'x': 0}]
    """
    wanted = [_told(case, reference, compare, mistakes, convert) for case in fixed]
    for _try in range(TRIES):
        cases = candidates()
        if all(
            telling(case, reference, compare, mistakes, convert) == told
            for case, told in zip(cases, wanted, strict=True)
        ):
            return cases
    return [dict(case) for case in fixed]


def drawn_in_order(
    fixed: Sequence[Mapping[str, Any]],
    families: Sequence[Callable[[], list[dict[str, Any]]]],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    mistakes: Sequence[Mistake],
    convert: Callable[[Any], Any] = lambda value: value,
) -> list[dict[str, Any]]:
    """Cases drawn by ``families`` (each draws the next one or more, in the order of
    ``fixed``) on which each mistake is caught, and named, as on ``fixed``.

    A mistake not yet caught must fail the drawn case where the fixed cases first fail it,
    and be named there as they name it; it may fail an earlier drawn case only if named the
    same there. Less strict than :func:`drawn_like`, which asks each case to tell every
    mistake apart exactly as its fixed case does, coincidences of the fixed numbers included.
    A family that draws nothing acceptable in :data:`TRIES` tries keeps its fixed cases.

    Examples
    --------
    >>> import numpy as np
    >>> rng = np.random.default_rng(0)
    >>> halved = Mistake("halved", "", lambda x: x / 2)
    >>> same = lambda a, b: a == b
    >>> at_zero = lambda: [{"x": 0}]
    >>> drawn_in_order([{"x": 0}, {"x": 4}], [at_zero, lambda: [{"x": int(rng.integers(-5, 6))}]],
    ...                lambda x: x, same, [halved])
    [{'x': 0}, {'x': 4}]
    """
    # Where the fixed cases first fail each mistake, and the mistake they name there.
    first: list[tuple[int, int | None] | None] = [None] * len(mistakes)
    for number, case in enumerate(fixed):
        for index, told in enumerate(_told(case, reference, compare, mistakes, convert)):
            if first[index] is None and told is not None and not told[0]:
                first[index] = (number, told[1])

    def caught_by(drawn: list[dict[str, Any]], start: int, caught: set[int]) -> set[int] | None:
        """The mistakes ``drawn`` catches as the fixed cases do, or None if it cannot."""
        caught = set(caught)
        for number, case in enumerate(drawn, start=start):
            if len(caught) == len(mistakes):
                break  # every mistake caught: the rest of the cases cannot change a name
            answers = _Case(case, reference, compare, mistakes, convert)
            for index in range(len(mistakes)):
                if index in caught:
                    continue
                told, wanted = answers.told(index), first[index]
                if told is None or told[0]:
                    if wanted is not None and wanted[0] == number:
                        return None  # the fixed cases catch it here: so must the drawn ones
                elif wanted is None or wanted[1] != told[1]:
                    return None  # caught here, but not named as the fixed cases name it
                else:
                    caught.add(index)
        return caught

    caught: set[int] = set()
    cases: list[dict[str, Any]] = []
    for family in families:
        start = len(cases)
        for _try in range(TRIES):
            drawn = family()
            now = caught_by(drawn, start, caught)
            if now is not None:
                break
        else:
            drawn = [dict(case) for case in fixed[start : start + len(drawn)]]
            now = caught | {
                i for i, told in enumerate(first) if told and told[0] < start + len(drawn)
            }
        caught = now
        cases += drawn
    return cases
