"""The lessons as nbgrader grades them: one generator for the student edition and nbgrader.

Standard library only, as the student edition it makes: ``python -m course student`` needs
no numpy, matplotlib or nbgrader.

An exercise cell of a lesson (tagged ``solution``) defines the student's function and ends
with its check, ``check.<name>(<function>)``. Graded, it becomes two cells:

- the answer cell: the cell without its check, an nbgrader solution cell whose grade id is
  the function's name, its answers between nbgrader's markers (each function's body, or the
  scaffold's own ``### BEGIN SOLUTION`` / ``### END SOLUTION`` lines), tagged ``exercise``;
- the check cell under it: locked, autograded, worth :data:`EXERCISE_POINTS`, running
  ``check.<name>(<function>).graded()``, which shows the check's report and, under nbgrader,
  raises when the answer is wrong (:meth:`course.check.base.CheckResult.graded`). An
  exercise that calls an earlier one is checked with the earlier one's grader answer
  (:func:`course.classroom.nbgrader.earlier_exercises`), so a mistake is charged once.

:func:`nbgrader_notebook` is the lesson so, with its answers: nbgrader's source, which
``make nbgrader`` writes. :func:`student_notebook` is the same with each answer replaced by
the stub in the lesson's language (:func:`~course.classroom.stubs.stub_line`), checksummed
and locked as ``nbgrader generate_assignment`` does (``tests/test_nbgrader.py`` compares the
two): the student edition *is* nbgrader's release, so the notebook a student works in, from
``make lab``, the hub or a link, is the one nbgrader grades.

Both replace a cell that reveals a solution another way (printed source, a solved variant:
:func:`~course.classroom.edition.reveals`) by a note in the lesson's language, drop the
``source_of`` import that such cells use, and clear every output.
"""

from __future__ import annotations

import ast
import copy
import hashlib
import re
from dataclasses import dataclass
from typing import Any

from course.classroom.edition import (
    EXERCISE_TAG,
    KERNELSPEC,
    SOLUTION_TAG,
    cell_source,
    check_notebook,
    hidden_cell,
    notebook_language,
    reveals,
    solution_cells,
    translated,
)
from course.classroom.notebooks import DEFAULT_LANGUAGE
from course.classroom.stubs import (
    BEGIN_SOLUTION,
    END_SOLUTION,
    parse_solution,
    solution_bodies,
    stub_line,
)
from course.i18n import N_, _

__all__ = [
    "EXERCISE_POINTS",
    "Exercise",
    "exercises",
    "nbgrader_checksum",
    "nbgrader_notebook",
    "student_notebook",
    "without_source_import",
]

#: The points of each exercise's check cell.
EXERCISE_POINTS = 1
#: nbgrader's cell metadata schema.
SCHEMA_VERSION = 3
# The check cell's comments, in the lesson's language (edition.translated).
_TEST_COMMENT = N_(
    "Check {function} ({points} point, autograded): run this cell after the one above."
)
_TEST_COMMENT_POINTS = N_(
    "Check {function} ({points} points, autograded): run this cell after the one above."
)
_EARLIER_COMMENT = N_(
    "Checked with the grader's own {earlier}, so that a mistake there is not charged twice."
)
# The import of the library's source printer, which only the cells a student edition hides use.
_SOURCE_IMPORT = re.compile(r"^from course\.classroom\.source import source_of\s*$")


@dataclass(frozen=True)
class Exercise:
    """One exercise of a lesson, as nbgrader grades it."""

    #: The function the student writes.
    function: str
    #: The checker's call that ends the cell, e.g. ``check.bilinear_sample(bilinear_sample)``.
    check: str
    #: The earlier exercises this one calls, checked with their grader answers.
    uses: tuple[str, ...]
    #: The index of its cell in the lesson.
    cell: int
    #: The first line of the check's call in the cell (1-based): the answer ends above it.
    check_line: int = 0
    points: int = EXERCISE_POINTS

    @property
    def grade_cell(self) -> str:
        """The source of the check cell, its comments in English."""
        return self.grade_source(DEFAULT_LANGUAGE)

    def grade_source(self, language: str) -> str:
        """The source of the check cell, its comments in ``language``."""
        call = f"{self.check}.graded()"
        comment = _TEST_COMMENT if self.points == 1 else _TEST_COMMENT_POINTS
        lines = [
            "# " + translated(comment, language).format(function=self.function, points=self.points)
        ]
        if not self.uses:
            return "\n".join([*lines, call])
        names = ", ".join(repr(name) for name in self.uses)
        earlier = translated(_EARLIER_COMMENT, language).format(earlier=" and ".join(self.uses))
        lines += [
            f"# {earlier}",
            "from course.classroom.nbgrader import earlier_exercises",
            "",
            f"with earlier_exercises({self.function}, {names}):",
            f"    {call}",
        ]
        return "\n".join(lines)


def exercises(notebook: dict[str, Any]) -> list[Exercise]:
    """The exercises of a lesson: each cell tagged ``solution``, in order.

    A solution cell defines its function (a top-level ``def``) and ends with the checker's
    call on it, ``check.<name>(<function>)``.

    Examples
    --------
    >>> cell = {"cell_type": "code", "metadata": {"tags": ["solution"]},
    ...         "source": "def twice(x):\\n    return 2 * x\\n\\n\\ncheck.twice(twice)"}
    >>> exercises({"cells": [cell]})[0].check
    'check.twice(twice)'
    """
    found: list[Exercise] = []
    for index in solution_cells(notebook):
        source = cell_source(notebook["cells"][index])
        tree = parse_solution(source, _("notebook cell {index}").format(index=index))
        functions = [node for node in tree.body if isinstance(node, ast.FunctionDef)]
        last = tree.body[-1] if tree.body else None
        call = last.value if isinstance(last, ast.Expr) else None
        if (
            not functions
            or not isinstance(call, ast.Call)
            or not isinstance(call.func, ast.Attribute)
            or not isinstance(call.func.value, ast.Name)
            or len(call.args) != 1
            or not isinstance(call.args[0], ast.Name)
        ):
            raise ValueError(
                _(
                    "notebook cell {index}: a solution cell defines the exercise's function and "
                    "ends with its check, check.<name>(<function>)"
                ).format(index=index)
            )
        function = call.args[0].id
        body = next((node for node in functions if node.name == function), None)
        if body is None:
            raise ValueError(
                _("notebook cell {index}: the check's {function} is not defined here").format(
                    index=index, function=function
                )
            )
        called = {node.id for node in ast.walk(body) if isinstance(node, ast.Name)}
        uses = tuple(earlier.function for earlier in found if earlier.function in called)
        found.append(Exercise(function, ast.unparse(call), uses, index, last.lineno))
    return found


def _marked(source: str) -> str:
    """``source`` with nbgrader's markers around each answer (the student edition's stubs)."""
    if BEGIN_SOLUTION in source or END_SOLUTION in source:
        return source
    lines = source.splitlines()
    for start, end, indent in reversed(solution_bodies(source)):
        lines[start:end] = [indent + BEGIN_SOLUTION, *lines[start:end], indent + END_SOLUTION]
    return "\n".join(lines)


def _nbgrader(grade_id: str, *, solution: bool, grade: bool, points: int = 0) -> dict[str, Any]:
    metadata = {
        "grade": grade,
        "grade_id": grade_id,
        "locked": not solution,
        "schema_version": SCHEMA_VERSION,
        "solution": solution,
    }
    if grade:
        metadata["points"] = points
    return metadata


def without_source_import(cell: dict[str, Any]) -> dict[str, Any] | None:
    """The code cell without the import of the library's source printer, ``source_of``,
    which only the cells an edition hides use (None when nothing else is left).

    Examples
    --------
    >>> cell = {"cell_type": "code", "metadata": {},
    ...         "source": "import time\\nfrom course.classroom.source import source_of"}
    >>> without_source_import(cell)["source"]
    'import time'
    """
    lines = cell_source(cell).split("\n")
    kept = [line for line in lines if not _SOURCE_IMPORT.match(line)]
    if len(kept) == len(lines):
        return cell
    text = "\n".join(kept).strip("\n")
    if not text.strip():
        return None
    return {**cell, "source": re.sub(r"\n{3,}", "\n\n", text)}


def nbgrader_notebook(notebook: dict[str, Any]) -> dict[str, Any]:
    """A copy of a lesson as nbgrader's source: answer cells, check cells, no outputs.

    Cells that reveal a solution another way become the student edition's note; the notes
    and the check cells' comments are in the lesson's language; every output is cleared;
    the kernelspec is JupyterLab's.
    """
    found = exercises(notebook)
    language = notebook_language(notebook)
    by_cell = {exercise.cell: exercise for exercise in found}
    cells = []
    for index, original in enumerate(copy.deepcopy(notebook["cells"])):
        cell: dict[str, Any] | None = original
        if reveals(original):
            cell = hidden_cell(original, index, language)
        elif original["cell_type"] == "code":
            cell = without_source_import(original)
        if cell is None:
            continue
        if cell["cell_type"] == "code":
            cell["outputs"] = []
            cell["execution_count"] = None
        exercise = by_cell.get(index)
        if exercise is None:
            cells.append(cell)
            continue
        answer = "\n".join(cell_source(cell).splitlines()[: exercise.check_line - 1]).rstrip()
        try:
            cell["source"] = _marked(answer)
        except ValueError as error:
            raise ValueError(
                _("notebook cell {index}: {error}").format(index=index, error=error)
            ) from None
        metadata = cell.setdefault("metadata", {})
        tags = [tag for tag in metadata.get("tags", []) if tag != SOLUTION_TAG]
        metadata["tags"] = [EXERCISE_TAG, *tags]
        metadata["nbgrader"] = _nbgrader(exercise.function, solution=True, grade=False)
        cells.append(cell)
        cells.append(
            {
                "cell_type": "code",
                "execution_count": None,
                "id": f"{exercise.function}-test",
                "metadata": {
                    "nbgrader": _nbgrader(
                        f"{exercise.function}_test",
                        solution=False,
                        grade=True,
                        points=exercise.points,
                    )
                },
                "outputs": [],
                "source": exercise.grade_source(language),
            }
        )
    source = {**copy.deepcopy({k: v for k, v in notebook.items() if k != "cells"}), "cells": cells}
    source.setdefault("metadata", {})["kernelspec"] = dict(KERNELSPEC)
    return source


def _cleared(source: str, stub: str) -> str:
    """``source`` with each marked answer replaced by ``stub``, as nbgrader's ClearSolutions."""
    lines, inside = [], False
    for line in source.split("\n"):
        if BEGIN_SOLUTION in line:
            inside = True
            lines.append(re.match(r"\s*", line).group(0) + stub)  # type: ignore[union-attr]
        elif END_SOLUTION in line:
            inside = False
        elif not inside:
            lines.append(line)
    return "\n".join(lines)


def nbgrader_checksum(cell: dict[str, Any]) -> str:
    """The checksum nbgrader keeps of a graded, answer or locked cell (``nbgrader.utils``'s
    ``compute_checksum``): it tells nbgrader whether a student changed the cell.

    Examples
    --------
    >>> cell = {"cell_type": "code", "source": "x = 1", "metadata": {"nbgrader": {
    ...     "grade": False, "solution": True, "locked": False, "grade_id": "x"}}}
    >>> nbgrader_checksum(cell)
    '09fc51f431844ad18c8792ab7e71a243'
    """
    grading = cell["metadata"]["nbgrader"]
    digest = hashlib.md5(usedforsecurity=False)
    for part in (
        cell_source(cell),
        cell["cell_type"],
        str(bool(grading.get("grade"))),
        str(bool(grading.get("solution"))),
        str(bool(grading.get("locked"))),
        grading["grade_id"],
    ):
        digest.update(part.encode("utf-8"))
    if grading.get("grade"):
        digest.update(str(float(grading["points"])).encode("utf-8"))
    return digest.hexdigest()


def student_notebook(notebook: dict[str, Any]) -> dict[str, Any]:
    """A lesson's student edition: nbgrader's release of :func:`nbgrader_notebook`.

    Each answer is replaced by its stub, in the lesson's language; the answer and check cells
    carry nbgrader's metadata and checksums, and are locked as ``nbgrader
    generate_assignment`` locks them (an answer cell cannot be deleted, a check cell neither
    deleted nor edited). The input is left alone.
    """
    check_notebook(notebook)
    try:
        release = nbgrader_notebook(notebook)
    except ValueError as error:
        raise ValueError(
            _("{error} (a cell tagged {tag})").format(error=error, tag=repr(SOLUTION_TAG))
        ) from None
    stub = stub_line(notebook_language(notebook))
    for cell in release["cells"]:
        grading = cell.get("metadata", {}).get("nbgrader")
        if grading is None:
            continue
        cell["source"] = _cleared(cell_source(cell), stub)
        grading["cell_type"] = cell["cell_type"]
        grading["checksum"] = nbgrader_checksum(cell)
        cell["metadata"]["deletable"] = False
        if grading["locked"]:
            cell["metadata"]["editable"] = False
    return release
