"""The lesson notebooks, found on disk: ``NN_topic.ipynb``, in lesson order.

Everything that can be read off a notebook is read off it: a lesson exists
when its notebook exists, its title is the notebook's first heading and its
summary the paragraph after it. Standard library only.
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass
from pathlib import Path

__all__ = ["NOTEBOOKS", "Notebook", "find_notebooks", "notebooks"]

#: The lessons' folder when the package is used from its repository (``pip install -e``).
#: An installed package (``pip install .``) has no such folder: see :func:`find_notebooks`.
NOTEBOOKS = Path(__file__).resolve().parent.parent.parent / "notebooks"
#: An environment variable naming the lessons' folder, for an installed package.
NOTEBOOKS_VARIABLE = "COURSE_NOTEBOOKS"
LESSON_FILE = re.compile(r"^(\d\d)_(\w+)\.ipynb$")
_HEADING = re.compile(r"^#\s+(.+?)\s*$", re.MULTILINE)


@dataclass(frozen=True)
class Notebook:
    """A lesson notebook as found on disk."""

    number: str
    topic: str
    path: Path
    title: str
    summary: str


def find_notebooks() -> Path | None:
    """The lessons' folder, or None when there is none to be found.

    In order: ``$COURSE_NOTEBOOKS``; the repository's ``notebooks/`` beside the package
    (an editable install, or the package used from its clone); ``./notebooks`` when it
    holds lessons (an installed package run from a clone's folder).
    """
    named = os.environ.get(NOTEBOOKS_VARIABLE)
    if named:
        return Path(named)
    for folder in (NOTEBOOKS, Path.cwd() / "notebooks"):
        if folder.is_dir() and any(LESSON_FILE.match(path.name) for path in folder.iterdir()):
            return folder
    return None


def notebooks(folder: str | Path = NOTEBOOKS, index: bool = False) -> list[Notebook]:
    """Every ``NN_topic.ipynb`` in ``folder``, in lesson order.

    The course map ``00_index.ipynb`` is left out unless ``index`` is true.

    Examples
    --------
    >>> [(book.number, book.title) for book in notebooks()][:2]
    [('01', "Lesson 01 · de Casteljau's algorithm"), ('02', 'Lesson 02 · The Bernstein form')]
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise ValueError(f"notebooks: expected a folder of NN_topic.ipynb files; got {folder}")
    found = []
    for path in sorted(folder.iterdir()):
        match = LESSON_FILE.match(path.name)
        if not match or (match.group(1) == "00" and not index):
            continue
        title, summary = _title_and_summary(path)
        found.append(Notebook(match.group(1), match.group(2), path, title, summary))
    return found


def _title_and_summary(path: Path) -> tuple[str, str]:
    """The first markdown heading and the first paragraph after it."""
    try:
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        markdown = ["".join(cell["source"]) for cell in cells if cell["cell_type"] == "markdown"]
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as error:
        raise ValueError(f"{path}: not a notebook file ({error})") from None
    except (KeyError, TypeError, AttributeError) as error:
        raise ValueError(
            f"{path}: not an nbformat 4 notebook (a JSON object whose cells each have a "
            f"cell_type and a source); reading it failed at {error!r}"
        ) from None
    for text in markdown:
        heading = _HEADING.search(text)
        if heading:
            rest = text[heading.end() :].strip()
            paragraph = rest.split("\n\n")[0] if rest else ""
            return heading.group(1), " ".join(paragraph.split())
    raise ValueError(f"{path.name}: a lesson notebook starts with a '# Title' markdown heading")
