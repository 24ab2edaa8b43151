"""The lesson notebooks, found on disk: ``NN_topic.ipynb``, in lesson order.

Everything that can be read off a notebook is read off it: a lesson exists
when its notebook exists, its title is the notebook's first heading and its
summary the paragraph after it. Standard library only (and :mod:`course.i18n`, which is).
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

from course.classroom.folders import read_json_file
from course.i18n import DEFAULT_LANGUAGE, _
from course.i18n import LANGUAGES as _LIBRARY_LANGUAGES

__all__ = [
    "DEFAULT_LANGUAGE",
    "LANGUAGES",
    "NOTEBOOKS",
    "Notebook",
    "find_notebooks",
    "language_folder",
    "notebooks",
]

#: The lessons' folder when the package is used from its repository (``pip install -e``).
#: An installed package (``pip install .``) has no such folder: see :func:`find_notebooks`.
NOTEBOOKS = Path(__file__).resolve().parent.parent.parent / "notebooks"
#: An environment variable naming the lessons' folder, for an installed package.
NOTEBOOKS_VARIABLE = "COURSE_NOTEBOOKS"
#: The editions' languages, the library's (:mod:`course.i18n`): English, the lessons in
#: ``notebooks/``, is the default; every other language's lessons are their twins in
#: ``notebooks/<language>/`` (``python -m course twins``).
LANGUAGES = tuple(_LIBRARY_LANGUAGES)
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


def language_folder(folder: str | Path, language: str) -> Path:
    """The lessons of ``language``: ``folder`` itself for English, else its twins' folder.

    Examples
    --------
    >>> language_folder("notebooks", "zh-CN").as_posix()
    'notebooks/zh-CN'
    >>> language_folder("notebooks", "en").as_posix()
    'notebooks'
    >>> language_folder("notebooks", "fr")
    Traceback (most recent call last):
    ...
    ValueError: language: expected one of en, zh-CN; got 'fr'
    """
    if isinstance(folder, bool) or not isinstance(folder, (str, os.PathLike)):
        raise TypeError(
            _("folder: expected a folder path; got {folder_type}").format(
                folder_type=type(folder).__name__
            )
        )
    if not isinstance(language, str) or language not in LANGUAGES:
        raise ValueError(
            _("language: expected one of {choices}; got {language:.60}").format(
                choices=", ".join(LANGUAGES), language=repr(language)
            )
        )
    folder = Path(folder)
    return folder if language == DEFAULT_LANGUAGE else folder / language


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
        raise ValueError(
            _("notebooks: expected a folder of NN_topic.ipynb files; got {folder}").format(
                folder=folder
            )
        )
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
        cells = read_json_file(path)["cells"]
        markdown = ["".join(cell["source"]) for cell in cells if cell["cell_type"] == "markdown"]
    except (OSError, ValueError) as error:  # a pipe, not UTF-8, not JSON, nested too deep
        raise ValueError(
            _("{path}: not a notebook file ({error})").format(path=path, error=error)
        ) from None
    except (KeyError, TypeError, AttributeError) as error:
        raise ValueError(
            _(
                "{path}: not an nbformat 4 notebook (a JSON object whose cells each have a "
                "cell_type and a source); reading it failed at {error}"
            ).format(path=path, error=repr(error))
        ) from None
    for text in markdown:
        heading = _HEADING.search(text)
        if heading:
            rest = text[heading.end() :].strip()
            paragraph = rest.split("\n\n")[0] if rest else ""
            return heading.group(1), " ".join(paragraph.split())
    raise ValueError(
        _("{name}: a lesson notebook starts with a '# Title' markdown heading").format(
            name=path.name
        )
    )
