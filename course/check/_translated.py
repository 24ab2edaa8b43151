"""Hints that speak the current language, for checkers whose hints are registered at import.

A checker registers its :class:`~course.check.base.Hints` once, when its module is
imported, but a student may switch language afterwards (``course.use_language``).
:class:`TranslatedHints` keeps the English texts, marked for extraction with
:func:`~course.i18n.N_`, and translates each one when it is read, so the report and
``check.hint(...)`` speak the language of the moment. English reads the texts unchanged.

Unchecked: it holds the library's own messages, never a student's input.

Examples
--------
>>> from course.i18n import N_
>>> hints = TranslatedHints(N_("look at x"), N_("twice x"), N_("return 2 * x"))
>>> hints.where
'look at x'
"""

from __future__ import annotations

from typing import Any

from course.check.base import Hints
from course.i18n import _

UNCHECKED = True  # see the module docstring

__all__ = ["TranslatedHints"]

_TEXTS = frozenset({"where", "more", "recipe"})


class TranslatedHints(Hints):
    """:class:`~course.check.base.Hints` whose texts are translated each time they are read."""

    def __getattribute__(self, name: str) -> Any:
        value = super().__getattribute__(name)
        if name in _TEXTS and isinstance(value, str):
            return _(value)
        return value
