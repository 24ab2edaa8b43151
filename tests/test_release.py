"""course.classroom.release: the edition students work in is the one nbgrader grades.

A class's whole nbgrader cycle, with the real nbgrader and two students, both ways in.

The students work in the student edition (what ``make lab``, the hub and a link give them:
:func:`course.classroom.release.student_notebook`); alice solves lesson 07, bob makes one of
the checker's named mistakes in its first exercise. Their work reaches the teacher

- through nbgrader's exchange, as on the hub: release, fetch, submit, collect, autograde,
  generate_feedback, release_feedback (the students fetch their feedback), export;
- from a learning platform's download, with ``nbgrader zip_collect`` and the file-name rule
  ``make nbgrader`` writes into ``nbgrader_config.py``, then autograde and export.

Each way, alice scores full marks and bob loses exactly the point of his mistake, which his
feedback names, and which the class's mistakes report counts.
"""

from __future__ import annotations

import csv
import json
import os
import site
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from mistakes import named_mistakes

from course.classroom.class_mistakes import class_mistakes
from course.classroom.edition import cell_source
from course.classroom.nbgrader import write_nbgrader_course
from course.classroom.notebooks import NOTEBOOKS
from course.classroom.release import exercises, student_notebook

REPOSITORY = Path(__file__).resolve().parent.parent
LESSON = "07_filtering"
CHECKS = "course.lessons.l07_filtering.check"
COURSE_ID = "course"  # nbgrader_config.py's


@pytest.fixture(scope="module")
def environment():
    """nbgrader on PATH (it runs alembic), the course and tests/mistakes.py importable."""
    paths = [str(REPOSITORY), str(REPOSITORY / "tests"), os.environ.get("PYTHONPATH", "")]
    return {
        **os.environ,
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}",
        "PYTHONPATH": os.pathsep.join(filter(None, paths)),
        "MPLBACKEND": "Agg",
    }


def as_student(environment: dict, home: Path) -> dict:
    """A student's own home and Jupyter data (nbgrader keeps what they submitted there), as
    each student of a hub has."""
    return {**environment, "HOME": str(home), "JUPYTER_DATA_DIR": str(home / ".jupyter-data")}


def nbgrader(environment: dict, folder: Path, *arguments: str) -> str:
    done = subprocess.run(
        [str(Path(sys.executable).parent / "nbgrader"), *arguments],
        cwd=folder,
        env=environment,
        capture_output=True,
        text=True,
        timeout=900,
    )
    assert done.returncode == 0, f"nbgrader {' '.join(arguments)}:\n{done.stdout}\n{done.stderr}"
    return done.stdout + done.stderr


def teacher_lesson() -> dict:
    return json.loads((NOTEBOOKS / f"{LESSON}.ipynb").read_text(encoding="utf-8"))


def worked(edition: dict, student: str) -> dict:
    """The student edition with ``student``'s answers typed into its answer cells."""
    teacher = teacher_lesson()
    answers = {}
    for exercise in exercises(teacher):
        lines = cell_source(teacher["cells"][exercise.cell]).splitlines()
        answers[exercise.function] = "\n".join(lines[: exercise.check_line - 1])
    if student == "bob":
        mistake = named_mistakes(CHECKS, "blur")[0][0]
        answers["blur"] = (
            "from mistakes import mistaken\n\n"
            f"blur = mistaken({CHECKS!r}, 'blur', {mistake.name!r}, ['image'])"
        )
    notebook = json.loads(json.dumps(edition))
    for cell in notebook["cells"]:
        grade_id = cell["metadata"].get("nbgrader", {}).get("grade_id")
        if grade_id in answers:
            cell["source"] = answers[grade_id]
    return notebook


def grades(course: Path) -> dict[str, float]:
    """Each student's score in the lesson, from ``nbgrader export``'s CSV."""
    with (course / "grades.csv").open(newline="") as table:
        return {
            row["student_id"]: float(row["score"])
            for row in csv.DictReader(table)
            if row["assignment"] == LESSON
        }


def counted(course: Path) -> None:
    """The class's mistakes report counts the one passed and the one named mistake."""
    (blur, edge) = class_mistakes(course, [LESSON])
    mistake = named_mistakes(CHECKS, "blur")[0][0]
    kinds = {outcome.name: outcome.students for outcome in blur.outcomes if outcome.students}
    assert kinds == {"passed": 1, mistake.name: 1}, kinds
    assert {o.name: o.students for o in edge.outcomes if o.students} == {"passed": 2}


def named_in_feedback(html: str) -> bool:
    mistake = named_mistakes(CHECKS, "blur")[0][0]
    return f"This is a known mistake, {mistake.name}" in html


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    folder = tmp_path_factory.mktemp("class")
    write_nbgrader_course(folder / "course")
    # bob's mistake is the library's reproduction (tests/mistakes.py): the grader's child may
    # import the course and the tests here, which a real class's never does.
    with (folder / "course" / "nbgrader_config.py").open("a", encoding="utf-8") as config:
        paths = [str(REPOSITORY), str(REPOSITORY / "tests"), *site.getsitepackages()]
        config.write(f"c.CheckOutsideKernel.child_paths = {paths!r}\n")
    return folder / "course"


def test_the_exchange_cycle_grades_the_edition_the_students_work_in(course, environment, tmp_path):
    exchange = tmp_path / "exchange"
    exchange.mkdir(mode=0o777)
    exchange.chmod(0o777)  # nbgrader wants a world-writable exchange, as a hub's is
    shared = [f"--Exchange.root={exchange}", f"--CourseDirectory.course_id={COURSE_ID}"]
    nbgrader(environment, course, "generate_assignment", LESSON)
    nbgrader(environment, course, "release_assignment", LESSON, *shared)
    edition = student_notebook(teacher_lesson())
    for student in ("alice", "bob"):
        nbgrader(environment, course, "db", "student", "add", student)
        home = tmp_path / student
        home.mkdir()
        nbgrader(as_student(environment, home), home, "fetch_assignment", LESSON, *shared)
        fetched = json.loads((home / LESSON / f"{LESSON}.ipynb").read_text(encoding="utf-8"))
        assert [cell_source(c) for c in fetched["cells"]] == [
            cell_source(c) for c in edition["cells"]
        ], "the exchange hands out the student edition"
        (home / LESSON / f"{LESSON}.ipynb").write_text(json.dumps(worked(fetched, student)))
        nbgrader(
            as_student(environment, home), home, "submit", LESSON, *shared, f"--student={student}"
        )
    nbgrader(environment, course, "collect", LESSON, *shared)
    nbgrader(environment, course, "autograde", LESSON)
    nbgrader(environment, course, "generate_feedback", LESSON)
    nbgrader(environment, course, "release_feedback", LESSON, *shared)
    nbgrader(environment, course, "export")
    assert grades(course) == {"alice": 2.0, "bob": 1.0}
    counted(course)
    for student in ("alice", "bob"):
        nbgrader(
            as_student(environment, tmp_path / student),
            tmp_path / student,
            "fetch_feedback",
            LESSON,
            *shared,
            f"--student={student}",
        )
        feedback = list((tmp_path / student / LESSON / "feedback").rglob("*.html"))
        assert len(feedback) == 1, feedback
        assert named_in_feedback(feedback[0].read_text(encoding="utf-8")) == (student == "bob")


def test_zip_collect_grades_a_learning_platforms_download(course, environment, tmp_path):
    """The students download the edition's lesson, upload it to the platform, and the teacher
    downloads every upload in one archive, each file named <student>_<lesson>.ipynb."""
    edition = student_notebook(teacher_lesson())
    archive = course / "downloaded" / LESSON / "archive"
    archive.mkdir(parents=True)
    with zipfile.ZipFile(archive / "uploads.zip", "w") as uploads:
        for student in ("carol", "dave"):
            work = worked(edition, "bob" if student == "dave" else "alice")
            uploads.writestr(f"{student}_{LESSON}.ipynb", json.dumps(work))
    nbgrader(environment, course, "generate_assignment", LESSON, "--force")
    nbgrader(environment, course, "zip_collect", LESSON)
    for student in ("carol", "dave"):
        assert (course / "submitted" / student / LESSON / f"{LESSON}.ipynb").is_file()
    nbgrader(environment, course, "autograde", LESSON, "--create")
    nbgrader(environment, course, "generate_feedback", LESSON)
    nbgrader(environment, course, "export")
    scores = grades(course)
    assert (scores["carol"], scores["dave"]) == (2.0, 1.0)
    html = (course / "feedback" / "dave" / LESSON / f"{LESSON}.html").read_text(encoding="utf-8")
    assert named_in_feedback(html)
