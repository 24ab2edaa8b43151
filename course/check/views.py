"""The checker's view of the world while it works, and the student's while their code runs.

A cell may rebind what the checker works with (``np.allclose = lambda *a, **k: True``),
by accident or not; the checker's own work (the reference, the comparison, the report)
runs in :class:`CheckersView`: numpy, math and the builtins as the course imported them,
whatever a cell patched since, and warnings off without resetting Python's
once-per-location memory of them. The student's code runs with their patches
(:meth:`CheckersView.students`), and the warnings it raises are kept as text for the
report, never printed to stderr, where nbgrader would zero the test cell. (That memory
does not last from cell to cell in a notebook anyway: IPython empties the user
namespace's ``__warningregistry__`` before each cell, so a function defined in a cell
warns again in every later cell that calls it. Keeping its warnings as text is what keeps
a check cell's stderr empty; within one check, each is kept once.)

Unchecked: the checkers' machinery (``UNCHECKED = True``); nothing here takes a student's
input.
"""

from __future__ import annotations

import builtins
import math
import os
import warnings
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np

from course.check.sandbox import is_notebook_cell
from course.i18n import _

UNCHECKED = True  # see the module docstring

__all__ = ["CheckersView", "quiet"]

_seterr = np.seterr  # held from import, as everything the views use

_MISSING = object()


def _as_imported() -> tuple[tuple[dict[str, Any], str, Any], ...]:
    """Every public name of builtins, math and numpy (its linalg and fft too) with its value at
    import: the functions the checkers compare and convert with."""
    kept = []
    for module in (builtins, math, np, np.linalg, np.fft):
        space = vars(module)
        kept.extend((space, name, value) for name, value in list(space.items()) if name[:1] != "_")
    return tuple(kept)


_AS_IMPORTED = _as_imported()


def _patched() -> list[tuple[dict[str, Any], str, Any, Any]]:
    """The names a cell has rebound or deleted since import: (namespace, name, original, now)."""
    return [
        (space, name, value, space.get(name, _MISSING))
        for space, name, value in _AS_IMPORTED
        if space.get(name, _MISSING) is not value
    ]


def _put(space: dict[str, Any], name: str, value: Any) -> None:
    if value is _MISSING:
        space.pop(name, None)
    else:
        space[name] = value


def _ignore_all() -> list[tuple[Any, ...]]:
    return [("ignore", None, Warning, None, 0)]


@contextmanager
def quiet() -> Iterator[None]:
    """No warning shown inside, without making Python show the student's again after.

    ``warnings.catch_warnings`` and ``simplefilter`` bump the filters' version,
    which empties every module's once-per-location memory of the warnings it
    has shown: a RuntimeWarning a student's cell showed once would print again,
    to stderr, in the next check cell. Replacing the filter list itself, which
    Python's warnings code reads at every warning, bumps nothing.

    Examples
    --------
    >>> with quiet():
    ...     warnings.warn("not shown")
    """
    filters, errors = warnings.filters, _seterr(all="ignore")
    warnings.filters = _ignore_all()
    try:
        yield
    finally:
        warnings.filters = filters
        _seterr(**errors)


def _keeper(kept: list[str]) -> Callable[..., None]:
    """A ``warnings.showwarning`` that keeps each warning as a line of text in ``kept``."""

    def keep(message: Any, category: Any, filename: str, lineno: int, *rest: Any) -> None:
        try:
            if is_notebook_cell(filename):
                where = _("line {line} of your cell").format(line=lineno)
            else:
                where = _("line {line} of {file}").format(
                    line=lineno, file=os.path.basename(filename)
                )
            text = f"{getattr(category, '__name__', 'Warning')}: {message} ({where})"
        except Exception:  # a warning that cannot say itself is still a warning
            text = getattr(category, "__name__", "Warning")
        if text not in kept:
            kept.append(text)

    return keep


class CheckersView:
    """The checker's view of the world while it works, entered around its whole run.

    Inside, numpy (with ``linalg`` and ``fft``), math and the builtins hold the
    functions they held when the course was imported, however a cell rebound
    them since (``np.allclose = lambda *a, **k: True`` passes nothing), and no
    warning is shown (:func:`quiet`); numpy's floating-point errors are
    ignored. :meth:`students` gives the student's code its own world back for
    its call: their rebindings, their warning filters and numpy error state,
    and the warnings it raises kept as text for the report rather than
    printed. Leaving the view puts the student's rebindings back.

    Examples
    --------
    >>> saved = np.allclose
    >>> np.allclose = lambda *args, **kwargs: True
    >>> view = CheckersView()
    >>> with view:
    ...     print(np.allclose(1.0, 2.0))
    ...     with view.students([]):
    ...         print(np.allclose(1.0, 2.0))
    False
    True
    >>> np.allclose(1.0, 2.0)
    True
    >>> np.allclose = saved
    """

    def __enter__(self) -> CheckersView:
        self._theirs = _patched()
        for space, name, original, _now in self._theirs:
            _put(space, name, original)
        self._filters, self._errors = warnings.filters, _seterr(all="ignore")
        warnings.filters = _ignore_all()
        return self

    def __exit__(self, *exception: Any) -> None:
        warnings.filters = self._filters
        _seterr(**self._errors)
        for space, name, _original, now in self._theirs:
            _put(space, name, now)

    @contextmanager
    def students(self, kept: list[str]) -> Iterator[None]:
        """Within the view: the student's own world, for their code's call."""
        for space, name, _original, now in self._theirs:
            _put(space, name, now)
        warnings.filters = self._filters
        _seterr(**self._errors)
        shown = warnings.showwarning
        warnings.showwarning = _keeper(kept)
        try:
            yield
        finally:
            warnings.showwarning = shown
            self._errors = _seterr(all="ignore")
            self._filters, warnings.filters = warnings.filters, _ignore_all()
            self._theirs = _patched()  # what their call rebound counts as theirs too
            for space, name, original, _now in self._theirs:
                _put(space, name, original)
