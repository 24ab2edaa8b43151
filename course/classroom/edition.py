"""The student edition: every notebook with its solutions replaced by stubs.

Standard library only: ``python -m course student`` needs no numpy, matplotlib
or ipywidgets.

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
import json
import re
from pathlib import Path
from typing import Any

from course.classroom.folders import check_output_folder
from course.classroom.notebooks import NOTEBOOKS, notebooks

__all__ = [
    "BEGIN_SOLUTION",
    "END_SOLUTION",
    "HIDDEN_NOTE",
    "REVEALS_TAG",
    "SOLUTION_TAG",
    "STUB_LINE",
    "exercise_stub",
    "reveals",
    "solution_cells",
    "student_notebook",
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
HIDDEN_NOTE = (
    "*Student edition: a cell here printed code that answers an exercise. "
    "Solve the exercise first; the teacher's edition has the cell.*"
)
_PRINTS_SOURCE = re.compile(r"\bsource_of\(|getsource\(|^\s*\S+\?\?\s*$|%psource", re.MULTILINE)


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
    if BEGIN_SOLUTION in source or END_SOLUTION in source:
        return _scaffold_stub(source)
    tree = ast.parse(source)
    functions = [node for node in tree.body if isinstance(node, ast.FunctionDef)]
    if not functions:
        raise ValueError(
            "source: a solution cell must define the exercise's function at top level "
            f"(def name(...): ...); got no def in:\n{source}"
        )
    lines = source.splitlines()
    # Replace from the bottom up, so earlier line numbers stay valid.
    for function in reversed(functions):
        body = function.body
        first = body[0]
        has_docstring = (
            isinstance(first, ast.Expr)
            and isinstance(first.value, ast.Constant)
            and isinstance(first.value.value, str)
        )
        if first.lineno == function.lineno:
            raise ValueError(
                f"source: put the body of {function.name} on its own lines, not after "
                f"'def ...:' (line {function.lineno})"
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
        lines[keep : function.end_lineno] = [indent + STUB_LINE]
    return "\n".join(lines)


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
                raise ValueError(f"source: line {number} opens a solution inside another")
            inside = True
            kept.append(line[: len(line) - len(line.lstrip())] + STUB_LINE)
        elif marker == END_SOLUTION:
            if not inside:
                raise ValueError(f"source: line {number} closes a solution never opened")
            inside = False
        elif not inside:
            kept.append(line)
    if inside:
        raise ValueError(f"source: {BEGIN_SOLUTION!r} without {END_SOLUTION!r}")
    return "\n".join(kept)


def reveals(cell: dict[str, Any]) -> bool:
    """Whether a cell shows a solution outside an exercise: printed source, a solved variant."""
    if cell["cell_type"] != "code" or SOLUTION_TAG in _tags(cell):
        return False
    return REVEALS_TAG in _tags(cell) or bool(_PRINTS_SOURCE.search("".join(cell["source"])))


def _tags(cell: dict[str, Any]) -> list[str]:
    return list(cell.get("metadata", {}).get("tags", []))


def solution_cells(notebook: dict[str, Any]) -> list[int]:
    """Indices of the cells tagged ``solution``."""
    return [
        index
        for index, cell in enumerate(notebook["cells"])
        if cell["cell_type"] == "code" and SOLUTION_TAG in _tags(cell)
    ]


def student_notebook(notebook: dict[str, Any]) -> dict[str, Any]:
    """A copy of ``notebook`` (nbformat 4 JSON) with stubs for solutions and no outputs.

    Cells that reveal a solution (:func:`reveals`) become a markdown note.
    """
    student = copy.deepcopy(notebook)
    for index, cell in enumerate(student["cells"]):
        if reveals(cell):
            student["cells"][index] = {
                "cell_type": "markdown",
                "id": cell.get("id", f"hidden-{index}"),
                "metadata": {"tags": ["hidden"]},
                "source": HIDDEN_NOTE,
            }
    for index in solution_cells(student):
        cell = student["cells"][index]
        cell["source"] = exercise_stub("".join(cell["source"]))
        tags = [EXERCISE_TAG if tag == SOLUTION_TAG else tag for tag in _tags(cell)]
        cell["metadata"]["tags"] = tags
    for cell in student["cells"]:
        if cell["cell_type"] == "code":
            cell["outputs"] = []
            cell["execution_count"] = None
    return student


def write_student_edition(
    out: str | Path, folder: str | Path = NOTEBOOKS, force: bool = False
) -> list[Path]:
    """Write the student edition of every notebook in ``folder`` into ``out``.

    Refuses a non-empty ``out`` unless ``force``; never deletes a file (with
    ``force``, notebooks of the same names are replaced). Returns the paths
    written.
    """
    check_output_folder(out, force)
    out = Path(out)
    editions = []
    for book in notebooks(folder, index=True):  # every notebook read before any is written
        try:
            notebook = json.loads(book.path.read_text(encoding="utf-8"))
            edition = student_notebook(notebook)
        except (json.JSONDecodeError, UnicodeDecodeError) as error:
            raise ValueError(f"{book.path}: not a notebook file ({error})") from None
        except (KeyError, TypeError, AttributeError) as error:
            raise ValueError(
                f"{book.path}: not a notebook, no {error} where one is needed"
            ) from None
        editions.append((book.path.name, edition))
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for name, edition in editions:
        path = out / name
        text = json.dumps(edition, indent=1, ensure_ascii=False)
        path.write_text(text + "\n", encoding="utf-8")
        written.append(path)
    return written
