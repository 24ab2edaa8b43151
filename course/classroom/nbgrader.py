"""The nbgrader edition: the lessons as an nbgrader course folder, from their ``solution`` tags.

``python -m course nbgrader --out DIR`` (``make nbgrader``) writes
``DIR/nbgrader_config.py`` and ``DIR/source/<lesson>/<lesson>.ipynb`` for
each lesson with exercises. Plain nbgrader then takes it from there:
``nbgrader generate_assignment <lesson>``, ``autograde``,
``generate_feedback``.

Each exercise cell becomes an nbgrader solution cell: its answer (each
function's body, or the lines between ``### BEGIN SOLUTION`` and ``### END
SOLUTION``) sits between nbgrader's markers, so the release shows the same
stub as the student edition. After it comes a locked, autograded test
cell worth :data:`EXERCISE_POINTS` that runs the lesson's checker and
raises :class:`course.check.base.CheckFailed`, with the checker's whole
report, when the answer is wrong: the report is the feedback.

A mistake is charged once. An exercise that calls an earlier one
(lesson 01's ``recursive_bezier`` calls ``next_level``) is graded with the
earlier exercise's ``grader_reference``, which its checker declares
(:func:`course.check.exercises.exercise`; :func:`earlier_exercises`).
"""

from __future__ import annotations

import ast
import copy
import os
import shutil
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from course.classroom.edition import (
    KERNELSPEC,
    SOLUTION_TAG,
    cell_source,
    hidden_note,
    notebook_language,
    notebook_text,
    read_notebook,
    reveals,
    solution_cells,
    translated,
)
from course.classroom.folders import check_output_folder
from course.classroom.notebooks import DEFAULT_LANGUAGE, NOTEBOOKS, notebooks
from course.classroom.stubs import (
    BEGIN_SOLUTION,
    END_SOLUTION,
    STUB_LINE,
    parse_solution,
    solution_bodies,
)
from course.i18n import N_, _

__all__ = [
    "EXERCISE_POINTS",
    "Exercise",
    "earlier_exercises",
    "exercises",
    "nbgrader_notebook",
    "reference",
    "write_nbgrader_course",
]

#: The points of each exercise's test cell.
EXERCISE_POINTS = 1
# The test cell's comments, in the lesson's language (edition.translated).
_TEST_COMMENT = N_(
    "Autograded test of {function} ({points} point): it raises, with the check's report, "
    "if the answer is wrong."
)
_TEST_COMMENT_POINTS = N_(
    "Autograded test of {function} ({points} points): it raises, with the check's report, "
    "if the answer is wrong."
)
_EARLIER_COMMENT = N_(
    "Graded with the library's {earlier}, so that a mistake there is not charged twice."
)
#: nbgrader's cell metadata schema.
SCHEMA_VERSION = 3
CONFIG = '''"""nbgrader's configuration for the course, written by `python -m course nbgrader`."""

c = get_config()  # noqa: F821 (nbgrader defines it)
c.CourseDirectory.course_id = "course"
# The release shows the same stub as the student edition.
c.ClearSolutions.code_stub = {{"python": {stub!r}}}
# A lesson's pictures and apps take a while to compute in a fresh kernel.
c.Execute.timeout = 600
'''


@dataclass(frozen=True)
class Exercise:
    """One exercise of a lesson, as the nbgrader edition grades it."""

    #: The function the student writes.
    function: str
    #: The checker's call that ends the cell, e.g. ``check.bilinear_lookup(bilinear_sample)``.
    check: str
    #: The earlier exercises this one calls, graded with their references.
    uses: tuple[str, ...]
    #: The index of its cell in the lesson.
    cell: int
    points: int = EXERCISE_POINTS

    @property
    def grade_cell(self) -> str:
        """The source of the autograded test cell, its comments in English."""
        return self.grade_source(DEFAULT_LANGUAGE)

    def grade_source(self, language: str) -> str:
        """The source of the autograded test cell, its comments in ``language``."""
        call = f"{self.check}.assert_passed()"
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

    A solution cell defines its function (the first top-level ``def``) and
    ends with the checker's call on it, ``check.<name>(<function>)``.
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
        unreferenced = [name for name in uses if _grader_reference(name) is None]
        if unreferenced:
            raise ValueError(
                _(
                    "notebook cell {index}: {function} calls the earlier exercise {unreferenced}, "
                    "whose checker declares no grader_reference to grade it with"
                ).format(index=index, function=function, unreferenced=unreferenced[0])
            )
        found.append(Exercise(function, ast.unparse(call), uses, index))
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


def nbgrader_notebook(notebook: dict[str, Any]) -> dict[str, Any]:
    """A copy of a lesson as nbgrader's source: solution cells, test cells, no outputs.

    Cells that reveal a solution another way become the student edition's
    note; the notes and the test cells' comments are in the lesson's language; every
    output is cleared; the kernelspec is JupyterLab's.
    """
    found = exercises(notebook)
    language = notebook_language(notebook)
    source = copy.deepcopy(notebook)
    cells = []
    by_cell = {exercise.cell: exercise for exercise in found}
    for index, cell in enumerate(source["cells"]):
        if reveals(cell):
            cell = {
                "cell_type": "markdown",
                "id": cell.get("id", f"hidden-{index}"),
                "metadata": {"tags": ["hidden"]},
                "source": hidden_note(language),
            }
        if cell["cell_type"] == "code":
            cell["outputs"] = []
            cell["execution_count"] = None
        exercise = by_cell.get(index)
        if exercise is None:
            cells.append(cell)
            continue
        try:
            cell["source"] = _marked(cell_source(cell))
        except ValueError as error:
            raise ValueError(
                _("notebook cell {index}: {error}").format(index=index, error=error)
            ) from None
        metadata = cell.setdefault("metadata", {})
        metadata["tags"] = [tag for tag in metadata.get("tags", []) if tag != SOLUTION_TAG]
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
    source["cells"] = cells
    source.setdefault("metadata", {})["kernelspec"] = dict(KERNELSPEC)
    return source


def write_nbgrader_course(
    out: str | Path, folder: str | Path = NOTEBOOKS, force: bool = False
) -> list[Path]:
    """Write an nbgrader course folder for the lessons in ``folder`` into ``out``.

    ``out/nbgrader_config.py`` and ``out/source/<lesson>/<lesson>.ipynb`` for
    each lesson with exercises. Refuses a non-empty ``out`` unless ``force``
    (then the lessons' sources are replaced, a teacher's
    ``nbgrader_config.py`` is kept, nothing is deleted). Every
    lesson is converted before anything is written, and the files are
    written to a temporary folder first, then moved into place.
    """
    check_output_folder(out, force)
    out = Path(out)
    files: dict[str, str] = {}
    if not (out / "nbgrader_config.py").exists():
        files["nbgrader_config.py"] = CONFIG.format(stub=STUB_LINE)
    for book in notebooks(folder):
        notebook = read_notebook(book.path)
        try:
            if not exercises(notebook):
                continue
            converted = nbgrader_notebook(notebook)
        except ValueError as error:
            raise ValueError(_("{path}: {error}").format(path=book.path, error=error)) from None
        lesson = book.path.stem
        files[f"source/{lesson}/{lesson}.ipynb"] = notebook_text(converted)
    out.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=".nbgrader-", dir=out))
    written = []
    try:
        for name, text in files.items():
            (staging / name).parent.mkdir(parents=True, exist_ok=True)
            (staging / name).write_text(text, encoding="utf-8")
        for name in files:
            target = out / name
            if target.is_dir():
                raise ValueError(
                    _("out: {target} is a folder; the course needs it for a file").format(
                        target=target
                    )
                )
            target.parent.mkdir(parents=True, exist_ok=True)
            os.replace(staging / name, target)
            written.append(target)
    except OSError as error:
        raise ValueError(
            _("out: cannot write into {out} ({reason})").format(
                out=out, reason=error.strerror or error
            )
        ) from None
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return written


def _grader_reference(name: str) -> Callable[..., Any] | None:
    """The declared grader's answer to the exercise whose function is ``name``, or None."""
    from course.check.exercises import declared
    from course.classroom.exercise_list import course_exercises

    try:
        found = declared(name)
    except LookupError:
        course_exercises()  # imports every chapter's checkers, which declares them
        try:
            found = declared(name)
        except LookupError:
            return None
    return found.grader_reference


def reference(name: str) -> Callable[..., Any]:
    """The grader's answer to the exercise whose function is ``name``, as its checker declares.

    Examples
    --------
    >>> reference("comb")(5, 2)
    10
    """
    found = _grader_reference(name) if isinstance(name, str) else None
    if found is None:
        raise ValueError(
            _(
                "name: expected an exercise whose checker declares a grader_reference; "
                "got {name:.60}"
            ).format(name=repr(name))
        )
    return found


@contextmanager
def earlier_exercises(function: Any, *names: str) -> Iterator[None]:
    """Within the block, the earlier exercises ``names`` are their graders' answers.

    The names are replaced in ``function``'s globals, the notebook's
    namespace, so the student's function and every helper of theirs call the
    reference; the student's own are put back on leaving, even on an error.
    A ``function`` that is not a Python function is left to the checker,
    which reports it.

    Examples
    --------
    >>> def next_level(control_points, t):
    ...     return control_points  # wrong
    >>> def curve(control_points, t):
    ...     return next_level(control_points, t)
    >>> import numpy as np
    >>> with earlier_exercises(curve, "next_level"):
    ...     curve(np.array([[0.0, 0.0], [2.0, 4.0]]), 0.5).tolist()
    [[1.0, 2.0]]
    >>> curve(np.array([[0.0, 0.0], [2.0, 4.0]]), 0.5).tolist()
    [[0.0, 0.0], [2.0, 4.0]]
    """
    namespace = getattr(function, "__globals__", None)
    if not isinstance(namespace, dict):
        yield
        return
    missing = object()
    saved = {name: namespace.get(name, missing) for name in names}
    references = {name: reference(name) for name in names}
    namespace.update(references)
    try:
        yield
    finally:
        for name, value in saved.items():
            if value is missing:
                namespace.pop(name, None)
            else:
                namespace[name] = value
