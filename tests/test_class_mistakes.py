"""``python -m course mistakes``: exact counts from autograded notebooks with known outcomes.

The synthetic class: six students and two exercises of lesson 01, next_level and
recursive_bezier, in nbgrader's layout. s05 is in the gradebook only (no submission); s06
submitted, but autograde wrote nothing (their kernel died); s04's recursive_bezier test cell
has no output. One test runs the real nbgrader on three students.
"""

from __future__ import annotations

import argparse
import csv
import itertools
import json
import os
import sqlite3
import sys
from pathlib import Path

import pytest
from mistakes import named_mistakes

from course.classroom.class_mistakes import (
    ExerciseOutcomes,
    Outcome,
    add_mistakes_command,
    checker_mistakes,
    class_mistakes,
    mistakes_table,
    run,
    write_mistakes,
)
from course.classroom.exercise_list import course_exercises
from course.i18n import gettext_catalog, message_language

REPOSITORY = Path(__file__).resolve().parent.parent
LESSON = "01_de_casteljau"
CHINESE = gettext_catalog("zh_CN").gettext
CELL_NUMBERS = itertools.count()

# Each student's outcome of each exercise: (passed, mistake) or None for a cell without output.
OUTCOMES = {
    "s01": {"next_level": (True, None), "recursive_bezier": (False, "one level short")},
    "s02": {"next_level": (False, "the reversed step"), "recursive_bezier": (False, None)},
    # s03's notebook spoke Chinese: its mistake's name came in Chinese.
    "s03": {"next_level": (False, CHINESE("the reversed step")), "recursive_bezier": (True, None)},
    "s04": {"next_level": (False, None), "recursive_bezier": None},
}


def code_cell(source: str, metadata: dict | None = None, outputs: list | None = None) -> dict:
    return {
        "cell_type": "code",
        "execution_count": None,
        "id": f"cell-{next(CELL_NUMBERS)}",
        "metadata": metadata or {},
        "outputs": outputs or [],
        "source": source,
    }


def graded_cell(function: str, outcome: tuple | None, student: str) -> dict:
    """An autograded test cell: its display of the check (the contract), then its error."""
    grading = {"grade": True, "grade_id": f"{function}_test", "locked": True, "points": 1}
    grading |= {"schema_version": 3, "solution": False}
    outputs = []
    if outcome is not None:
        passed, mistake = outcome
        verdict = "PASS" if passed else "FAIL"
        report = f"{verdict} {function}: the report {student} read"
        check = {"exercise": function, "function": function, "passed": passed}
        check |= {"mistake": mistake, "report": report}
        outputs.append(
            {
                "output_type": "display_data",
                "data": {"text/plain": report},
                "metadata": {"course": {"check": check}},
            }
        )
        if not passed:
            outputs.append({"output_type": "error", "ename": "CheckFailed", "evalue": report})
    source = f"check.{function}({function}).graded()"
    return code_cell(source, {"nbgrader": grading}, outputs)


def notebook(student: str | None) -> dict:
    """The lesson's notebook: the source (no outputs) or a student's autograded copy."""
    cells = [code_cell("from course.lessons.l01_de_casteljau import check")]
    for function in ("next_level", "recursive_bezier"):
        solution = {"grade": False, "grade_id": function, "locked": False, "solution": True}
        cells.append(
            code_cell(f"def {function}(control_points, t):\n    ...", {"nbgrader": solution})
        )
        if student is None:
            cells.append(graded_cell(function, None, "nobody"))
        else:
            cells.append(graded_cell(function, OUTCOMES[student][function], student))
    return {"cells": cells, "metadata": {}, "nbformat": 4, "nbformat_minor": 5}


def write(path: Path, content: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(content), encoding="utf-8")


@pytest.fixture(scope="module")
def course(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("nbgrader")
    write(folder / "source" / LESSON / f"{LESSON}.ipynb", notebook(None))
    for student in OUTCOMES:
        write(folder / "submitted" / student / LESSON / f"{LESSON}.ipynb", notebook(None))
        write(folder / "autograded" / student / LESSON / f"{LESSON}.ipynb", notebook(student))
    write(folder / "submitted" / "s06" / LESSON / f"{LESSON}.ipynb", notebook(None))
    with sqlite3.connect(folder / "gradebook.db") as gradebook:  # nbgrader's table of students
        gradebook.execute("CREATE TABLE student (id VARCHAR(128) PRIMARY KEY, first_name TEXT)")
        gradebook.executemany(
            "INSERT INTO student VALUES (?, ?)", [(f"s0{n}", "Name") for n in range(1, 7)]
        )
    gradebook.close()
    return folder


def counts(rows: list[ExerciseOutcomes]) -> dict[str, dict[str, int]]:
    return {row.function: {o.name: o.students for o in row.outcomes} for row in rows}


def test_each_checkers_named_mistakes_are_listed_once_in_its_order():
    for exercises in course_exercises().values():
        for exercise in exercises:
            recorded = [m.name for m in named_mistakes(exercise.module, exercise.name)[0]]
            listed = checker_mistakes(exercise.name)
            # comb's "the exponential recursion" is its call budget's, not run_cases's.
            extra = ["the exponential recursion"] if exercise.name == "comb" else []
            assert listed == list(dict.fromkeys(recorded + extra)), exercise.name
    # The recording is undone: the checkers run their cases again.
    from course.check.base import run_cases
    from course.check.references import call_budget
    from course.lessons.l02_bernstein import check

    assert check.run_cases is run_cases and check.call_budget is call_budget
    with pytest.raises(ValueError, match=r"^checker: .*not a declared exercise"):
        checker_mistakes("no_such_exercise")


def test_the_counts_are_exact_and_every_known_mistake_is_listed(course):
    rows = class_mistakes(course)
    assert [(row.assignment, row.function) for row in rows] == [
        (LESSON, "next_level"),
        (LESSON, "recursive_bezier"),
    ]
    zero = dict.fromkeys(checker_mistakes("next_level"), 0)
    assert counts(rows)["next_level"] == {
        "passed": 1,
        **zero,
        "the reversed step": 2,  # s02's in English, s03's in Chinese
        "failed, not named": 1,
        "not submitted": 1,
        "test did not run": 1,
    }
    zero = dict.fromkeys(checker_mistakes("recursive_bezier"), 0)
    assert counts(rows)["recursive_bezier"] == {
        "passed": 1,
        **zero,
        "one level short": 1,
        "failed, not named": 1,
        "not submitted": 1,
        "test did not run": 2,
    }
    assert [o.name for o in rows[0].outcomes][:2] == ["passed", "the reversed step"]
    assert [o.kind for o in rows[0].outcomes][-3:] == ["failed", "not submitted", "did not run"]
    examples = {(row.function, o.name): o.example for row in rows for o in row.outcomes}
    assert examples["next_level", "the reversed step"] == "FAIL next_level: the report s02 read"
    assert examples["recursive_bezier", "failed, not named"].endswith("s02 read")
    assert examples["next_level", "passed"] == examples["next_level", "one point short"] == ""


def test_the_assignments_are_chosen_and_bad_input_is_named(course, tmp_path):
    assert class_mistakes(course, [LESSON]) == class_mistakes(course)
    with pytest.raises(ValueError, match=r"^assignments: no assignment '02_bernstein'"):
        class_mistakes(course, ["02_bernstein"])
    with pytest.raises(TypeError, match=r"^assignments: "):
        class_mistakes(course, LESSON)
    with pytest.raises(ValueError, match=r"^course: no autograded nbgrader course"):
        class_mistakes(tmp_path / "missing")
    with pytest.raises(TypeError, match=r"^course: "):
        class_mistakes(3)


def test_the_table_csv_and_chart(course, tmp_path):
    rows = class_mistakes(course)
    table = mistakes_table(rows)
    lines = table.splitlines()
    assert lines[0].split() == ["lesson", "exercise", "outcome", "students"]
    assert lines[1].split() == [LESSON, "next_level", "passed", "1"]
    assert lines[2].split() == ["the", "reversed", "step", "2"]
    assert f"{LESSON}, next_level, the reversed step:" in lines
    assert "    FAIL next_level: the report s02 read" in lines
    assert "s03" not in table  # one example each: the lowest student id's
    first = write_mistakes(rows, tmp_path / "first")
    assert [path.name for path in first] == ["mistakes.csv", "mistakes.png"]
    with first[0].open(encoding="utf-8-sig", newline="") as file:
        table_rows = list(csv.reader(file))
    assert table_rows[0] == ["lesson", "exercise", "outcome", "students", "example"]
    assert table_rows[1] == [LESSON, "next_level", "passed", "1", ""]
    assert table_rows[2] == [
        LESSON, "next_level", "the reversed step", "2", "FAIL next_level: the report s02 read"
    ]  # fmt: skip
    assert len(table_rows) == 1 + sum(len(row.outcomes) for row in rows)
    assert [row[2:4] for row in table_rows if row[1] == "recursive_bezier"][-3:] == [
        ["failed, not named", "1"], ["not submitted", "1"], ["test did not run", "2"]
    ]  # fmt: skip
    png = first[1].read_bytes()
    assert png.startswith(b"\x89PNG") and len(png) > 10_000
    second = write_mistakes(rows, tmp_path / "second")
    assert second[1].read_bytes() == png
    assert second[0].read_bytes() == first[0].read_bytes()


def test_the_chinese_report(course, tmp_path):
    with message_language("zh-CN"):
        rows = class_mistakes(course)
        table = mistakes_table(rows)
        written = write_mistakes(rows, tmp_path)
    assert [path.name for path in written] == ["mistakes.zh-CN.csv", "mistakes.zh-CN.png"]
    lines = table.splitlines()
    assert lines[0].split() == [CHINESE(word) for word in ("lesson", "exercise", "outcome")] + [
        CHINESE("students")
    ]
    assert lines[1].split() == [LESSON, "next_level", CHINESE("passed"), "1"]
    assert lines[2].split() == [CHINESE("the reversed step"), "2"]
    # The columns line up in a terminal, where a Chinese letter is two columns wide.
    assert len({len(line.encode("gb18030")) for line in lines[1:4]}) == 1
    for label in ("passed", "failed, not named", "not submitted", "test did not run"):
        assert CHINESE(label) != label and CHINESE(label) in table
    with written[0].open(encoding="utf-8-sig", newline="") as file:
        header, *body = csv.reader(file)
    assert header == [CHINESE(c) for c in ("lesson", "exercise", "outcome", "students", "example")]
    assert body[1][2:4] == [CHINESE("the reversed step"), "2"]
    assert written[1].read_bytes().startswith(b"\x89PNG")


def parsed(*argv: str) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m course")
    add_mistakes_command(parser.add_subparsers(dest="command", required=True))
    return parser.parse_args(["mistakes", *argv])


def test_the_command(course, tmp_path, capsys, monkeypatch):
    monkeypatch.delenv("COURSE_LANG", raising=False)
    args = parsed("--course", str(course), "--assignment", LESSON, "--out", str(tmp_path))
    assert run(args) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[1].split() == [LESSON, "next_level", "passed", "1"]
    assert sorted(path.name for path in tmp_path.iterdir()) == ["mistakes.csv", "mistakes.png"]
    assert run(parsed("--course", str(course), "--language", "zh-CN")) == 0
    assert CHINESE("passed") in capsys.readouterr().out
    assert (course / "mistakes" / "mistakes.zh-CN.png").is_file()
    assert run(parsed("--course", str(course), "--language", "fr")) == 2
    assert "--language: expected one of en, zh-CN" in capsys.readouterr().err
    assert run(parsed("--course", str(tmp_path / "nowhere"))) == 2
    assert "python -m course mistakes: course: " in capsys.readouterr().err
    assert parsed().course == Path("build", "nbgrader")


try:
    from nbgrader.apps import NbGraderAPI
except ImportError:  # the dev extra installs it
    NbGraderAPI = None

NBGRADER_CONFIG = """c = get_config()  # noqa: F821
c.CourseDirectory.course_id = "course"
c.ClearSolutions.code_stub = {"python": "raise NotImplementedError('your code here')"}
c.Execute.timeout = 120
"""
SOLUTION = "return (1 - t) * control_points[:-1] + t * control_points[1:]"
# The test cell the nbgrader edition writes: the report displayed, a failure raised.
GRADED = "check.next_level(next_level).graded()"
MISTAKEN = (
    "from mistakes import mistaken\n\nnext_level = mistaken("
    "'course.lessons.l01_de_casteljau.check', 'next_level', 'the reversed step', "
    "['control_points', 't'])\n"
)


@pytest.mark.skipif(NbGraderAPI is None, reason="nbgrader is not installed (pip install .[dev])")
def test_the_real_nbgrader_s_autograded_notebooks_are_counted(tmp_path, monkeypatch):
    from nbgrader.api import Gradebook
    from traitlets.config import Config
    from traitlets.config.loader import PyFileConfigLoader

    (tmp_path / "nbgrader_config.py").write_text(NBGRADER_CONFIG)
    solution = {"grade": False, "grade_id": "next_level", "locked": False, "solution": True}
    grading = {"grade": True, "grade_id": "next_level_test", "locked": True, "points": 1}
    grading |= {"solution": False}
    lesson = notebook(None)
    lesson["cells"][1]["metadata"]["nbgrader"] = {**solution, "schema_version": 3}
    lesson["cells"][1]["source"] = (
        "def next_level(control_points, t):\n    ### BEGIN SOLUTION\n"
        f"    {SOLUTION}\n    ### END SOLUTION\n"
    )
    lesson["cells"][2] = code_cell(GRADED, {"nbgrader": {**grading, "schema_version": 3}})
    lesson["cells"] = lesson["cells"][:3]
    lesson["metadata"]["kernelspec"] = {"name": "python3", "display_name": "Python 3"}
    write(tmp_path / "source" / LESSON / f"{LESSON}.ipynb", lesson)
    monkeypatch.setenv("PATH", f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    paths = [str(REPOSITORY), str(REPOSITORY / "tests"), os.environ.get("PYTHONPATH", "")]
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(filter(None, paths)))
    config = Config()
    config.merge(PyFileConfigLoader("nbgrader_config.py", str(tmp_path)).load_config())
    config.CourseDirectory.root = str(tmp_path)
    api = NbGraderAPI(config=config)
    assert api.generate_assignment(LESSON)["success"]
    release = json.loads((tmp_path / "release" / LESSON / f"{LESSON}.ipynb").read_text())
    answers = {
        "solved": f"def next_level(control_points, t):\n    {SOLUTION}\n",
        "mistaken": MISTAKEN,
        "stub": None,  # the release as it is: NotImplementedError
    }
    for student, answer in answers.items():
        submitted = json.loads(json.dumps(release))
        if answer is not None:
            submitted["cells"][1]["source"] = answer
        write(tmp_path / "submitted" / student / LESSON / f"{LESSON}.ipynb", submitted)
    with Gradebook(f"sqlite:///{tmp_path / 'gradebook.db'}") as gradebook:
        gradebook.add_student("absent")  # on the class list, never submitted
    graded = api.autograde(LESSON, "*")
    assert graded["success"], graded.get("log")
    (row,) = class_mistakes(tmp_path)
    found = {o.name: o.students for o in row.outcomes if o.students}
    assert found == {
        "passed": 1,
        "the reversed step": 1,
        "failed, not named": 1,
        "not submitted": 1,
    }
    example = next(o.example for o in row.outcomes if o.name == "failed, not named")
    assert example.startswith("FAIL next_level: not written yet")


def test_the_report_writes_nothing_through_a_link_that_leads_out(tmp_path):
    rows = [ExerciseOutcomes(LESSON, "next_level", "next_level", (Outcome("passed", "", 3),))]
    outside = tmp_path / "outside.csv"
    outside.write_text("mine")
    out = tmp_path / "report"
    out.mkdir()
    (out / "mistakes.csv").symlink_to(outside)
    with pytest.raises(ValueError, match=r"mistakes\.csv leads outside .*report"):
        write_mistakes(rows, out)
    assert outside.read_text() == "mine" and [p.name for p in out.iterdir()] == ["mistakes.csv"]
