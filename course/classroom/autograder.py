"""The grade nbgrader saves: each exercise checked outside the student's kernel.

``nbgrader autograde`` runs a student's notebook in a kernel, then saves each check cell's
points from its outputs (an error costs the points; so does any line on stderr). The two
steps ``make nbgrader``'s ``nbgrader_config.py`` installs change that:
:class:`ExecuteAnswers` runs the notebook as nbgrader does but for the check cells of the
declared exercises, and then :class:`CheckOutsideKernel` grades each of those exercises in
nbgrader's own process:

- it takes the student's answer cells from the notebook by nbgrader's grade ids (the
  exercise's and the earlier ones', whose helpers it may use) and runs them in a fresh
  child process (:mod:`course.check.outside`: a clean interpreter without ``course``, under
  the operating system's limits), with the lesson's constants the answer uses (the
  matrices the lesson imports, read from the teacher's lesson) and, for an earlier exercise
  it calls, the grader's own answer, so that a mistake is charged once;
- it runs the exercise's checker on that function's stand-in, with cases drawn for this
  submission (:mod:`course.check.grading`: the student and the assignment seed them);
- it replaces the check cell's outputs with the verdict: the report (whose metadata the
  class's mistakes report reads), what the student's code printed or warned as plain
  text, and on a wrong answer the error that costs the point.

Whatever the student's kernel printed in the check cell is gone: a checker patched in the
kernel, a frame walk, an input transformer or a warning on stderr cannot move the points.

Runs only inside nbgrader (``UNCHECKED = True``).
"""

from __future__ import annotations

import ast
import importlib
import inspect
import textwrap
from collections import Counter
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
from nbformat.notebooknode import NotebookNode, from_dict
from nbgrader.preprocessors import Execute, NbGraderPreprocessor
from traitlets import List, Unicode

from course.check.exercises import declared
from course.check.grading import grading, submission_seed
from course.check.results import CheckResult
from course.classroom.edition import cell_source, read_notebook
from course.classroom.exercise_list import course_exercises
from course.classroom.notebooks import NOTEBOOKS
from course.i18n import _

__all__ = ["CheckOutsideKernel", "ExecuteAnswers", "grade_exercise", "lesson_constants"]

UNCHECKED = True  # see the module docstring

_TEST = "_test"


def _grading(cell: Mapping[str, Any]) -> dict[str, Any]:
    return dict(cell.get("metadata", {}).get("nbgrader", {}))


def _free_names(source: str) -> set[str]:
    """The names ``source`` reads but does not define (a cell that does not parse: none)."""
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return set()
    defined, used = set(), set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            defined.add(node.name)
        elif isinstance(node, ast.arg):
            defined.add(node.arg)
        elif isinstance(node, ast.Name):
            (defined if isinstance(node.ctx, ast.Store) else used).add(node.id)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            defined.update((alias.asname or alias.name).split(".")[0] for alias in node.names)
    return used - defined


def lesson_constants(assignment: str) -> dict[str, Any]:
    """The arrays and numbers the teacher's lesson ``assignment`` imports from the library by
    name (``from course.halftone.dither import ORDERED_MATRIX as M``): what an answer may
    read as the lesson gives it. Functions are left out: an answer writes its own.

    Examples
    --------
    >>> lesson_constants("07_filtering")["SOBEL_X"].tolist()[0]
    [-1, 0, 1]
    """
    path = NOTEBOOKS / f"{assignment}.ipynb"
    if not path.is_file():
        return {}
    found: dict[str, Any] = {}
    for cell in read_notebook(path)["cells"]:
        if cell["cell_type"] != "code":
            continue
        try:
            tree = ast.parse(cell_source(cell))
        except SyntaxError:
            continue
        for node in tree.body:
            if not (isinstance(node, ast.ImportFrom) and (node.module or "").startswith("course")):
                continue
            module = importlib.import_module(node.module or "")
            for alias in node.names:
                value = getattr(module, alias.name, None)
                if isinstance(value, (np.ndarray, int, float)) and not isinstance(value, bool):
                    found[alias.asname or alias.name] = value
    return found


def _graders_answers(earlier: list[str], used: set[str]) -> str:
    """A cell with every earlier exercise's grader answer (one may call another), and the
    lines that bind the names the answer uses to them (``next_level = _graded_next_level``)."""
    sources, bindings = ["from __future__ import annotations"], []
    for function in earlier:
        answer = declared(function).grader_reference
        if answer is None:
            continue
        sources.append(textwrap.dedent(inspect.getsource(answer)))
        if function in used:
            bindings.append(f"{function} = {answer.__name__}")
    return "\n\n".join([*sources, *bindings])


def grade_exercise(
    notebook: Mapping[str, Any],
    function: str,
    seed: int,
    assignment: str = "",
    paths: Sequence[str] = (),
) -> tuple[CheckResult, list[str]]:
    """The checker's result on the student's ``function`` of ``notebook``, run outside this
    process with cases drawn from ``seed``, and what their code printed or warned."""
    from course.check.outside import outside_function

    course_exercises()  # every chapter's checkers declared
    declaration = declared(function)
    answers = [
        (_grading(cell).get("grade_id"), cell_source(cell))
        for cell in notebook["cells"]
        if _grading(cell).get("solution") and cell["cell_type"] == "code"
    ]
    names = [grade_id for grade_id, _source in answers]
    if function not in names:
        return CheckResult(
            declaration.name,
            False,
            0,
            _("the notebook has no answer cell for {function}").format(function=function),
        ), []
    position = names.index(function)
    earlier = [name for name in names[:position] if name and _has_declaration(name)]
    own = answers[position][1]
    graders = _graders_answers(earlier, used=_free_names(own))
    free = set().union(*(_free_names(source) for _name, source in answers[: position + 1]))
    constants = lesson_constants(assignment)
    given = {name: constants[name] for name in free if name in constants}
    cells = [source for _name, source in answers[:position]] + [graders, own]
    stand_in = outside_function(cells, function, given, paths=paths)
    try:
        with grading(seed):
            result = declaration.checker(stand_in)
    finally:
        stand_in.close()
    outside = stand_in.outside
    return result, _once([text for text in outside.printed if text.strip()] + outside.warned)


def _once(said: list[str]) -> list[str]:
    r"""What the code said, each text once (a print in the function says it every case), with
    how many times it was said.

    Examples
    --------
    >>> _once(["level 2", "level 2", "done"])
    ['level 2\n(said 2 times)', 'done']
    """
    counts = Counter(said)
    return [
        text
        if counts[text] == 1
        else _("{text}\n(said {count} times)").format(text=text.rstrip("\n"), count=counts[text])
        for text in counts
    ]


def _graded_outside(cell: Mapping[str, Any]) -> str | None:
    """The exercise whose check cell ``cell`` is, if :class:`CheckOutsideKernel` grades it.

    None for every other cell, a check cell of the teacher's own among them. The
    chapters' checkers must be declared (:func:`course_exercises`).
    """
    grade_id = str(_grading(cell).get("grade_id", ""))
    if cell.get("cell_type") != "code" or not _grading(cell).get("grade"):
        return None
    if not grade_id.endswith(_TEST):
        return None
    function = grade_id[: -len(_TEST)]
    return function if _has_declaration(function) else None


def _has_declaration(name: str) -> bool:
    try:
        declared(name)
    except LookupError:
        return False
    return True


def _shown(data: dict[str, str]) -> dict[str, Any]:
    return {"output_type": "display_data", "data": data, "metadata": {}}


def _verdict(result: CheckResult, said: list[str]) -> list[NotebookNode]:
    """The check cell's outputs: the report, what the code said, and the error of a failure."""
    report = {"text/plain": str(result)}
    outputs = [
        {
            "output_type": "display_data",
            "data": report,
            "metadata": {"course": {"check": result.outcome()}},
        }
    ]
    if result.picture is not None:
        import base64

        picture = base64.b64encode(result.picture).decode("ascii")
        outputs.append(_shown({"image/png": picture}))
    if said:
        heading = _("What your code printed or warned (shown, never graded):")
        outputs.append(_shown({"text/plain": "\n".join([heading, *said])}))
    if not result.passed:
        first = str(result).splitlines()[0]
        outputs.append(
            {
                "output_type": "error",
                "ename": "CheckFailed",
                "evalue": first,
                "traceback": [f"CheckFailed: {first}"],
            }
        )
    return [from_dict(output) for output in outputs]


class CheckOutsideKernel(NbGraderPreprocessor):
    """nbgrader's step that grades each check cell outside the student's kernel."""

    child_paths = List(
        Unicode(),
        default_value=[],
        help="Folders the child process may import from besides numpy's (none: no course).",
    ).tag(config=True)

    grading_secret = Unicode(
        "",
        help="The teacher's secret the graded cases are drawn from, with the student and the "
        "assignment (empty: a student who knows the names can draw them too).",
    ).tag(config=True)

    def preprocess(self, nb: NotebookNode, resources: dict) -> tuple[NotebookNode, dict]:
        grading_of = resources.get("nbgrader", {})
        student = str(grading_of.get("student", ""))
        assignment = str(grading_of.get("assignment", ""))
        if not self.grading_secret:
            self.log.warning(
                "CheckOutsideKernel.grading_secret is not set: a student can draw the graded "
                "cases in their kernel (python -m course nbgrader writes one into a new "
                "nbgrader_config.py)"
            )
        seed = submission_seed(student, assignment, self.grading_secret)
        course_exercises()  # every chapter's checkers declared, in nbgrader's fresh process
        for cell in nb.cells:
            function = _graded_outside(cell)
            if function is None:
                continue
            try:
                result, said = grade_exercise(nb, function, seed, assignment, self.child_paths)
            except Exception as error:  # the grader's own failure: loud, in the log and cell
                self.log.error("grading %s of %s failed: %r", function, student, error)
                result, said = CheckResult(function, False, 0, f"the grader failed: {error}"), []
            cell.outputs = _verdict(result, said)
        return nb, resources


class ExecuteAnswers(Execute):
    """nbgrader's Execute, but for the check cells :class:`CheckOutsideKernel` grades.

    Their outputs are the verdict :class:`CheckOutsideKernel` writes, whatever the kernel
    printed: run in the kernel too, a check would only cost its time (1.7 s of a lesson 01
    submission's 7.6 s). Such a cell is left with an error, which costs its points unless
    :class:`CheckOutsideKernel` replaces it: without that step, nothing is graded by
    mistake. The student's answers and every other cell run as nbgrader runs them; a
    check cell of the teacher's own, for no declared exercise, too.
    """

    def preprocess(
        self, nb: NotebookNode, resources: dict | None = None, km: Any = None
    ) -> tuple[NotebookNode, dict]:
        course_exercises()  # every chapter's checkers declared, in nbgrader's fresh process
        return super().preprocess(nb, resources, km)

    def preprocess_cell(
        self, cell: NotebookNode, resources: dict, index: int
    ) -> tuple[NotebookNode, dict]:
        function = _graded_outside(cell)
        if function is None:
            return super().preprocess_cell(cell, resources, index)
        cell.outputs = [_not_graded(function)]
        return cell, resources


def _not_graded(function: str) -> NotebookNode:
    """The error a check cell holds until :class:`CheckOutsideKernel` writes its verdict."""
    message = _(
        "{function} is graded outside the kernel by CheckOutsideKernel, which did not run: "
        "add it to the autograde steps, as the course's nbgrader_config.py does"
    ).format(function=function)
    return from_dict(
        {"output_type": "error", "ename": "NotGraded", "evalue": message, "traceback": [message]}
    )
