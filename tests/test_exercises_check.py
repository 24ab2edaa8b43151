"""course.check.exercises: an exercise is declared once, and a part left out fails by name.

An exercise is its solution cell in the notebook and its declared checker in the chapter.
These tests hold the two together, so that a contributor who forgets a part is told which:
a cell whose checker is not declared, a checker no cell calls, a checker that runs cases but
was never declared, a hint a report points to that does not answer.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import re
from pathlib import Path
from typing import Any

import graded_draws
import numpy as np
import pytest

from course.check.exercises import Exercise, declared, exercise, refused_messages
from course.check.hints import Hints, hint
from course.classroom.exercise_list import course_exercises
from course.classroom.nbgrader import exercises as notebook_exercises
from course.classroom.notebooks import notebooks
from course.classroom.registry import lesson_modules

DECLARED = course_exercises()
ALL = [declaration for chapter in DECLARED.values() for declaration in chapter]
BOOKS = {book.number: book for book in notebooks() if book.number in DECLARED}


def chapter_of(number: str) -> str:
    return lesson_modules()[number].rsplit(".", 1)[0]


def solution_calls(number: str) -> list[tuple[str, str]]:
    """(checker, function) of each solution cell's ``check.<checker>(<function>)``."""
    import json

    notebook = json.loads(Path(BOOKS[number].path).read_text(encoding="utf-8"))
    calls = []
    for found in notebook_exercises(notebook):
        checker = re.fullmatch(r"check\.(\w+)\((\w+)\)", found.check)
        assert checker, f"lesson {number}: {found.check} is not check.<name>(<function>)"
        calls.append((checker.group(1), checker.group(2)))
    return calls


@pytest.mark.parametrize("number", sorted(BOOKS))
def test_every_solution_cell_calls_a_checker_its_chapter_declares(number):
    names = {declaration.name: declaration for declaration in DECLARED[number]}
    for checker, function in solution_calls(number):
        assert checker in names, (
            f"lesson {number}: the notebook's check.{checker} is not declared in "
            f"{chapter_of(number)}.check: decorate it with @exercise(hints=..., refuses=...)"
        )
        assert function == checker, (
            f"lesson {number}: check.{checker} checks {function} in the notebook: an exercise "
            "has one name, the student's function is named as its checker"
        )


@pytest.mark.parametrize("number", sorted(BOOKS))
def test_every_declared_exercise_has_exactly_one_solution_cell(number):
    called = [checker for checker, _function in solution_calls(number)]
    for declaration in DECLARED[number]:
        assert called.count(declaration.name) == 1, (
            f"lesson {number}: {declaration.name} is declared in {declaration.module} but "
            f"{called.count(declaration.name)} solution cells call it"
        )


def test_every_checker_that_runs_cases_is_declared():
    """A checker without its declaration would run with no hints and refuse nothing."""
    for number in DECLARED:
        module = importlib.import_module(f"{chapter_of(number)}.check")
        tree = ast.parse(inspect.getsource(module))
        for node in tree.body:
            if not isinstance(node, ast.FunctionDef) or node.name.startswith("_"):
                continue
            runs = any(
                isinstance(call, ast.Call) and getattr(call.func, "id", None) == "run_cases"
                for call in ast.walk(node)
            )
            if runs:
                assert isinstance(
                    getattr(getattr(module, node.name), "exercise", None), Exercise
                ), (
                    f"{module.__name__}.{node.name} runs cases but is not declared: "
                    "decorate it with @exercise(hints=..., refuses=...)"
                )


@pytest.mark.parametrize("declaration", ALL, ids=lambda d: d.name)
def test_each_checker_is_public_and_names_the_handouts_mistakes(declaration):
    """In its module's __all__ (the fuzz test and the docs find it), and with mistakes to name."""
    module = importlib.import_module(declaration.module)
    assert declaration.name in module.__all__, (
        f"{declaration.module}: add {declaration.name!r} to __all__"
    )
    tree = ast.parse(inspect.getsource(declaration.checker))
    calls = [
        call
        for call in ast.walk(tree)
        if isinstance(call, ast.Call) and getattr(call.func, "id", None) == "run_cases"
    ]
    assert any(keyword.arg == "mistakes" for call in calls for keyword in call.keywords), (
        f"{declaration.name}: its run_cases names no mistakes=: the handouts' known mistakes, "
        "reproduced, are how a report says which one the student made"
    )


@pytest.mark.parametrize("declaration", ALL, ids=lambda d: d.name)
def test_each_name_of_an_exercise_finds_its_hints(declaration):
    assert declared(declaration.name) is declaration
    for name in (declaration.name, *declaration.handout_names):
        assert str(hint(name)).startswith("Hint for "), name


@pytest.mark.parametrize("declaration", ALL, ids=lambda d: d.name)
def test_a_failure_points_to_a_hint_that_answers(declaration):
    """A wrong answer's report ends with check.hint("..."): that call must work."""

    def forgets_to_return(*args):
        return None

    report = str(declaration.checker(forgets_to_return))
    asked = re.findall(r'check\.hint\("(\w+)"', report)
    assert asked, report
    for name in asked:
        assert hint(name).text


@pytest.mark.parametrize("declaration", ALL, ids=lambda d: d.name)
def test_each_exercise_refuses_the_library_s_answers_by_name(declaration):
    messages = refused_messages(declaration)
    assert messages
    for function, message in messages.items():
        assert function.__name__ in message, message


@pytest.mark.parametrize("declaration", ALL, ids=lambda d: d.name)
def test_each_exercise_draws_the_cases_a_submission_is_graded_on(declaration):
    """Graded, a checker runs on cases drawn from the submission's seed, not the fixed ones."""
    where = f"{declaration.module}.{declaration.name}"
    assert declaration.draw is not None, (
        f"{where} declares no draw=: give @exercise a draw(rng) that draws, from the numpy "
        "Generator rng, cases like its fixed ones (CONTRIBUTING.md, 'Add an exercise'); graded, "
        "the checker runs on those"
    )
    fixed = graded_draws.recorded(declaration)["cases"]
    drawn = list(declaration.draw(np.random.default_rng(0)))
    assert [list(case) for case in drawn] == [list(case) for case in fixed], (
        f"{where}: its draw(rng) must give as many cases as the fixed ones, {len(fixed)}, "
        f"each with the same keys in the same order, {list(fixed[0])}"
    )


def test_a_declaration_that_leaves_out_its_hints_or_refusals_fails_by_name():
    with pytest.raises(TypeError, match="hints"):
        exercise(refuses=(abs,))  # type: ignore[call-arg]
    with pytest.raises(TypeError, match="refuses"):
        exercise(hints=Hints("a", "b", "c"))  # type: ignore[call-arg]
    with pytest.raises(
        ValueError, match=r"\.blank_recipe: hints: every step says something; recipe"
    ):

        @exercise(hints=Hints("a", "b", " "), refuses=(abs,))
        def blank_recipe(student):
            return student

    with pytest.raises(ValueError, match="refuses must name at least one"):
        exercise(hints=Hints("a", "b", "c"), refuses=())
    with pytest.raises(LookupError, match="not a declared exercise"):
        declared("no_such_exercise")


def test_the_list_of_exercises_is_the_declarations():
    """Nothing counts them by hand: every lesson with exercises is found, in lesson order."""
    assert list(DECLARED) == sorted(DECLARED)
    assert set(DECLARED) == set(BOOKS)
    assert all(len(chapter) >= 2 for chapter in DECLARED.values())  # teaching.md's budget


TOY_CHECK = '''
"""Lesson 09's toy exercise, made by a test as CONTRIBUTING.md's recipe says."""

from course.check.base import CheckResult, close, hint, run_cases
from course.check.exercises import exercise
from course.check.hints import Hints
from course.curves import bezier

__all__ = ["hint", "twice"]

TWICE_HINTS = Hints(where="look at x.", more="it is doubled.", recipe="return 2 * x")


@exercise(hints=TWICE_HINTS, refuses=(bezier.binomial,), handout_names=("Twice",))
def twice(student) -> CheckResult:
    """Check ``student(x)`` -> 2 x."""
    return run_cases("twice", student, [{"x": 1.0}, {"x": 2.5}], lambda x: 2 * x, close())
'''

TOY_LESSON = '''
"""Lesson 09's registry entry."""

from course.classroom.registry import Lesson

LESSON = Lesson(handout="Lab 9, Task 1", teaches="doubling a number")
'''


def toy_notebook(path: Path) -> Path:
    import json

    def cell(kind, source, tags=()):
        found = {"cell_type": kind, "id": f"{kind}-{len(source)}", "metadata": {}, "source": source}
        if tags:
            found["metadata"]["tags"] = list(tags)
        if kind == "code":
            found |= {"outputs": [], "execution_count": None}
        return found

    cells = [
        cell("markdown", "# Lesson 09 · Doubling\n\nWrite `twice`."),
        cell("code", "from course.lessons.l09_toy import check"),
        cell(
            "code",
            'def twice(x):\n    """Twice x."""\n    return 2 * x\n\n\ncheck.twice(twice)',
            tags=["solution"],
        ),
    ]
    path.write_text(
        json.dumps({"cells": cells, "metadata": {}, "nbformat": 4, "nbformat_minor": 5})
    )
    return path


@pytest.fixture
def toy_chapter(tmp_path, monkeypatch):
    """A chapter with one exercise, and its notebook, in a temporary folder only."""
    import sys

    import course.lessons

    chapter = tmp_path / "modules" / "l09_toy"
    chapter.mkdir(parents=True)
    (chapter / "__init__.py").write_text('"""Lesson 09 · Doubling."""\n')
    (chapter / "lesson.py").write_text(TOY_LESSON)
    (chapter / "check.py").write_text(TOY_CHECK)
    monkeypatch.setattr(course.lessons, "__path__", [*course.lessons.__path__, str(chapter.parent)])
    books = tmp_path / "notebooks"
    books.mkdir()
    yield toy_notebook(books / "09_toy.ipynb")
    for name in ("", ".lesson", ".check"):
        sys.modules.pop(f"course.lessons.l09_toy{name}", None)


def test_the_add_an_exercise_recipe_is_picked_up_everywhere(toy_chapter):
    """CONTRIBUTING.md's recipe: a checker and a cell, and every derived part follows."""
    import json

    import mutation

    from course.classroom import twins
    from course.classroom.release import nbgrader_notebook, student_notebook

    toy = course_exercises()["09"]
    assert [e.name for e in toy] == ["twice"]  # the list of exercises
    assert str(hint("Twice")) == "Hint for twice: look at x. It is doubled."  # the hint table
    check = importlib.import_module("course.lessons.l09_toy.check")
    assert check.twice(lambda x: 2 * x)
    refused = check.twice(lambda x: 2 * x + 0 * bezier_binomial(2, 1))
    assert "your function calls course.curves.binomial" in str(refused)  # the refused names

    notebook = json.loads(toy_chapter.read_text())
    student = "".join(student_notebook(notebook)["cells"][2]["source"])  # the student edition
    assert "def twice(x):" in student and "return 2 * x" not in student
    graded = nbgrader_notebook(notebook)  # the nbgrader source: an answer cell, a check cell
    test_cells = [
        c for c in graded["cells"] if c.get("metadata", {}).get("nbgrader", {}).get("grade")
    ]
    assert [c["metadata"]["nbgrader"]["grade_id"] for c in test_cells] == ["twice_test"]
    assert "check.twice(twice).graded()" in "".join(test_cells[0]["source"])

    found = mutation.find_exercises([toy_chapter])  # the mutation test
    assert [(e.checker, e.function) for e in found] == [("twice", "twice")]
    assert mutation.mutants(found[0])

    po_path = toy_chapter.parent / "zh-CN" / "09_toy.po"  # the Chinese twin
    assert twins.update_catalog(toy_chapter, po_path) == (2, 0)  # the markdown, the docstring
    twin, report = twins.build_twin(toy_chapter, twins.read_catalog(po_path))
    ids = [cell["id"] for cell in notebook["cells"]]
    assert report.untranslated == [ids[0], f"{ids[2]}:docstring"]
    assert twins.english_code(twin)[1] == "".join(notebook["cells"][2]["source"])


def bezier_binomial(n, k):
    from course.curves import bezier

    return bezier.binomial(n, k)


# --- every library function that answers an exercise is refused ------------------------------


def _library_functions() -> dict[str, Any]:
    """The library's public functions (not the lessons', the checkers' or the classroom's)."""
    import test_fuzz

    shared = (
        "course.lessons",
        "course.check",
        "course.classroom",
        "course.widgets",
        "course.limits",
    )
    return {
        name: value
        for name, value in test_fuzz.CALLABLES.items()
        if inspect.isfunction(value) and not name.startswith(shared)
    }


def _takes(function: Any, count: int) -> bool:
    """Whether ``function`` can be called with ``count`` positional arguments."""
    parameters = list(inspect.signature(function).parameters.values())
    if any(p.kind == p.VAR_POSITIONAL for p in parameters):
        return True
    positional = [p for p in parameters if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    required = [p for p in positional if p.default is p.empty]
    keyword_only = [p for p in parameters if p.kind == p.KEYWORD_ONLY and p.default is p.empty]
    return len(required) <= count <= len(positional) and not keyword_only


def _notebook_exercises() -> list[Any]:
    import mutation

    return mutation.find_exercises()


@pytest.mark.parametrize("found", _notebook_exercises(), ids=lambda e: e.checker)
def test_no_library_function_passes_a_checker_unrefused(found):
    """A refused list that leaves out a library function answering the exercise is caught:
    a student's function that only calls it (with the same arguments) must not pass.

    Every public function of the library that takes the student's arguments is tried, as a
    student would write it: ``def <function>(<args>): return <module>.<name>(<args>)``.
    """
    import contextlib
    import io
    import warnings

    import mutation

    tree = ast.parse(found.source)
    definition = next(
        s for s in tree.body if isinstance(s, ast.FunctionDef) and s.name == found.function
    )
    arguments = ", ".join(a.arg for a in definition.args.args)
    passing = []
    for qualified, function in _library_functions().items():
        if not _takes(function, len(definition.args.args)):
            continue
        module, name = qualified.rsplit(".", 1)
        answer = (
            f"import {module}\n\n\ndef {found.function}({arguments}):\n"
            f"    return {module}.{name}({arguments})\n"
        )
        namespace: dict[str, Any] = {"__name__": "__student__"}
        with (
            contextlib.redirect_stdout(io.StringIO()),
            contextlib.redirect_stderr(io.StringIO()),
            warnings.catch_warnings(),
        ):
            warnings.simplefilter("ignore")
            exec(found.setup, namespace)
            exec(found.source, namespace)
            exec(answer, namespace)
            result = eval(found.call, namespace)
        if mutation.classify(result)[0] == "survived":
            passing.append(qualified)
    assert not passing, (
        f"check.{found.checker} passes a function that only calls {passing}: add them to its "
        "@exercise(refuses=...) (course.check.exercises)"
    )


# --- one name per exercise --------------------------------------------------------------
# One name per exercise: the student's function, its checker, its report and its hint key.
#
# The course map tells a student that every exercise ends with ``check.name(name)``: the function
# they write is checked by ``check.<name>``, the report opens with ``FAIL <name>:`` and the hint
# is ``check.hint("<name>")``. A second name for any of them is one more thing to get wrong.

EVERY_EXERCISE = [exercise for chapter in course_exercises().values() for exercise in chapter]


def not_written_yet(*arguments):
    """The student edition's stub."""
    raise NotImplementedError("your code here")


def forgets_to_return(*arguments):
    """A first try: a wrong answer, whose report ends with a hint."""
    return None


@pytest.mark.parametrize("declaration", EVERY_EXERCISE, ids=lambda d: d.name)
def test_an_exercise_has_one_name(declaration):
    name = declaration.name
    module = importlib.import_module(declaration.module)
    assert getattr(module, name) is declaration.checker, f"check.{name} is not its checker"
    report = declaration.checker(forgets_to_return)
    assert report.exercise == name and str(report).startswith(f"FAIL {name}:"), str(report)
    asked = re.findall(r'check\.hint\("([^"]+)"', str(report))
    assert asked == [name], f"{name}: its report points to check.hint{tuple(asked)}"
    assert hint(name).exercise == name


RENAMED = {
    "l04_supersampling": ("supersample", "bilinear_sample"),
    "l05_antialiasing": ("splat",),
    "l06_dithering": ("dithering_ordered", "dithering_error_diffuse"),
    "l07_filtering": ("blur", "edge"),
    "l08_poisson": ("boundary_ring", "jacobi_solve"),
}


@pytest.mark.parametrize("chapter", sorted(RENAMED))
def test_the_renamed_exercises_answer_to_their_function_names_only(chapter):
    check = importlib.import_module(f"course.lessons.{chapter}.check")
    for name in RENAMED[chapter]:
        assert getattr(check, name).exercise.name == name
        assert str(getattr(check, name)(not_written_yet)).startswith(f"FAIL {name}:")
    # The second names they had are gone: no checker answers to them.
    for old in ("bilinear_splat", "blur_exercise", "Edge", "boundary_exercise", "jacobi_sweep"):
        with pytest.raises(LookupError):
            declared(old)


@pytest.mark.parametrize(
    ("handout_name", "name"),
    [
        ("DitheringOrdered", "dithering_ordered"),
        ("DitheringErrorDiffuse", "dithering_error_diffuse"),
        ("Blur", "blur"),
        ("Edge", "edge"),
    ],
)
def test_a_labs_own_name_still_finds_the_hint(handout_name, name):
    course_exercises()
    assert hint(handout_name).exercise == name


def test_the_course_map_tells_a_student_the_one_name():
    from course.classroom.course_map import EXERCISE_GUIDE

    assert "`check.name(name)`" in EXERCISE_GUIDE and '`check.hint("name")`' in EXERCISE_GUIDE


def test_a_notebook_without_the_answer_is_graded_under_the_one_name():
    from course.classroom.autograder import grade_exercise

    result, printed = grade_exercise({"cells": []}, "blur", seed=0)
    assert not result and printed == []
    assert str(result).startswith("FAIL blur:"), str(result)
    assert "no answer cell for blur" in str(result)
