"""The nbgrader edition, graded by the real nbgrader: release, autograde, feedback, per lesson.

For each lesson with exercises, nbgrader releases the lesson, then
autogrades three kinds of submission: the teacher's solutions (full
marks), the release as it is (every stub fails), and the checkers' named
mistakes, several at once, one per exercise (each loses exactly its own
exercise's points, even where a later exercise calls the mistaken one).
The feedback must show each failing check's diagnosis.

The submissions keep the lesson's text, its first code cell (the imports)
and its exercise and test cells: the other cells draw pictures, which
grading does not need. Every lesson is released; lesson 01, whose
exercises build on each other, is graded by default (about two minutes),
every lesson with ``COURSE_NBGRADER=all`` (about fifteen), and the whole
lessons, every cell, with ``COURSE_NBGRADER=full``.
"""

from __future__ import annotations

import ast
import json
import os
import re
import site
import sys
from html import unescape
from pathlib import Path

import numpy as np
import pytest
from mistakes import mistaken, named_mistakes
from nbgrader.api import Gradebook
from nbgrader.apps import NbGraderAPI
from traitlets.config import Config
from traitlets.config.loader import PyFileConfigLoader

from course.classroom.edition import cell_source, solution_cells
from course.classroom.nbgrader import (
    EXERCISE_POINTS,
    exercises,
    nbgrader_notebook,
    write_nbgrader_course,
)
from course.classroom.notebooks import NOTEBOOKS, language_folder, notebooks
from course.classroom.release import student_notebook
from course.classroom.stubs import STUB_LINE, exercise_stub, stub_line

REPOSITORY = Path(__file__).resolve().parent.parent
FULL = os.environ.get("COURSE_NBGRADER") == "full"
EVERY_LESSON = os.environ.get("COURSE_NBGRADER") in ("all", "full")
LESSONS = [
    book for book in notebooks() if exercises(json.loads(book.path.read_text(encoding="utf-8")))
]
#: The scores of every lesson, filled in as the tests run and printed at the end (-s).
TABLE: dict[str, dict[str, str]] = {}


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    folder = tmp_path_factory.mktemp("nbgrader")
    write_nbgrader_course(folder)
    return folder


@pytest.fixture(scope="module")
def chinese_course(tmp_path_factory):
    """The nbgrader course of the Chinese twins (make nbgrader COURSE_LANG=zh-CN)."""
    folder = tmp_path_factory.mktemp("nbgrader-zh-CN")
    write_nbgrader_course(folder, language_folder(NOTEBOOKS, "zh-CN"))
    return folder


def test_the_chinese_course_releases_the_chinese_students_stub(course, chinese_course):
    """nbgrader generate_assignment writes the config's stub: the student edition's, in Chinese."""
    chinese = (chinese_course / "nbgrader_config.py").read_text(encoding="utf-8")
    assert f'code_stub = {{"python": {stub_line("zh-CN")!r}}}' in chinese
    english = (course / "nbgrader_config.py").read_text(encoding="utf-8")
    assert f'code_stub = {{"python": {STUB_LINE!r}}}' in english


def nbgrader_api(course: Path) -> NbGraderAPI:
    config = Config()
    config.merge(PyFileConfigLoader("nbgrader_config.py", str(course)).load_config())
    config.CourseDirectory.root = str(course)
    # The planted mistakes are the library's reproductions (tests/mistakes.py): the grader's
    # child may import the course and the tests, which a real class's never does.
    config.CheckOutsideKernel.child_paths = [
        str(REPOSITORY),
        str(REPOSITORY / "tests"),
        *site.getsitepackages(),
    ]
    return NbGraderAPI(config=config)


@pytest.fixture(scope="module")
def api(course):
    # nbgrader runs `alembic` for its database, and the grading kernels import the
    # course and tests/mistakes.py.
    patch = pytest.MonkeyPatch()
    patch.setenv("PATH", f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    paths = [str(REPOSITORY), str(REPOSITORY / "tests"), os.environ.get("PYTHONPATH", "")]
    patch.setenv("PYTHONPATH", os.pathsep.join(filter(None, paths)))
    yield nbgrader_api(course)
    patch.undo()
    if TABLE:
        print("\nlesson | available | solutions | stubs | each named mistake")
        for lesson, row in sorted(TABLE.items()):
            print(
                f"{lesson} | {row['available']} | {row['solutions']} | {row['stubs']} | "
                f"{row['mistakes']}"
            )


def test_each_exercise_becomes_a_solution_cell_and_a_locked_test_cell_worth_its_points():
    book = next(book for book in LESSONS if book.number == "01")
    lesson = json.loads(book.path.read_text(encoding="utf-8"))
    source = nbgrader_notebook(lesson)
    graded = [cell for cell in source["cells"] if "nbgrader" in cell["metadata"]]
    assert [cell["metadata"]["nbgrader"]["grade_id"] for cell in graded] == [
        "next_level", "next_level_test", "recursive_bezier", "recursive_bezier_test",
        "bezier", "bezier_test",
    ]  # fmt: skip
    for solution, test in zip(graded[::2], graded[1::2], strict=True):
        assert solution["metadata"]["nbgrader"]["solution"] is True
        assert solution["metadata"]["nbgrader"]["locked"] is False
        assert test["metadata"]["nbgrader"]["points"] == EXERCISE_POINTS
        assert test["metadata"]["nbgrader"]["locked"] is True
        assert test["source"].splitlines()[-1].strip().endswith(".graded()")
        assert "check." not in solution["source"]  # the check is the locked cell's
    # recursive_bezier calls next_level, and bezier recursive_bezier: checked with the
    # graders' own answers.
    assert "earlier_exercises(recursive_bezier, 'next_level')" in graded[3]["source"]
    assert "earlier_exercises(bezier, 'recursive_bezier')" in graded[5]["source"]
    assert "earlier_exercises" not in graded[1]["source"]
    assert lesson == json.loads(book.path.read_text(encoding="utf-8")), "the lesson is unchanged"


def test_a_solution_cell_whose_check_is_missing_is_refused():
    notebook = {
        "cells": [{"cell_type": "code", "metadata": {"tags": ["solution"]}, "source": "x = 1"}]
    }
    with pytest.raises(ValueError, match=r"ends with its check, check\.<name>\(<function>\)"):
        exercises(notebook)


def solution_lines(teacher: dict) -> set[tuple[str, ...]]:
    """Every three consecutive lines the student edition's stubs take out of the solutions."""
    triples = set()
    for index in solution_cells(teacher):
        source = cell_source(teacher["cells"][index])
        removed = [line.strip() for line in source.splitlines() if line.strip()]
        kept = {line.strip() for line in exercise_stub(source).splitlines()}
        removed = [line for line in removed if line not in kept]
        triples |= {tuple(removed[i : i + 3]) for i in range(len(removed) - 2)}
    return triples


def shown_lines(notebook: dict) -> set[tuple[str, ...]]:
    lines = [
        line.strip()
        for cell in notebook["cells"]
        for line in cell_source(cell).splitlines()
        if line.strip()
    ]
    return {tuple(lines[i : i + 3]) for i in range(len(lines) - 2)}


def submission(released: dict, answers: dict[str, str], ids: set[str]) -> dict:
    """The released lesson with ``answers`` (grade_id -> source) in its solution cells."""
    notebook = json.loads(json.dumps(released))
    kept = []
    first_code = True
    for cell in notebook["cells"]:
        grading = cell["metadata"].get("nbgrader", {})
        grade_id = grading.get("grade_id")
        if grade_id in answers:
            cell["source"] = answers[grade_id]
        keep = FULL or cell["cell_type"] == "markdown" or grade_id in ids or first_code
        if cell["cell_type"] == "code":
            first_code = False
        if keep:
            kept.append(cell)
    notebook["cells"] = kept
    return notebook


def scores(course: Path, lesson: str, student: str) -> dict[str, float]:
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gradebook:
        graded = gradebook.find_submission_notebook(lesson, lesson, student)
        return {grade.name: grade.score for grade in graded.grades}


def released(course: Path, api: NbGraderAPI, lesson: str) -> dict:
    """``nbgrader generate_assignment`` on the lesson, once; its release."""
    path = course / "release" / lesson / f"{lesson}.ipynb"
    if not path.is_file():
        generated = api.generate_assignment(lesson)
        assert generated["success"], generated.get("log")
    return json.loads(path.read_text(encoding="utf-8"))


@pytest.mark.parametrize("book", LESSONS, ids=lambda book: book.path.stem)
def test_nbgraders_release_is_the_student_edition(book, course, api):
    """What nbgrader releases is what make lab, the hub and a link give students, cell for
    cell: sources, ids, tags and nbgrader's metadata, checksums included."""
    teacher = json.loads(book.path.read_text(encoding="utf-8"))
    release = released(course, api, book.path.stem)
    edition = student_notebook(teacher)

    def cells(notebook):
        return [
            (c["cell_type"], c.get("id"), cell_source(c), c["metadata"]) for c in notebook["cells"]
        ]

    assert cells(release) == cells(edition)


@pytest.mark.parametrize("book", LESSONS, ids=lambda book: book.path.stem)
def test_the_release_shows_every_exercise_as_its_stub_and_no_solution(book, course, api):
    teacher = json.loads(book.path.read_text(encoding="utf-8"))
    release = released(course, api, book.path.stem)
    leaked = solution_lines(teacher) & shown_lines(release)
    assert not leaked, f"the release shows solution lines: {sorted(leaked)[:2]}"
    stubs = sum(STUB_LINE in cell_source(cell) for cell in release["cells"])
    assert stubs >= len(exercises(teacher))
    assert all(not cell.get("outputs") for cell in release["cells"])


def code_only(source: str) -> list[str]:
    return [line for line in source.splitlines() if not line.lstrip().startswith("#")]


def graded_cells(notebook: dict) -> list[tuple]:
    """What a gradebook knows of a lesson: each nbgrader cell's id, grade id, kind and points."""
    return [
        (
            cell["cell_type"],
            cell.get("id"),
            *(cell["metadata"]["nbgrader"].get(key) for key in ("grade_id", "points")),
            *(cell["metadata"]["nbgrader"][key] for key in ("grade", "solution", "locked")),
        )
        for cell in notebook["cells"]
        if "nbgrader" in cell["metadata"]
    ]


@pytest.mark.parametrize("book", LESSONS, ids=lambda book: book.path.stem)
def test_the_chinese_release_grades_as_the_english_one_and_shows_no_solution(
    book, course, api, chinese_course
):
    """Same cell ids, grade ids and points: one gradebook could grade either language."""
    lesson = book.path.stem
    twin = language_folder(book.path.parent, "zh-CN") / book.path.name
    teacher = json.loads(twin.read_text(encoding="utf-8"))
    english = released(course, api, lesson)
    chinese = released(chinese_course, nbgrader_api(chinese_course), lesson)
    assert graded_cells(chinese) == graded_cells(english)
    assert graded_cells(english), "the comparison above needs graded cells"
    leaked = solution_lines(teacher) & shown_lines(chinese)
    assert solution_lines(teacher) and not leaked, f"solution lines: {sorted(leaked)[:2]}"
    assert all(not cell.get("outputs") for cell in chinese["cells"])
    english_tests = [cell_source(c) for c in english["cells"] if c["id"].endswith("-test")]
    chinese_tests = [cell_source(c) for c in chinese["cells"] if c["id"].endswith("-test")]
    # The same code; only the comments differ, in Chinese.
    for ours, theirs in zip(chinese_tests, english_tests, strict=True):
        assert code_only(ours) == code_only(theirs) and ours != theirs
        assert "自动评分测试" in ours
    markdown = "".join(cell_source(c) for c in chinese["cells"] if c["cell_type"] == "markdown")
    assert sum("\u4e00" <= letter <= "\u9fff" for letter in markdown) > 100


@pytest.mark.parametrize(
    "book",
    [
        pytest.param(
            book,
            marks=pytest.mark.skipif(
                book.number != "01" and not EVERY_LESSON,
                reason="COURSE_NBGRADER=all grades every lesson (about fifteen minutes)",
            ),
        )
        for book in LESSONS
    ],
    ids=lambda book: book.path.stem,
)
def test_nbgrader_autogrades_and_explains_the_lesson(book, course, api):
    lesson = book.path.stem
    teacher = json.loads(book.path.read_text(encoding="utf-8"))
    found = exercises(teacher)
    chapter = re.search(
        r"from (course\.lessons\.l\d\d_\w+) import check\b",
        "".join(cell_source(cell) for cell in teacher["cells"]),
    ).group(1)
    module = f"{chapter}.check"
    released(course, api, lesson)  # the gradebook knows the lesson
    edition = student_notebook(teacher)  # what the students work in, and submit

    tests = {f"{exercise.function}_test": exercise for exercise in found}
    ids = {exercise.function for exercise in found} | set(tests)
    solutions = {  # each answer cell as the student writes it: the function, no check
        e.function: "\n".join(
            cell_source(teacher["cells"][e.cell]).splitlines()[: e.check_line - 1]
        )
        for e in found
    }
    # The checkers' named mistakes: each exercise's k-th in submission k. A mistake whose
    # answer the checker passes, or names as another, is noted for the table.
    mistakes_of = {}
    notes = []
    for exercise in found:
        checker = exercise.check.split("(")[0].split(".")[1]
        checks_module = __import__(module, fromlist=[checker])
        definition = next(
            node
            for node in ast.parse(solutions[exercise.function]).body
            if isinstance(node, ast.FunctionDef) and node.name == exercise.function
        )
        parameters = [argument.arg for argument in definition.args.args]
        usable = []
        for mistake in named_mistakes(module, checker)[0]:
            result = getattr(checks_module, checker)(
                mistaken(module, checker, mistake.name, parameters)
            )
            if result.passed:
                notes.append(f"{exercise.function} '{mistake.name}' passes its check")
                continue
            if result.mistake != mistake.name:
                notes.append(
                    f"{exercise.function} '{mistake.name}' is named "
                    f"{result.mistake and repr(result.mistake)}"
                )
            first_line = str(result).splitlines()[1].strip()
            code = (
                "from mistakes import mistaken\n\n"
                f"{exercise.function} = mistaken({module!r}, {checker!r}, {mistake.name!r}, "
                f"{parameters!r})\n"
            )
            usable.append((mistake.name, code, first_line, result.mistake))
        mistakes_of[exercise.function] = usable
    rounds = max(len(usable) for usable in mistakes_of.values())

    students = {"solutions": solutions, "stubs": {}}
    planted = {}
    for number in range(rounds):
        answers = dict(solutions)
        planted[f"mistakes{number}"] = {}
        for function, usable in mistakes_of.items():
            if number < len(usable):
                name, code, first_line, named = usable[number]
                answers[function] = code
                planted[f"mistakes{number}"][function] = (name, first_line, named)
        students[f"mistakes{number}"] = answers
    for student, answers in students.items():
        folder = course / "submitted" / student / lesson
        folder.mkdir(parents=True, exist_ok=True)
        notebook = submission(edition, answers, ids)
        (folder / f"{lesson}.ipynb").write_text(json.dumps(notebook), encoding="utf-8")

    graded = api.autograde(lesson, "*")
    assert graded["success"], graded.get("log")
    feedback = api.generate_feedback(lesson, "*")
    assert feedback["success"], feedback.get("log")

    available = EXERCISE_POINTS * len(found)
    marks = {student: scores(course, lesson, student) for student in students}
    assert set(marks["solutions"]) == set(tests)
    assert sum(marks["solutions"].values()) == available, marks["solutions"]
    assert sum(marks["stubs"].values()) == 0, marks["stubs"]
    row = []
    for student, wrong in planted.items():
        html = unescape((course / "feedback" / student / lesson / f"{lesson}.html").read_text())
        for grade_id, score in marks[student].items():
            function = tests[grade_id].function
            if function in wrong:
                name, first_line, named = wrong[function]
                assert score == 0, f"{function} with '{name}' scored {score}"
                assert first_line.split(":")[0] in html, (function, name, first_line)
                if named:
                    assert f"This is a known mistake, {named}" in html
                # The diagnosis alone: no traceback through the course, no server's paths.
                assert "most recent call last" not in html and str(REPOSITORY) not in html
                row.append(f"{function} '{name}' {available - EXERCISE_POINTS:g}/{available}")
            else:
                assert score == EXERCISE_POINTS, f"{function} lost points for another mistake"
    stubs_html = (course / "feedback" / "stubs" / lesson / f"{lesson}.html").read_text()
    assert "NotImplementedError: your code here" in stubs_html
    TABLE[lesson] = {
        "available": str(available),
        "solutions": f"{sum(marks['solutions'].values()):g}",
        "stubs": f"{sum(marks['stubs'].values()):g}",
        "mistakes": "; ".join(row + [f"(note: {note})" for note in notes]),
    }


def test_the_graders_own_answers_agree_with_the_library_without_running_it():
    from course.classroom.nbgrader import reference
    from course.curves import bezier
    from course.sampling import resample

    points = np.array([[0.0, 0.0], [10.0, 30.0], [40.0, 5.0], [50.0, 50.0]])
    for t in (0.0, 0.3, 1.0):
        np.testing.assert_allclose(
            reference("recursive_bezier")(points, t), bezier.de_casteljau(points, t)
        )
        np.testing.assert_allclose(
            reference("next_level")(points, t), bezier.de_casteljau_levels(points, t)[1]
        )
    assert all(
        reference("comb")(m, n) == bezier.binomial(m, n) for m in range(45) for n in range(m + 1)
    )
    rng = np.random.default_rng(1)
    image = rng.random((5, 7, 3))
    for x, y in rng.uniform(-2.0, 9.0, (100, 2)):
        np.testing.assert_allclose(
            reference("bilinear_sample")(image, x, y), resample.bilinear(image, x, y)
        )


def test_the_course_s_autograde_runs_the_answers_in_the_kernel_and_the_checks_outside(course):
    """nbgrader's Execute gives way to ExecuteAnswers, CheckOutsideKernel right after it,
    and ExecuteAnswers keeps Execute's settings (its timeout)."""
    from nbgrader.converters import Autograde
    from nbgrader.preprocessors import Execute

    from course.classroom.autograder import CheckOutsideKernel, ExecuteAnswers

    config = PyFileConfigLoader("nbgrader_config.py", str(course)).load_config()
    steps = config.Autograde.autograde_preprocessors
    default = list(Autograde.class_traits()["autograde_preprocessors"].make_dynamic_default())
    where = default.index(Execute)
    assert steps == [*default[:where], ExecuteAnswers, CheckOutsideKernel, *default[where + 1 :]]
    assert ExecuteAnswers(config=config).timeout == 600 == config.Execute.timeout


def test_a_check_cell_graded_outside_is_not_run_in_the_kernel_and_costs_its_points_until_graded(
    monkeypatch,
):
    """ExecuteAnswers hands nbgrader's Execute every cell but the declared exercises' check
    cells, which it leaves holding an error: were CheckOutsideKernel taken out of the
    steps, they would score nothing, not every point."""
    from nbformat.v4 import new_code_cell
    from nbgrader.preprocessors import Execute

    from course.classroom.autograder import ExecuteAnswers
    from course.classroom.exercise_list import course_exercises

    run = []

    def executed(self, cell, resources, index):
        run.append(index)
        return cell, resources

    monkeypatch.setattr(Execute, "preprocess_cell", executed)

    def graded(grade_id, source):
        metadata = {"nbgrader": {"grade": True, "grade_id": grade_id, "points": 1}}
        return new_code_cell(source, metadata=metadata)

    cells = [
        new_code_cell("def next_level(control_points, t):\n    return control_points[:-1]"),
        graded("next_level_test", "check.next_level(next_level)"),
        graded("teachers_own_test", "assert True"),  # no declared exercise: the kernel runs it
        new_code_cell("check.next_level(next_level)"),  # not a graded cell
    ]
    course_exercises()  # as ExecuteAnswers.preprocess declares them before the cells
    step = ExecuteAnswers()
    for index, cell in enumerate(cells):
        step.preprocess_cell(cell, {}, index)
    assert run == [0, 2, 3]
    (error,) = cells[1].outputs
    assert error.output_type == "error" and error.ename == "NotGraded"
    assert "next_level is graded outside the kernel by CheckOutsideKernel" in error.evalue
