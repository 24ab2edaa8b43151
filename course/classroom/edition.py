"""The student edition: every notebook with its solutions replaced by stubs.

Standard library only: ``python -m course student`` needs no numpy, matplotlib
or ipywidgets.

A Chinese twin (``notebooks/zh-CN/``) goes through the same parser; the notes the
edition writes into it are in the language its first cell sets
(:func:`notebook_language`), from the library's gettext catalog.

An exercise cell in a lesson is tagged ``solution``: it defines the
student's function and ends with the checker call, for example::

    def recursive_bezier(control_points, t):
        ...the working solution...


    check.recursive_bezier(recursive_bezier)

The student edition keeps every line of that cell but its check and the bodies of
its top-level functions: each ``def`` line (with its decorators) and docstring
stay, and the body becomes ``raise NotImplementedError("your code here")``, its
message in the lesson's language (``"在这里写你的代码"`` in a Chinese twin:
:func:`course.classroom.stubs.stub_line`). The check moves to a locked cell under it,
which shows the checker's report: on the stub it reads ``FAIL ...: not written yet: your
function raised NotImplementedError: your code here`` (in Chinese «你还没有写这个函数（它抛出了
NotImplementedError：「在这里写你的代码」）») until the student writes the function, and
the notebook still runs from top to bottom. A partial scaffold marks what to remove
instead, with the lines ``### BEGIN SOLUTION`` and ``### END SOLUTION`` (nbgrader's
markers): only the lines between them go, replaced by the stub at the marker's indentation,
and the rest of the cell stays for the student to build on
(:mod:`course.classroom.stubs`). The cell's tag becomes ``exercise``; every
output and execution count is cleared, as ThinkDSP's student notebooks do.

A cell that shows a solution another way, by printing library source
(``source_of``, ``inspect.getsource``, ``??``) or by solving a variant of an
exercise, is replaced by a note; a cell tagged ``reveals`` is such a cell
too. Lessons keep those cells under "Going further".

:func:`course.classroom.release.student_notebook` makes one notebook's edition, as
nbgrader's release of the lesson (so the edition a student works in is the one graded);
:mod:`course.classroom.edition_folder` writes every lesson's into a folder. This module
holds what the editions share: reading a lesson, its language, its solution cells and the
cells that reveal one.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import Any

from course.classroom.folders import read_json_file
from course.classroom.notebooks import DEFAULT_LANGUAGE, LANGUAGES
from course.i18n import LANGUAGES as LOCALES
from course.i18n import N_, _, gettext_catalog

# The helpers below __all__'s names (cell_source, check_notebook, notebook_text,
# read_notebook) serve this package's other editions.
__all__ = [
    "EXERCISE_TAG",
    "HIDDEN_NOTE",
    "KERNELSPEC",
    "REVEALS_TAG",
    "SOLUTION_TAG",
    "cell_source",
    "check_notebook",
    "hidden_cell",
    "hidden_note",
    "notebook_language",
    "notebook_text",
    "read_notebook",
    "reveals",
    "solution_cells",
    "translated",
]

SOLUTION_TAG = "solution"
EXERCISE_TAG = "exercise"
#: A cell that gives an exercise's answer away another way (a solved variant).
REVEALS_TAG = "reveals"
#: What the student edition shows instead of a cell that reveals a solution.
HIDDEN_NOTE = N_(
    "*Student edition: a cell here printed code that answers an exercise. "
    "Solve the exercise first; the teacher's edition has the cell.*"
)
#: The kernelspec JupyterLab writes into a notebook it saves: every lesson carries it, so
#: opening one changes nothing.
KERNELSPEC = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}
_SETS_LANGUAGE = re.compile(r"""^\s*course\.use_language\(\s*["']([^"']+)["']\s*\)""", re.MULTILINE)
_PRINTS_SOURCE = re.compile(r"\bsource_of\(|getsource\(|^\s*\S+\?\?\s*$|%psource", re.MULTILINE)


def notebook_language(notebook: dict[str, Any]) -> str:
    """The language a lesson shows: the one its first code cell sets, else English.

    Examples
    --------
    >>> cell = {"cell_type": "code", "metadata": {}, "source": 'course.use_language("zh-CN")'}
    >>> notebook_language({"cells": [cell]}), notebook_language({"cells": []})
    ('zh-CN', 'en')
    """
    check_notebook(notebook)
    code = [cell_source(cell) for cell in notebook["cells"] if cell["cell_type"] == "code"]
    found = _SETS_LANGUAGE.search(code[0]) if code else None
    return found.group(1) if found and found.group(1) in LANGUAGES else DEFAULT_LANGUAGE


def translated(message: str, language: str) -> str:
    """``message``, one of the library's English messages, in ``language``.

    Examples
    --------
    >>> translated(HIDDEN_NOTE, "en") == HIDDEN_NOTE
    True
    >>> translated(HIDDEN_NOTE, "zh-CN")[:4]
    '*学生版'
    """
    if not isinstance(message, str):
        raise TypeError(
            _("message: expected a str; got {message_type}").format(
                message_type=type(message).__name__
            )
        )
    if language not in LANGUAGES:
        raise ValueError(
            _("language: expected one of {choices}; got {language:.60}").format(
                choices=", ".join(LANGUAGES), language=repr(language)
            )
        )
    locale = LOCALES[language]
    return message if locale is None else gettext_catalog(locale).gettext(message)


def hidden_note(language: str = DEFAULT_LANGUAGE) -> str:
    """The student edition's note, in ``language``, in place of a cell that reveals a solution."""
    return translated(HIDDEN_NOTE, language)


def hidden_cell(cell: dict[str, Any], index: int, language: str = DEFAULT_LANGUAGE) -> dict:
    """The note, a markdown cell in ``language``, that an edition shows in place of ``cell``
    (the ``index``-th), which reveals a solution; it keeps the cell's id.

    Examples
    --------
    >>> hidden_cell({"cell_type": "code", "source": "", "id": "c1"}, 3)["id"]
    'c1'
    """
    return {
        "cell_type": "markdown",
        "id": cell.get("id", f"hidden-{index}"),
        "metadata": {"tags": ["hidden"]},
        "source": hidden_note(language),
    }


def reveals(cell: dict[str, Any]) -> bool:
    """Whether a cell shows a solution outside an exercise: printed source, a solved variant.

    Examples
    --------
    >>> reveals({"cell_type": "code", "metadata": {}, "source": "print(source_of(f))"})
    True
    """
    _check_cell(cell, "cell")
    if cell["cell_type"] != "code" or SOLUTION_TAG in _tags(cell):
        return False
    return REVEALS_TAG in _tags(cell) or bool(_PRINTS_SOURCE.search(cell_source(cell)))


def cell_source(cell: dict[str, Any]) -> str:
    """A cell's source as one string (nbformat stores a string or a list of lines).

    Examples
    --------
    >>> cell_source({"cell_type": "code", "source": ["x = 1\\n", "y = 2"]})
    'x = 1\\ny = 2'
    """
    _check_cell(cell, "cell")
    source = cell["source"]
    return source if isinstance(source, str) else "".join(source)


def _tags(cell: dict[str, Any]) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


def _check_cell(cell: Any, name: str) -> None:
    """Refuse, with a ValueError naming ``name``, a cell nbformat 4 would not read."""
    if not isinstance(cell, dict):
        raise ValueError(
            _("{name}: expected a notebook cell (a JSON object); got {cell:.60}").format(
                name=name, cell=repr(cell)
            )
        )
    if cell.get("cell_type") not in ("code", "markdown", "raw"):
        raise ValueError(
            _(
                "{name}: expected a cell_type of 'code', 'markdown' or 'raw'; got {cell_type:.60}"
            ).format(name=name, cell_type=repr(cell.get("cell_type")))
        )
    source = cell.get("source")
    if not isinstance(source, str) and not (
        isinstance(source, list) and all(isinstance(line, str) for line in source)
    ):
        raise ValueError(
            _("{name}: expected a source (text or a list of lines); got {source:.60}").format(
                name=name, source=repr(source)
            )
        )
    metadata = cell.get("metadata", {})
    if not isinstance(metadata, dict):
        raise ValueError(
            _("{name}: expected metadata as a JSON object; got {metadata:.60}").format(
                name=name, metadata=repr(metadata)
            )
        )
    tags = metadata.get("tags", [])
    if not isinstance(tags, list) or not all(isinstance(tag, str) for tag in tags):
        raise ValueError(
            _("{name}: expected metadata.tags as a list of text; got {tags:.60}").format(
                name=name, tags=repr(tags)
            )
        )


def check_notebook(notebook: Any) -> None:
    """Refuse, with a ValueError naming the cell, what is not an nbformat 4 notebook's JSON.

    Examples
    --------
    >>> check_notebook({"cells": [{}]})
    Traceback (most recent call last):
    ...
    ValueError: notebook cell 0: expected a cell_type of 'code', 'markdown' or 'raw'; got None
    """
    if not isinstance(notebook, dict) or not isinstance(notebook.get("cells"), list):
        raise ValueError(
            _(
                "notebook: expected an nbformat 4 notebook, a JSON object with a list of cells; "
                "got {notebook:.60}"
            ).format(notebook=repr(notebook))
        )
    for index, cell in enumerate(notebook["cells"]):
        _check_cell(cell, _("notebook cell {index}").format(index=index))


def solution_cells(notebook: dict[str, Any]) -> list[int]:
    """Indices of the cells tagged ``solution``.

    Examples
    --------
    >>> solution_cells({"cells": [{"cell_type": "code", "source": "", "metadata": {}}]})
    []
    """
    check_notebook(notebook)
    return [
        index
        for index, cell in enumerate(notebook["cells"])
        if cell["cell_type"] == "code" and SOLUTION_TAG in _tags(cell)
    ]


def read_notebook(path: str | Path) -> dict[str, Any]:
    """The notebook JSON at ``path``, or a ValueError naming the file and what is wrong."""
    if isinstance(path, bool) or not isinstance(path, (str, os.PathLike)):
        raise TypeError(
            _("path: expected a notebook file's path; got {path_type}").format(
                path_type=type(path).__name__
            )
        )
    path = Path(path)
    try:
        notebook = read_json_file(path)
    except ValueError as error:  # a pipe, not UTF-8, not JSON, nested too deep
        raise ValueError(
            _("{path}: not a notebook file ({error})").format(path=path, error=error)
        ) from None
    except OSError as error:
        raise ValueError(
            _("{path}: cannot be read ({strerror})").format(path=path, strerror=error.strerror)
        ) from None
    try:
        check_notebook(notebook)
    except ValueError as error:
        raise ValueError(_("{path}: {error}").format(path=path, error=error)) from None
    return notebook


def notebook_text(notebook: dict[str, Any]) -> str:
    """The file text JupyterLab writes for ``notebook``: sorted keys, one-space indent."""
    check_notebook(notebook)
    try:
        return (
            json.dumps(notebook, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False)
            + "\n"
        )
    except (TypeError, ValueError) as error:
        raise ValueError(
            _("notebook: not JSON that a notebook file can hold ({error})").format(error=error)
        ) from None
