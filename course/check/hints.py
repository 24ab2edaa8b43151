"""An exercise's hints, in steps: where to look, then the idea, then the recipe.

A checker registers its exercise's :class:`Hints` with :func:`register_hints`;
its report shows the next step of them after each failure
(:func:`failure_hint`), and a student asks for more with :func:`hint`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from course.i18n import _

__all__ = ["Hint", "Hints", "failure_hint", "hint", "joined", "register_hints"]

# A plain lowercase word opening a sentence (the article "a" included): not a variable (one
# letter, or followed by "=", "(", "[", "." or "_"), which keeps its case.
_PLAIN_WORD = re.compile(r"(?:[a-z]{2,}|a(?=\s+[a-z]{2,}))(?![\w(\[.]|\s*=)")


@dataclass(frozen=True)
class Hints:
    """An exercise's hints, in steps: where to look, then the idea, then the recipe.

    Each text is marked with :func:`~course.i18n.N_` where it is written, and
    translated where it is shown.

    ``where`` comes with the first failure; ``more`` is added from the
    second failure on, and by :func:`hint`; ``recipe`` is shown only when
    asked for, ``hint(name, recipe=True)``.
    """

    where: str
    more: str
    recipe: str


@dataclass(frozen=True)
class Hint:
    """A hint asked for with :func:`hint`: shows as its text."""

    exercise: str
    text: str

    def __str__(self) -> str:
        return _("Hint for {exercise}: {text}").format(exercise=self.exercise, text=self.text)

    __repr__ = __str__


_HINTS: dict[str, tuple[str, Hints]] = {}


def register_hints(exercise: str, hints: Hints, *names: str) -> Hints:
    """Make ``hints`` those of ``exercise``, found by :func:`hint` under ``names`` too."""
    if not isinstance(hints, Hints):
        raise TypeError(
            _("hints must be a Hints; got {hints_type}").format(hints_type=type(hints).__name__)
        )
    for name in (exercise, *names):
        _HINTS[name.lower()] = (exercise, hints)
    return hints


def hint(exercise: str, recipe: bool = False) -> Hint:
    """More help with an exercise, by its name or its function's: the idea, or the recipe.

    Examples
    --------
    >>> register_hints("double", Hints("look at x", "twice x", "return 2 * x"))
    Hints(where='look at x', more='twice x', recipe='return 2 * x')
    >>> hint("double")
    Hint for double: look at x twice x
    >>> hint("double", recipe=True)
    Hint for double: return 2 * x
    """
    if not isinstance(exercise, str):
        raise TypeError(
            _("exercise must be an exercise's name; got {type}").format(
                type=type(exercise).__name__
            )
        )
    found = _HINTS.get(exercise.lower())
    if found is None:
        known = ", ".join(sorted({name for name, _hints in _HINTS.values()}))
        raise ValueError(
            _("exercise must be one of {known}; got {exercise}").format(
                known=known, exercise=repr(exercise)
            )
        )
    name, hints = found
    return Hint(name, _(hints.recipe) if recipe else joined(_(hints.where), _(hints.more)))


def failure_hint(exercise: str, hints: Hints, failures: int) -> str:
    """The hint a report ends with after ``failures`` failures of ``exercise``.

    The first failure says where to look; later ones say more, and where the recipe is.

    Examples
    --------
    >>> print(failure_hint("doubling", Hints("look at x.", "twice x.", "return 2 * x"), 1))
    Hint: look at x.
    (More: check.hint("doubling").)
    """
    if not isinstance(hints, Hints):
        raise TypeError(
            _("hints must be a Hints; got {hints_type}").format(hints_type=type(hints).__name__)
        )
    if isinstance(failures, bool) or not isinstance(failures, int):
        raise TypeError(
            _("failures must be an int; got {failures_type}").format(
                failures_type=type(failures).__name__
            )
        )
    name = str(exercise)
    if failures <= 1:
        return _('Hint: {where}\n(More: check.hint("{name}").)').format(
            where=_(hints.where), name=name
        )
    return _(
        'Hint: {where_and_more}\n(The recipe, if you want it: check.hint("{name}", recipe=True).)'
    ).format(where_and_more=joined(_(hints.where), _(hints.more)), name=name)


def joined(where: str, more: str) -> str:
    """Two steps of a hint as one text: ``more`` starts a sentence after ``where``'s full stop.

    Its first word is capitalised when it is a plain word; a variable keeps its case.

    Examples
    --------
    >>> joined("look at the border.", "each pixel is a mean.")
    'look at the border. Each pixel is a mean.'
    >>> joined("look at t.", "t must reach 1.")
    'look at t. t must reach 1.'
    >>> joined("look at x", "twice x")
    'look at x twice x'
    """
    if not isinstance(where, str) or not isinstance(more, str):
        raise TypeError(
            _("where and more must be str; got {where_type}, {more_type}").format(
                where_type=type(where).__name__, more_type=type(more).__name__
            )
        )
    if where.endswith(("。", "？", "！")):
        return where + more
    if where.endswith((".", "?", "!")) and _PLAIN_WORD.match(more):
        more = more[0].upper() + more[1:]
    return f"{where} {more}"
