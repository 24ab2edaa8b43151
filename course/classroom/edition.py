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

The student edition keeps every line of that cell but the bodies of its
top-level functions: each ``def`` line (with its decorators) and docstring
stay, and the body becomes ``raise NotImplementedError("your code here")``.
So the notebook still runs from top to bottom, and the checker's report on
the stub reads ``FAIL ...: case 1 raised NotImplementedError: your code
here`` until the student writes the function. A partial scaffold marks what
to remove instead, with the lines ``### BEGIN SOLUTION`` and ``### END
SOLUTION`` (nbgrader's markers): only the lines between them go, replaced by
the stub at the marker's indentation, and the rest of the cell stays for the
student to build on. The cell's tag becomes ``exercise``; every output and
execution count is cleared, as ThinkDSP's student notebooks do.

A cell that shows a solution another way, by printing library source
(``source_of``, ``inspect.getsource``, ``??``) or by solving a variant of an
exercise, is replaced by a note; a cell tagged ``reveals`` is such a cell
too. Lessons keep those cells under "Going further".
"""

from __future__ import annotations

import ast
import copy
import hashlib
import json
import os
import re
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from course.classroom.folders import check_output_folder
from course.classroom.notebooks import DEFAULT_LANGUAGE, LANGUAGES, NOTEBOOKS, notebooks
from course.i18n import LANGUAGES as LOCALES
from course.i18n import N_, _, gettext_catalog

# The helpers below __all__'s names (cell_source, check_notebook, notebook_text,
# read_notebook, solution_bodies, EditionReport) serve this package's other editions.
__all__ = [
    "BEGIN_SOLUTION",
    "END_SOLUTION",
    "HIDDEN_NOTE",
    "KERNELSPEC",
    "MANIFEST",
    "REVEALS_TAG",
    "SOLUTION_TAG",
    "STUB_LINE",
    "EditionReport",
    "cell_source",
    "check_notebook",
    "exercise_stub",
    "hidden_note",
    "notebook_language",
    "notebook_text",
    "parse_solution",
    "read_notebook",
    "reveals",
    "solution_bodies",
    "solution_cells",
    "student_notebook",
    "translated",
    "write_student_edition",
]

SOLUTION_TAG = "solution"
EXERCISE_TAG = "exercise"
#: A cell that gives an exercise's answer away another way (a solved variant).
REVEALS_TAG = "reveals"
STUB_LINE = 'raise NotImplementedError("your code here")'
BEGIN_SOLUTION = "### BEGIN SOLUTION"
END_SOLUTION = "### END SOLUTION"
#: What the student edition shows instead of a cell that reveals a solution.
HIDDEN_NOTE = N_(
    "*Student edition: a cell here printed code that answers an exercise. "
    "Solve the exercise first; the teacher's edition has the cell.*"
)
#: The kernelspec JupyterLab writes into a notebook it saves: every lesson carries it, so
#: opening one changes nothing.
KERNELSPEC = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}
#: The student edition's record of what it wrote: a digest of each notebook's sources.
MANIFEST = ".edition.json"
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


def exercise_stub(source: str) -> str:
    """The cell ``source`` with its solution replaced by a stub.

    With ``### BEGIN SOLUTION`` / ``### END SOLUTION`` markers, the lines
    between each pair (and the markers) become one stub line at the begin
    marker's indentation; otherwise each top-level function's body does.

    Examples
    --------
    >>> print(exercise_stub('''def area(w, h):
    ...     \"\"\"Width times height.\"\"\"
    ...     return w * h
    ...
    ...
    ... check.area(area)'''))
    def area(w, h):
        \"\"\"Width times height.\"\"\"
        raise NotImplementedError("your code here")
    <BLANKLINE>
    <BLANKLINE>
    check.area(area)
    """
    if not isinstance(source, str):
        raise TypeError(
            _("source: expected a cell's source text; got {source_type}").format(
                source_type=type(source).__name__
            )
        )
    if BEGIN_SOLUTION in source or END_SOLUTION in source:
        return _scaffold_stub(source)
    lines = source.splitlines()
    # Replace from the bottom up, so earlier line numbers stay valid.
    for start, end, indent in reversed(solution_bodies(source)):
        lines[start:end] = [indent + STUB_LINE]
    return "\n".join(lines)


def parse_solution(source: str, where: str) -> ast.Module:
    """The syntax tree of a solution cell's ``source``; a ValueError, beginning ``where``, if none.

    Examples
    --------
    >>> parse_solution("def f(:", "cell 3").body
    Traceback (most recent call last):
    ...
    ValueError: cell 3: a solution cell must be valid Python; line 1: invalid syntax
    """
    if not isinstance(source, str):
        raise TypeError(
            _("source: expected a cell's source text; got {source_type}").format(
                source_type=type(source).__name__
            )
        )
    try:
        return ast.parse(source)
    except (SyntaxError, ValueError) as error:  # ValueError: a NUL byte
        raise ValueError(
            _("{where}: a solution cell must be valid Python; line {line}: {problem}").format(
                where=where,
                line=getattr(error, "lineno", "?"),
                problem=getattr(error, "msg", error),
            )
        ) from None


def solution_bodies(source: str) -> list[tuple[int, int, str]]:
    """Where a solution cell's answers are: ``(start, end, indent)`` for each top-level function.

    ``lines[start:end]`` (0-based, of ``source.splitlines()``) is the body
    after the ``def`` line and docstring; ``indent`` is its indentation. The
    student edition replaces it by a stub, the nbgrader edition puts it
    between nbgrader's markers.

    Examples
    --------
    >>> solution_bodies("def f(x):\\n    return 2 * x\\n\\nf(1)")
    [(1, 2, '    ')]
    """
    tree = parse_solution(source, "source")
    functions = [
        node for node in tree.body if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
    ]
    if not functions:
        raise ValueError(
            _(
                "source: a solution cell must define the exercise's function at top level (def "
                "name(...): ...); got no def in:\n{source}"
            ).format(source=source)
        )
    lines = source.splitlines()
    bodies = []
    for function in functions:
        body = function.body
        first = body[0]
        has_docstring = (
            isinstance(first, ast.Expr)
            and isinstance(first.value, ast.Constant)
            and isinstance(first.value.value, str)
        )
        if first.lineno == function.lineno:
            raise ValueError(
                _(
                    "source: put the body of {name} on its own lines, not after 'def ...:' (line "
                    "{lineno})"
                ).format(name=function.name, lineno=function.lineno)
            )
        indent = " " * first.col_offset
        if has_docstring:
            keep = first.end_lineno
        else:
            # Comments above the first statement belong to the body (they may give
            # the answer away); the header ends at the last code line before them.
            keep = first.lineno - 1
            while keep > function.lineno and lines[keep - 1].strip()[:1] in ("", "#"):
                keep -= 1
        bodies.append((keep, function.end_lineno, indent))
    return bodies


def _scaffold_stub(source: str) -> str:
    """Replace each marked region, markers included, by the stub at the marker's indentation.

    Examples
    --------
    >>> print(_scaffold_stub('''def f(x):
    ...     y = 2 * x
    ...     ### BEGIN SOLUTION
    ...     y += 1
    ...     ### END SOLUTION
    ...     return y'''))
    def f(x):
        y = 2 * x
        raise NotImplementedError("your code here")
        return y
    """
    lines, kept, inside = source.splitlines(), [], False
    for number, line in enumerate(lines, start=1):
        marker = line.strip()
        if marker == BEGIN_SOLUTION:
            if inside:
                raise ValueError(
                    _("source: line {number} opens a solution inside another").format(number=number)
                )
            inside = True
            kept.append(line[: len(line) - len(line.lstrip())] + STUB_LINE)
        elif marker == END_SOLUTION:
            if not inside:
                raise ValueError(
                    _("source: line {number} closes a solution never opened").format(number=number)
                )
            inside = False
        elif not inside:
            kept.append(line)
    if inside:
        raise ValueError(
            _("source: {begin} without {end}").format(
                begin=repr(BEGIN_SOLUTION), end=repr(END_SOLUTION)
            )
        )
    return "\n".join(kept)


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


def student_notebook(notebook: dict[str, Any]) -> dict[str, Any]:
    """A copy of ``notebook`` (nbformat 4 JSON) with stubs for solutions and no outputs.

    Cells that reveal a solution (:func:`reveals`) become a markdown note, in the
    notebook's language (:func:`notebook_language`). The kernelspec is JupyterLab's own
    (:data:`KERNELSPEC`).
    """
    check_notebook(notebook)
    student = copy.deepcopy(notebook)
    note = hidden_note(notebook_language(notebook))
    for index, cell in enumerate(student["cells"]):
        if reveals(cell):
            student["cells"][index] = {
                "cell_type": "markdown",
                "id": cell.get("id", f"hidden-{index}"),
                "metadata": {"tags": ["hidden"]},
                "source": note,
            }
    for index in solution_cells(student):
        cell = student["cells"][index]
        try:
            cell["source"] = exercise_stub(cell_source(cell))
        except ValueError as error:
            raise ValueError(
                _("notebook cell {index} (tagged {tag}): {error}").format(
                    index=index, tag=repr(SOLUTION_TAG), error=error
                )
            ) from None
        tags = [EXERCISE_TAG if tag == SOLUTION_TAG else tag for tag in _tags(cell)]
        cell["metadata"]["tags"] = tags
    for cell in student["cells"]:
        if cell["cell_type"] == "code":
            cell["outputs"] = []
            cell["execution_count"] = None
    student.setdefault("metadata", {})["kernelspec"] = dict(KERNELSPEC)
    return student


@dataclass(frozen=True)
class EditionReport:
    """What :func:`write_student_edition` did, notebook by notebook."""

    written: list[Path] = field(default_factory=list)
    unchanged: list[Path] = field(default_factory=list)
    #: Notebooks the student edited, left as they are: the lesson has not changed.
    kept: list[Path] = field(default_factory=list)
    #: (the student's edited notebook, the new edition written beside it).
    beside: list[tuple[Path, Path]] = field(default_factory=list)

    def lines(self) -> list[str]:
        """One line per notebook that needs the reader's attention, then a summary."""
        notes = [
            _(
                "{edited} has your work: the lesson changed, and its new edition is {new}, "
                "beside it (yours is untouched)"
            ).format(edited=edited.name, new=new.name)
            for edited, new in self.beside
        ]
        notes.append(
            _(
                "{written} notebooks written, {unchanged} unchanged, {kept} with your edits kept"
            ).format(
                written=len(self.written),
                unchanged=len(self.unchanged),
                kept=len(self.kept) + len(self.beside),
            )
        )
        return notes


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
        notebook = json.loads(path.read_text(encoding="utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError) as error:
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


def _work(text: str) -> str:
    """A digest of what a student edits in a notebook: its cells' types and sources.

    Running cells changes outputs and counts, not the work: a notebook only run
    is replaced by a new edition; one whose sources differ is the student's.
    """
    try:
        notebook = json.loads(text)
        check_notebook(notebook)
        cells = [[cell["cell_type"], cell_source(cell)] for cell in notebook["cells"]]
    except (json.JSONDecodeError, ValueError):
        cells = ["unreadable", text]
    return hashlib.sha256(json.dumps(cells).encode("utf-8")).hexdigest()


def _read_manifest(out: Path) -> dict[str, str]:
    path = out / MANIFEST
    if not path.is_file():
        return {}
    try:
        manifest = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    if not isinstance(manifest, dict):
        return {}
    return {k: v for k, v in manifest.items() if isinstance(k, str) and isinstance(v, str)}


def _beside_name(out: Path, name: str, manifest: dict[str, str]) -> str:
    """The first ``NN_topic.new.ipynb`` (``.new2``, ...) that holds no edits of the student's."""
    stem = name.removesuffix(".ipynb")
    for number in range(1, 1000):
        candidate = f"{stem}.new{number if number > 1 else ''}.ipynb"
        path = out / candidate
        if not path.exists() or (
            path.is_file() and manifest.get(candidate) == _work(_read_text(path))
        ):
            return candidate
    raise ValueError(
        _("out: {out} holds 999 new editions of {name}; remove some").format(out=out, name=name)
    )


def _is_edition(out: Any) -> bool:
    """Whether ``out`` holds a student edition this function wrote (its manifest).

    A folder that holds only other languages' editions (``student/zh-CN/``, written
    before the English one) counts as one: the English edition goes beside them.
    """
    try:
        if not isinstance(out, (str, os.PathLike)):
            return False
        out = Path(out)
        if (out / MANIFEST).is_file():
            return True
        entries = list(out.iterdir()) if out.is_dir() else []
        return bool(entries) and all(
            entry.name in LANGUAGES and (entry / MANIFEST).is_file() for entry in entries
        )
    except OSError:
        return False


def _read_text(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return ""


def write_student_edition(
    out: str | Path, folder: str | Path = NOTEBOOKS, force: bool = False
) -> EditionReport:
    """Write or update the student edition of every notebook in ``folder`` in ``out``.

    A student's work is never lost. The edition records what it wrote in
    ``out/.edition.json``; run again, it writes new lessons, replaces the
    notebooks the student has not edited (running cells is not editing), and
    leaves every edited one alone: where that lesson changed, its new
    edition is written beside it as ``NN_topic.new.ipynb``.

    A non-empty ``out`` that is not an edition is refused unless ``force``;
    even then no file is replaced. Every notebook is read and every file
    checked before any is written, and each file is written whole (to a
    temporary file, then moved into place).
    """
    if not isinstance(force, bool):
        raise TypeError(
            _("force: expected True or False; got {force_type} {force:.60}").format(
                force_type=type(force).__name__, force=repr(force)
            )
        )
    check_output_folder(out, force or _is_edition(out))
    out = Path(out)
    editions = []
    for book in notebooks(folder, index=True):  # every notebook read before any is written
        notebook = read_notebook(book.path)
        try:
            edition = student_notebook(notebook)
        except ValueError as error:
            raise ValueError(_("{path}: {error}").format(path=book.path, error=error)) from None
        editions.append((book.path.name, notebook_text(edition)))
    manifest = _read_manifest(out)
    report = EditionReport()
    plan: list[tuple[str, str]] = []
    for name, text in editions:
        path = out / name
        work = _work(text)
        if path.is_dir():
            raise ValueError(
                _("out: {path} is a folder; the edition needs that name for a notebook").format(
                    path=path
                )
            )
        if not path.exists():
            plan.append((name, text))
            report.written.append(path)
            continue
        current = _work(_read_text(path))
        if current == work:
            report.unchanged.append(path)
        elif manifest.get(name) == current:  # as the edition wrote it: no work of the student's
            plan.append((name, text))
            report.written.append(path)
        elif manifest.get(name) == work:  # the student's, and the lesson has not changed
            report.kept.append(path)
        else:
            beside = _beside_name(out, name, manifest)
            plan.append((beside, text))
            report.beside.append((path, out / beside))
            report.written.append(out / beside)
        manifest[name] = work
    for name, text in plan:
        manifest[name] = _work(text)
    out.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=".edition-", dir=out))
    try:
        for name, text in plan:
            (staging / name).write_text(text, encoding="utf-8")
        (staging / MANIFEST).write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
        for name, _edition in plan:
            os.replace(staging / name, out / name)
        os.replace(staging / MANIFEST, out / MANIFEST)
    except OSError as error:
        raise ValueError(
            _("out: cannot write into {out} ({reason})").format(
                out=out, reason=error.strerror or error
            )
        ) from None
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return report
