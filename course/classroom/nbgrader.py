"""The nbgrader edition: the lessons as an nbgrader course folder, from their ``solution`` tags.

``python -m course nbgrader --out DIR`` (``make nbgrader``) writes
``DIR/nbgrader_config.py`` and ``DIR/source/<lesson>/<lesson>.ipynb`` for
each lesson with exercises. Plain nbgrader then takes it from there:
``nbgrader generate_assignment <lesson>``, ``autograde``,
``generate_feedback``.

The lessons' sources are :func:`course.classroom.release.nbgrader_notebook`: each exercise
an answer cell and a locked, autograded check cell worth :data:`EXERCISE_POINTS`, whose
report is the feedback. ``nbgrader generate_assignment`` releases exactly the student
edition (:func:`course.classroom.release.student_notebook`), so students may work in the
edition ``make lab``, the hub or a link gives them, and submit it.

A mistake is charged once. An exercise that calls an earlier one
(lesson 01's ``recursive_bezier`` calls ``next_level``) is graded with the
earlier exercise's ``grader_reference``, which its checker declares
(:func:`course.check.exercises.exercise`; :func:`earlier_exercises`).
"""

from __future__ import annotations

import os
import secrets
import shutil
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from course.classroom.edition import notebook_language, notebook_text, read_notebook
from course.classroom.folders import check_output_folder, require_inside
from course.classroom.notebooks import DEFAULT_LANGUAGE, NOTEBOOKS, notebooks
from course.classroom.release import (
    EXERCISE_POINTS,
    Exercise,
    exercises,
    nbgrader_notebook,
)
from course.classroom.stubs import stub_line
from course.i18n import _

__all__ = [
    "EXERCISE_POINTS",
    "Exercise",
    "earlier_exercises",
    "exercises",
    "nbgrader_notebook",
    "reference",
    "write_nbgrader_course",
]

CONFIG = '''"""nbgrader's configuration for the course, written by `python -m course nbgrader`."""

c = get_config()  # noqa: F821 (nbgrader defines it)
c.CourseDirectory.course_id = "course"
# The release shows the same stub as the student edition.
c.ClearSolutions.code_stub = {{"python": {stub!r}}}
# A lesson's pictures and apps take a while to compute in a fresh kernel.
c.Execute.timeout = 600
# Each exercise graded outside the student's kernel (course.classroom.autograder), right
# after nbgrader has run the notebook but for its check cells: their points are its verdicts.
from course.classroom.autograder import CheckOutsideKernel, ExecuteAnswers  # noqa: E402
from nbgrader.converters import Autograde  # noqa: E402
from nbgrader.preprocessors import Execute  # noqa: E402

_steps = list(Autograde.class_traits()["autograde_preprocessors"].make_dynamic_default())
_at = _steps.index(Execute)
_steps[_at : _at + 1] = [ExecuteAnswers, CheckOutsideKernel]
c.Autograde.autograde_preprocessors = _steps
# The graded cases are drawn from this secret, the student and the lesson: keep this file
# where students cannot read it. A new secret draws new cases for every submission.
c.CheckOutsideKernel.grading_secret = {secret!r}
# nbgrader zip_collect: a learning platform's download, each upload named
# <student>_<lesson>.ipynb (01_de_casteljau's by alice: alice_01_de_casteljau.ipynb);
# change the rule to your platform's file names.
c.FileNameCollectorPlugin.named_regexp = {collect!r}
'''
#: How ``nbgrader zip_collect`` reads a student and a lesson from an uploaded file's path.
UPLOAD_NAME = r".*/(?P<student_id>[^/_]+)_(?P<file_id>\d\d_\w+)\.ipynb$"


def write_nbgrader_course(
    out: str | Path, folder: str | Path = NOTEBOOKS, force: bool = False
) -> list[Path]:
    """Write an nbgrader course folder for the lessons in ``folder`` into ``out``.

    ``out/nbgrader_config.py`` and ``out/source/<lesson>/<lesson>.ipynb`` for
    each lesson with exercises. Refuses a non-empty ``out`` unless ``force``
    (then the lessons' sources are replaced, a teacher's
    ``nbgrader_config.py`` is kept, nothing is deleted). Every
    lesson is converted before anything is written, and the files are
    written to a temporary folder first, then moved into place. A symbolic
    link under ``out`` (``source/``, say) that leads outside it is refused.
    """
    check_output_folder(out, force)
    out = Path(out)
    files: dict[str, str] = {}
    language = DEFAULT_LANGUAGE
    for book in notebooks(folder):
        notebook = read_notebook(book.path)
        language = notebook_language(notebook)
        try:
            found = exercises(notebook)
            if not found:
                continue
            _require_grader_references(found)
            converted = nbgrader_notebook(notebook)
        except ValueError as error:
            raise ValueError(_("{path}: {error}").format(path=book.path, error=error)) from None
        lesson = book.path.stem
        files[f"source/{lesson}/{lesson}.ipynb"] = notebook_text(converted)
    if not (out / "nbgrader_config.py").exists():
        # The release's stubs are the student edition's, in the lessons' language.
        files["nbgrader_config.py"] = CONFIG.format(
            stub=stub_line(language), collect=UPLOAD_NAME, secret=secrets.token_hex(16)
        )
    require_inside(out, [out / name for name in files])  # source/ may be a link
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


def _require_grader_references(found: list[Exercise]) -> None:
    """A ValueError naming the cell of an exercise that calls an earlier one whose checker
    declares no grader answer to check it with."""
    for exercise in found:
        unreferenced = [name for name in exercise.uses if _grader_reference(name) is None]
        if unreferenced:
            raise ValueError(
                _(
                    "notebook cell {index}: {function} calls the earlier exercise {unreferenced}, "
                    "whose checker declares no grader_reference to grade it with"
                ).format(
                    index=exercise.cell, function=exercise.function, unreferenced=unreferenced[0]
                )
            )


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
