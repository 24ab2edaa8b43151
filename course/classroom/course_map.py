"""The course map: one table row per lesson notebook, joined with its registry entry.

Used by the course map notebook (``00_index.ipynb``) and, with links from
the repository's top, by the README's lesson table. Standard library only
(the lesson modules it reads the entries from import what they draw with).
"""

from __future__ import annotations

from pathlib import Path

from course.classroom.notebooks import NOTEBOOKS, notebooks
from course.classroom.registry import lessons

__all__ = ["course_map"]

HEADER = "| lesson | what it teaches | handout task it answers |"


def course_map(folder: str | Path = NOTEBOOKS, link_prefix: str = "") -> str:
    """The course map as a Markdown table: one row per lesson notebook in ``folder``.

    Each title links to its notebook as ``link_prefix + file name``: the
    default suits the notebooks' own folder (and a copy of it), and
    ``"notebooks/"`` the repository's top, where the README is.

    Examples
    --------
    >>> print(course_map().splitlines()[0])
    | lesson | what it teaches | handout task it answers |
    """
    registered = lessons()
    rows = [HEADER, "|---|---|---|"]
    for book in notebooks(folder):
        lesson = registered.get(book.number)
        cells = [
            f"[{_escape(book.title)}]({link_prefix}{book.path.name})",
            _escape(lesson.teaches if lesson else book.summary),
            _escape(lesson.handout)
            if lesson
            else f"(no module course/lessons/l{book.number}_{book.topic}.py)",
        ]
        rows.append("| " + " | ".join(cells) + " |")
    return "\n".join(rows)


def _escape(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")
