"""The shape of a lesson as a student meets it, against the budgets of ``teaching.md``.

A lesson's main path is everything before its "Going further" heading; the appendix after
it is not counted. :func:`shape` measures, for one notebook:

- ``words``: markdown words on the main path (a formula reads as one word, code blocks and
  images as none);
- ``longest``: the most markdown words between two things to look at (a picture, an app);
- ``pictures`` and ``apps``: image and widget outputs on the main path;
- ``exercises``: code cells tagged ``solution``;
- ``reveals``: main-path code cells that print library source (``getsource``, ``??``): an
  exercise's answer shown before the student tries;
- ``code``: the longest main-path code cell, in lines.

:func:`misses` names each budget a lesson misses; ``tests/test_lessons.py`` holds every
lesson (01 and up) to them. Standard library only; it reads the course's own notebooks, never
a student's input, and checks none (``UNCHECKED = True``).
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

__all__ = ["AT_LEAST", "AT_MOST", "misses", "shape"]

UNCHECKED = True  # see the module docstring

#: The budgets of the main path (steps 1-6 of a lesson's outline), from ``teaching.md``.
AT_MOST = {"words": 1000, "longest": 250, "reveals": 0, "code": 15}
AT_LEAST = {"pictures": 3, "apps": 1, "exercises": 2}

_GOING_FURTHER = re.compile(r"^#+\s.*going further", re.IGNORECASE | re.MULTILINE)
_REVEAL = re.compile(r"getsource\(|^\s*\S+\?\?\s*$|%psource|%pinfo2", re.MULTILINE)
_WORD = re.compile(r"[^\W\d_]+(?:['’][^\W\d_]+)?", re.UNICODE)
_WIDGET = "application/vnd.jupyter.widget-view+json"


def _text(source: Any) -> str:
    return "".join(source) if isinstance(source, list) else source


def _markdown_words(source: str) -> int:
    source = re.sub(r"```.*?```", " ", source, flags=re.DOTALL)
    source = re.sub(r"\$\$.*?\$\$|\$[^$\n]+\$", " x ", source, flags=re.DOTALL)
    source = re.sub(r"!\[[^\]]*\]\([^)]*\)|<[^>]+>", " ", source)
    return len(_WORD.findall(source))


def _looked_at(cell: dict[str, Any]) -> tuple[int, int]:
    pictures = apps = 0
    for output in cell.get("outputs", []):
        data = output.get("data", {})
        if _WIDGET in data:
            apps += 1
        elif any(kind.startswith("image/") for kind in data):
            pictures += 1
    return pictures, apps


def shape(path: str | Path) -> dict[str, int]:
    """The measures of the lesson notebook at ``path`` (see the module docstring).

    Examples
    --------
    >>> import json, tempfile, pathlib
    >>> cells = [
    ...     {"cell_type": "markdown", "metadata": {}, "source": "Drag $P_1$ and watch."},
    ...     {"cell_type": "code", "metadata": {"tags": ["solution"]}, "source": "x = 1\\nx",
    ...      "outputs": [{"data": {"image/png": ""}}]},
    ...     {"cell_type": "markdown", "metadata": {}, "source": "## Going further\\n\\nMore."},
    ... ]
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "09_x.ipynb"
    >>> _ = path.write_text(json.dumps({"cells": cells}))
    >>> shape(path)
    {'words': 4, 'longest': 4, 'reveals': 0, 'code': 2, 'pictures': 1, 'apps': 0, 'exercises': 1}
    """
    cells = json.loads(Path(path).read_text(encoding="utf-8"))["cells"]
    row = dict.fromkeys([*AT_MOST, *AT_LEAST], 0)
    run = 0
    main_path = True
    for cell in cells:
        source = _text(cell.get("source", ""))
        if "solution" in cell.get("metadata", {}).get("tags", []):
            row["exercises"] += 1
        if cell["cell_type"] == "markdown" and _GOING_FURTHER.search(source):
            main_path = False
        if not main_path:
            continue
        if cell["cell_type"] == "markdown":
            words = _markdown_words(source)
            row["words"] += words
            run += words
            row["longest"] = max(row["longest"], run)
        elif cell["cell_type"] == "code":
            pictures, apps = _looked_at(cell)
            row["pictures"] += pictures
            row["apps"] += apps
            if pictures or apps:
                run = 0
            row["reveals"] += bool(_REVEAL.search(source))
            row["code"] = max(row["code"], len(source.strip().splitlines()))
    return row


def misses(row: dict[str, int]) -> list[str]:
    """The budgets ``row`` (a :func:`shape`) misses, as ``"words 1001 > 1000"``."""
    over = [f"{key} {row[key]} > {most}" for key, most in AT_MOST.items() if row[key] > most]
    under = [f"{key} {row[key]} < {least}" for key, least in AT_LEAST.items() if row[key] < least]
    return over + under
