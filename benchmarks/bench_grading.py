"""Issue 33: how long nbgrader takes to grade a class when each exercise is graded outside the
student's kernel, against today's ``nbgrader autograde``.

    python benchmarks/bench_grading.py [--students 40] [--lesson 01_de_casteljau]

Two nbgrader course folders, written by ``python -m course nbgrader``'s
:func:`~course.classroom.nbgrader.write_nbgrader_course`, with the lesson released:

- **outside**: the course's own ``nbgrader_config.py``, whose autograde runs
  :class:`~course.classroom.autograder.CheckOutsideKernel` after the kernel (each exercise
  re-graded in a child process, on cases drawn for the submission);
- **today**: the same file, without that step (nbgrader's own autograde: the grades are
  the kernel's outputs).

A class of ``--students`` submit the lesson solved: the student edition
(:func:`course.classroom.release.student_notebook`, every cell, the pictures and apps
included) with the teacher's answers typed into its answer cells. Each folder is graded
by one ``nbgrader autograde <lesson> --create`` (every student at once, as a teacher runs
it), timed on the wall clock from the command's start to its end; today's first, then the
grader's, in one run. It prints both, the seconds per student, and the ratio.

Every submission must get every point in both (else the time is not a grading's). Then a
witness, graded apart and not timed: answers right in the kernel only (they call
``get_ipython()``), which the grader must fail; if it does not, the grader did not run and
the ratio measures nothing, which the last line says.

Goal (issue 33): the grader's time at most 2x today's. Takes about 2 x 40 x (the lesson's
Run All and a kernel's start): 10 to 20 minutes on a 2-core machine; ``make bench`` runs it.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from course.classroom.edition import cell_source
from course.classroom.nbgrader import write_nbgrader_course
from course.classroom.notebooks import NOTEBOOKS
from course.classroom.release import exercises, student_notebook

NBGRADER = Path(sys.executable).parent / "nbgrader"
GOAL = 2.0
#: Appended to the course's nbgrader_config.py for today's autograde: the step taken out.
WITHOUT_THE_GRADER = (
    "\n_steps[_steps.index(ExecuteAnswers)] = Execute\n_steps.remove(CheckOutsideKernel)\n"
    "c.Autograde.autograde_preprocessors = _steps\n"
)


def nbgrader(folder: Path, *arguments: str) -> subprocess.CompletedProcess[str]:
    environment = {
        **os.environ,
        "PATH": f"{NBGRADER.parent}{os.pathsep}{os.environ['PATH']}",  # nbgrader runs alembic
        "MPLBACKEND": "Agg",
    }
    done = subprocess.run(
        [str(NBGRADER), *arguments], cwd=folder, env=environment, capture_output=True, text=True
    )
    if done.returncode != 0:
        raise SystemExit(f"nbgrader {' '.join(arguments)} failed:\n{done.stderr[-4000:]}")
    return done


def solved(lesson: str, kernel_only: bool = False) -> str:
    """The student edition of ``lesson``, every cell, with the teacher's answers typed in (or
    the witness's: each answer calls get_ipython() first)."""
    teacher = json.loads((NOTEBOOKS / f"{lesson}.ipynb").read_text(encoding="utf-8"))
    answers = {}
    for found in exercises(teacher):
        lines = cell_source(teacher["cells"][found.cell]).splitlines()[: found.check_line - 1]
        answer = "\n".join(lines)
        if kernel_only:
            answer = answer.replace('"""\n', '"""\n    get_ipython()\n', 1)
        answers[found.function] = answer
    notebook = student_notebook(teacher)
    for cell in notebook["cells"]:
        grade_id = cell["metadata"].get("nbgrader", {}).get("grade_id")
        if grade_id in answers:
            cell["source"] = answers[grade_id]
    return json.dumps(notebook)


def course_folder(root: Path, name: str, lesson: str, today: bool) -> Path:
    course = root / name
    write_nbgrader_course(course)
    for other in (course / "source").iterdir():
        if other.name != lesson:
            shutil.rmtree(other)
    if today:
        with (course / "nbgrader_config.py").open("a", encoding="utf-8") as config:
            config.write(WITHOUT_THE_GRADER)
    nbgrader(course, "generate_assignment", lesson)
    return course


def submit(course: Path, lesson: str, students: list[str], text: str) -> None:
    for student in students:
        folder = course / "submitted" / student / lesson
        folder.mkdir(parents=True)
        (folder / f"{lesson}.ipynb").write_text(text, encoding="utf-8")


def scores(course: Path, lesson: str, students: list[str]) -> dict[str, float]:
    from nbgrader.api import Gradebook

    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gradebook:
        return {
            student: sum(
                grade.score or 0.0
                for grade in gradebook.find_submission_notebook(lesson, lesson, student).grades
            )
            for student in students
        }


def autograde_seconds(course: Path, lesson: str) -> float:
    start = time.perf_counter()
    nbgrader(course, "autograde", lesson, "--create")
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=40, help="the class's size")
    parser.add_argument("--lesson", default="01_de_casteljau", help="the lesson graded")
    args = parser.parse_args()
    lesson = args.lesson
    teacher = json.loads((NOTEBOOKS / f"{lesson}.ipynb").read_text(encoding="utf-8"))
    available = sum(found.points for found in exercises(teacher))
    students = [f"student{number:02d}" for number in range(1, args.students + 1)]
    work = solved(lesson)
    with tempfile.TemporaryDirectory(prefix="bench-grading-") as temporary:
        root = Path(temporary)
        folders = {
            "today": course_folder(root, "today", lesson, today=True),
            "outside": course_folder(root, "outside", lesson, today=False),
        }
        seconds = {}
        for name, course in folders.items():
            submit(course, lesson, students, work)
            seconds[name] = autograde_seconds(course, lesson)
            got = scores(course, lesson, students)
            wrong = {student: score for student, score in got.items() if score != available}
            if wrong:
                raise SystemExit(f"{name}: not every point for a solved lesson: {wrong}")
            print(
                f"{name:<8} nbgrader autograde, {len(students)} students of {lesson}: "
                f"{seconds[name]:.0f} s ({seconds[name] / len(students):.1f} s a student)",
                flush=True,
            )
        outside = folders["outside"]
        submit(outside, lesson, ["witness"], solved(lesson, kernel_only=True))
        nbgrader(outside, "autograde", lesson, "--student=witness")
        graded = scores(outside, lesson, ["witness"])["witness"] == 0
    ratio = seconds["outside"] / seconds["today"]
    verdict = "met" if ratio <= GOAL else "NOT met"
    print(f"ratio outside / today: {ratio:.2f}x (goal <= {GOAL:g}x, {verdict})")
    if graded:
        print("the grader ran: the witness (right in the kernel only) got 0")
    else:
        print(
            "WARNING: the grader did not grade (the witness, right in the kernel only, got its "
            "points): the ratio does not measure it"
        )


if __name__ == "__main__":
    main()
