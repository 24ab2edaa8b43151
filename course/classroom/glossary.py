"""The Chinese edition's glossary: one term per concept, its variants and its first-use glosses.

``course/locale/zh_CN/glossary.tsv`` holds a row per concept (its heading says its columns):
the Chinese term used in prose, outputs, figures, widgets and checkers, the variants never to
use (plain text, or ``/.../`` a regular expression) and where a variant is checked, and the
gloss a lesson gives at the term's first use, «反走样（抗锯齿）». :func:`load_glossary` reads
it; :func:`forbidden_variants` finds a variant in the texts a student sees
(:class:`~course.classroom.chinese_text.Shown`, gathered by
:mod:`course.classroom.chinese_review`), outside code spans and LaTeX;
:func:`missing_glosses` finds a lesson without its gloss at the term's first use.

Classroom tooling over the course's own files, never given a student's input: it checks none
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from course.classroom.chinese_text import Shown, prose

UNCHECKED = True  # see the module docstring

__all__ = ["GLOSSARY", "Term", "forbidden_variants", "load_glossary", "missing_glosses"]

#: One term per concept.
GLOSSARY = Path(__file__).resolve().parents[1] / "locale" / "zh_CN" / "glossary.tsv"


@dataclass(frozen=True)
class Term:
    """One concept's row of the glossary (see ``glossary.tsv``'s heading)."""

    concept: str
    chinese: str
    forbidden: tuple[str, ...]
    gloss: str
    gloss_lessons: tuple[str, ...]
    scope: tuple[str, ...]

    def variants(self) -> list[tuple[str, re.Pattern]]:
        """Each forbidden variant with its pattern (``/.../`` a regular expression)."""
        return [
            (
                variant,
                re.compile(variant[1:-1])
                if len(variant) > 2 and variant.startswith("/") and variant.endswith("/")
                else re.compile(re.escape(variant)),
            )
            for variant in self.forbidden
        ]


_COLUMNS = ("concept", "chinese", "forbidden", "gloss", "gloss_lessons", "scope")


def load_glossary(path: Path = GLOSSARY) -> list[Term]:
    """The glossary's terms, in its order.

    Raises
    ------
    ValueError
        If the heading is not :data:`_COLUMNS`, a row has another number of columns, a
        term or a concept comes twice, or a variant is not a valid regular expression.
    """
    rows = [
        line.split("\t")
        for line in path.read_text(encoding="utf-8").splitlines()
        if line.strip() and not line.startswith("#")
    ]
    if not rows or tuple(rows[0]) != _COLUMNS:
        raise ValueError(f"{path.name}: the heading must be {' TAB '.join(_COLUMNS)}")
    terms = []
    for number, row in enumerate(rows[1:], 2):
        if len(row) != len(_COLUMNS):
            raise ValueError(f"{path.name}: row {number} has {len(row)} columns, not 6: {row}")
        concept, chinese, forbidden, gloss, lessons, scope = (cell.strip() for cell in row)
        if not concept or not chinese:
            raise ValueError(f"{path.name}: row {number} needs a concept and its term")
        if lessons and not gloss:
            raise ValueError(f"{path.name}: row {number} names lessons for no gloss")
        term = Term(
            concept,
            chinese,
            tuple(v.strip() for v in forbidden.split(" | ") if v.strip()),
            gloss,
            tuple(x.strip() for x in lessons.split(",") if x.strip()),
            tuple(x.strip() for x in scope.split(",") if x.strip()),
        )
        try:
            term.variants()
        except re.error as error:
            raise ValueError(f"{path.name}: row {number}: {error}") from error
        terms.append(term)
    for attribute in ("concept", "chinese"):
        names = [getattr(term, attribute) for term in terms]
        twice = sorted({name for name in names if names.count(name) > 1})
        if twice:
            raise ValueError(f"{path.name}: {attribute} given twice: {twice}")
    return terms


def forbidden_variants(terms: Iterable[Term], texts: Iterable[Shown]) -> list[str]:
    """Each use of a forbidden variant in ``texts``: where, the variant and the term.

    Examples
    --------
    >>> term = Term("naive loop", "朴素循环", ("普通循环",), "", (), ())
    >>> forbidden_variants([term], [Shown("05", "cell 3", "普通循环的像素值"),
    ...                             Shown("05", "cell 4", "`普通循环` 朴素循环")])
    ['05 cell 3: 普通循环 (use 朴素循环): «普通循环的像素值»']
    """
    found = []
    texts = list(texts)
    for term in terms:
        for variant, pattern in term.variants():
            for shown in texts:
                if term.scope and shown.lesson not in term.scope:
                    continue
                if pattern.search(prose(shown.text)):
                    found.append(
                        f"{shown.lesson or '--'} {shown.where}: {variant} (use {term.chinese}): "
                        f"«{_excerpt(shown.text, pattern)}»"
                    )
    return found


def _excerpt(text: str, pattern: re.Pattern, width: int = 30) -> str:
    hit = pattern.search(prose(text))
    start = max(0, hit.start() - width) if hit else 0
    end = min(len(text), (hit.end() if hit else 0) + width)
    return text[start:end].replace("\n", " ")


def missing_glosses(terms: Iterable[Term], lessons: dict[str, str]) -> list[str]:
    """Each first-use gloss a lesson lacks, or gives after the term's first use.

    ``lessons`` maps a lesson's number to its Chinese prose in order. A row's gloss is due
    in each of its lessons, ``first`` standing for the first lesson that uses the term;
    there it holds the term's first use, and is given once.

    Examples
    --------
    >>> term = Term("splat", "泼溅", (), "泼溅（splat）", ("first",), ())
    >>> missing_glosses([term], {"04": "没有", "05": "泼溅（splat）是……泼溅"})
    []
    >>> missing_glosses([term], {"05": "先说泼溅，再说泼溅（splat）"})
    ['05: 泼溅 is first used without its gloss «泼溅（splat）»']
    >>> missing_glosses([term], {"05": "泼溅"})
    ['05: no «泼溅（splat）» at the first use of 泼溅']
    """
    found = []
    for term in terms:
        due = [number for number in term.gloss_lessons if number != "first"]
        if "first" in term.gloss_lessons:
            users = [number for number, text in sorted(lessons.items()) if term.chinese in text]
            due += users[:1]
        for number in sorted(set(due)):
            text = prose(lessons.get(number, ""))
            at, first = text.find(term.gloss), text.find(term.chinese)
            if at < 0:
                found.append(f"{number}: no «{term.gloss}» at the first use of {term.chinese}")
            elif not at <= first < at + len(term.gloss):
                found.append(
                    f"{number}: {term.chinese} is first used without its gloss «{term.gloss}»"
                )
            elif term.gloss != term.chinese and text.count(term.gloss) > 1:
                found.append(f"{number}: «{term.gloss}» given {text.count(term.gloss)} times")
    return found
