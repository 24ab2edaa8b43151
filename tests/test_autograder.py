"""course.classroom.autograder: what a class's cleverest, or unluckiest, student does to a grade.

Issue 33's battery, in two parts.

**The tricks, through the real nbgrader** (the slow part: one module fixture, 38 submissions
graded in 3.5 to 5 minutes on this shared 2-core machine; it runs in ``make test``, where
``--dist loadfile`` gives the whole file to one worker). A course folder is written by
:func:`~course.classroom.nbgrader.write_nbgrader_course`, with the ``nbgrader_config.py`` a
teacher gets (the grader's child may import nothing of the course's), lessons 01 and 06
are released, and one submission per trick is made from the student edition
(:func:`course.classroom.release.student_notebook`, kept to its first code cell, the
imports, and its nbgrader cells): the exercises left as their stubs, or wrong, plus the
trick, each function in its own answer cell. One ``nbgrader autograde`` grades them all,
then one ``generate_feedback``. Each trick must score 0 on the exercises it targets. The
tricks are the issue's 25 (its ``np.allclose / np.array_equal`` made two submissions) and
five more (:data:`BEYOND`): one on the kernel, four that reach the library, the teacher's
notebook or the graded cases from the grader's child itself. And the other way round: an
honest answer that prints to standard error, and one that raises numpy's RuntimeWarning,
get every point, and what they said is in their feedback. Controls: the teacher's answers
(every point), the stubs (none), and a witness right in the kernel only (0 when the grade
is the grader's).

None scores: the child confines itself before the student's first line (an audit hook: no
file outside the standard library, numpy and its own folder, no process, no ``ctypes``),
and the graded cases' seed holds the teacher's secret. ``COURSE_TRICKS=today`` also grades
every submission without :class:`~course.classroom.autograder.CheckOutsideKernel` and
prints what each scores there.

**The accidents, in the grader's child** (:func:`course.check.outside.outside_function`,
no nbgrader; about two minutes): endless loops in Python and in C, memory in numpy and
``mmap``, lying objects, endless iterators, BaseExceptions, ``os._exit``, writes to the
protocol's file descriptors, as the student's function for a declared exercise's checker,
graded (``grading(seed)``). Each must give a FAIL report, with no traceback and no path of
the course's code in it, within the child's wall-clock budget (its start timed apart).
Not every attack meets every checker: :func:`accident_pairs` deals them out round a list
shuffled with a fixed seed, each attack to :data:`MEETS` checkers (five for the quick, two
for those the processor-time alarm stops, one for those only the wall-clock kill stops,
which take its whole 9 s: each case gets ACCIDENT_SECONDS, 1 s), 122 pairs, every checker
meeting at least five attacks.
"""

from __future__ import annotations

import contextlib
import functools
import json
import os
import random
import re
import shutil
import subprocess
import sys
import textwrap
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from html import unescape
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from course.check import outside
from course.check.exercises import declared
from course.check.grading import grading, submission_seed
from course.classroom.edition import cell_source
from course.classroom.exercise_list import course_exercises
from course.classroom.nbgrader import write_nbgrader_course
from course.classroom.notebooks import NOTEBOOKS
from course.classroom.release import exercises, student_notebook

REPOSITORY = Path(__file__).resolve().parent.parent
NBGRADER = Path(sys.executable).parent / "nbgrader"
L01, L06 = "01_de_casteljau", "06_dithering"
LESSONS = (L01, L06)
#: nbgrader's assignment glob for both lessons: one command grades them all.
BOTH = "0[16]_*"
EXERCISES = {
    L01: ("next_level", "recursive_bezier", "bezier"),
    L06: ("dithering_ordered", "dithering_error_diffuse"),
}
TODAY = os.environ.get("COURSE_TRICKS") == "today"
PARAMETERS_01 = {
    "next_level": "control_points, t",
    "recursive_bezier": "control_points, t",
    "bezier": "control_points, window",
}


# --- the submissions ----------------------------------------------------------------------


@dataclass(frozen=True)
class Student:
    """One submission: ``answers`` replace answer cells (by grade id; the others keep their
    stubs), ``edit`` then changes the notebook (or returns its text); ``targets`` are the
    exercises the trick aims at, which must score 0."""

    name: str
    lesson: str
    answers: dict[str, str] | Callable[[], dict[str, str]]  # made when graded (a table)
    targets: tuple[str, ...]
    what: str
    edit: Callable[[dict], dict | str] | None = None


def code(text: str) -> str:
    return textwrap.dedent(text).strip() + "\n"


def teacher(lesson: str) -> dict:
    return json.loads((NOTEBOOKS / f"{lesson}.ipynb").read_text(encoding="utf-8"))


def solutions(lesson: str) -> dict[str, str]:
    """Each answer cell as the teacher wrote it: the function, without its check line."""
    notebook = teacher(lesson)
    return {
        found.function: "\n".join(
            cell_source(notebook["cells"][found.cell]).splitlines()[: found.check_line - 1]
        )
        for found in exercises(notebook)
    }


@functools.cache
def stubs(lesson: str) -> dict[str, str]:
    """Each answer cell of the student edition: its stub."""
    return {
        cell["metadata"]["nbgrader"]["grade_id"]: cell_source(cell)
        for cell in student_notebook(teacher(lesson))["cells"]
        if cell["metadata"].get("nbgrader", {}).get("solution")
    }


def check_cells(notebook: dict) -> Iterator[dict]:
    return (
        cell
        for cell in notebook["cells"]
        if str(cell["metadata"].get("nbgrader", {}).get("grade_id", "")).endswith("_test")
    )


def edited(notebook: dict) -> dict:
    for cell in check_cells(notebook):
        cell["source"] = "pass"
    return notebook


def deleted(notebook: dict) -> dict:
    dropped = {id(cell) for cell in check_cells(notebook)}
    notebook["cells"] = [cell for cell in notebook["cells"] if id(cell) not in dropped]
    return notebook


def repointed(notebook: dict) -> dict:
    """Each test cell's nbgrader metadata put on a cell of the student's (``pass``), at the
    top, and the test cell itself made an ordinary cell."""
    moved = []
    for cell in check_cells(notebook):
        mine = {
            "cell_type": "code",
            "id": f"mine-{len(moved)}",
            "metadata": {"nbgrader": dict(cell["metadata"]["nbgrader"])},
            "source": "pass",
            "outputs": [],
            "execution_count": None,
        }
        moved.append(mine)
        del cell["metadata"]["nbgrader"]
    notebook["cells"][1:1] = moved
    return notebook


def corrupt(notebook: dict) -> str:
    text = json.dumps(notebook)
    return text[: len(text) // 2]


#: A result the kernel's checks take for a pass (tricks that replace the checker).
PASSED = code(
    """
    class _Passed:
        passed = True

        def graded(self):
            return None

        def assert_passed(self):
            return self
    """
)


def answer_cells(setup: str = "", **functions: str) -> dict[str, str]:
    """Lesson 01's answer cells: ``setup`` at the top of the first (next_level's), then each
    function's source in its own cell (a later cell redefines what an earlier one did), the
    stub where none is given."""
    cells = {**stubs(L01), **functions}  # a copy: stubs() is cached
    cells["next_level"] = f"{setup}\n\n{cells['next_level']}" if setup else cells["next_level"]
    return cells


#: Wrong answers that are not stubs (a stub is "not written yet" whatever is patched).
WRONG_01 = {
    "next_level": "def next_level(control_points, t):\n"
    "    return np.zeros((len(control_points) - 1, 2))\n",
    "recursive_bezier": "def recursive_bezier(control_points, t):\n    return np.zeros(2)\n",
    "bezier": "def bezier(control_points, window):\n    window[...] = 0\n",
}
#: The library's answers to next_level and recursive_bezier, by name.
LIBRARY_01 = {
    "next_level": "def next_level(control_points, t):\n"
    "    return de_casteljau_levels(control_points, t)[1]\n",
    "recursive_bezier": "def recursive_bezier(control_points, t):\n"
    "    return de_casteljau(control_points, t)\n",
}
#: Walks up from the student's function to the checker's frames: the expected answer, or
#: the checker's reference called on the case.
FROM_THE_CHECKER = code(
    """
    import sys


    def _answer_from_the_checker(clear_cases=False):
        frame = sys._getframe(2)
        found = None
        while frame is not None:
            names = frame.f_locals
            if clear_cases and isinstance(names.get("cases"), list):
                names["cases"].clear()
            if found is None and "expected" in names:
                found = names["expected"]
            if found is None and callable(names.get("reference")) and "case" in names:
                found = names["reference"](**names["case"])
            frame = frame.f_back
        if found is None:
            raise NotImplementedError("your code here")
        return found
    """
)
TEACHERS_CELLS = code(
    """
    for _cell in _teacher["cells"]:
        if "solution" in _cell["metadata"].get("tags", []):
            exec("".join(_cell["source"]).split("\\ncheck.")[0], globals())
    """
)


def table_answers(function: str, seed: int | None) -> str:
    """A cell answering ``function`` from a table of its checker's cases: the fixed ones (as a
    student reads them from the FAIL messages), or those drawn for ``seed``. The table's
    values are the right answers, as the reports print them."""
    table: dict[str, Any] = {}

    def level(points: np.ndarray, t: float) -> np.ndarray:
        return (1 - t) * points[:-1] + t * points[1:]

    def recorder(control_points: Any, t: Any) -> Any:
        points = np.asarray(control_points, dtype=float)
        key = repr((points.tolist(), float(t)))
        answer = level(points, float(t))
        if function == "recursive_bezier":
            while len(answer) > 1:
                answer = level(answer, float(t))
            answer = answer[0]
        table[key] = answer.tolist()
        return answer

    course_exercises()  # every chapter's checkers declared
    checker = declared(function).checker
    with grading(seed) if seed is not None else contextlib.nullcontext():
        result = checker(recorder)
    assert result.passed, str(result)
    return code(
        f"""
        _{function.upper()} = {table!r}


        def {function}(control_points, t):
            key = repr((np.asarray(control_points, dtype=float).tolist(), float(t)))
            return np.array(_{function.upper()}[key])
        """
    )


def issue_tricks() -> list[Student]:
    """The issue's 25 tricks (its np.allclose / np.array_equal as two)."""
    checks = "from course.lessons.l01_de_casteljau import check\n"
    teachers = code(
        f"""
        import json

        from course.classroom.notebooks import NOTEBOOKS

        _teacher = json.loads((NOTEBOOKS / "{L01}.ipynb").read_text(encoding="utf-8"))
        """
    )
    return [
        Student(
            "input_transformer",
            L01,
            answer_cells(
                code(
                    """
                    def _skip_checks(lines):
                        if any("check." in line for line in lines):
                            return ["pass\\n"]
                        return lines


                    get_ipython().input_transformers_cleanup.append(_skip_checks)
                    """
                )
            ),
            EXERCISES[L01],
            "an IPython input transformer turns every test cell into `pass`",
        ),
        Student(
            "patched_check",
            L01,
            answer_cells(
                checks + PASSED + "\n\nfor _name in ('next_level', 'recursive_bezier', 'bezier'):\n"
                "    setattr(check, _name, lambda student: _Passed())\n"
            ),
            EXERCISES[L01],
            "check.next_level = ... (each checker replaced on the lesson's check module)",
        ),
        Student(
            "rebound_check",
            L01,
            answer_cells(
                PASSED + "\n\nimport types\n\n"
                "check = types.SimpleNamespace(**{name: (lambda student: _Passed()) for name in "
                "('next_level', 'recursive_bezier', 'bezier')})\n"
            ),
            EXERCISES[L01],
            "the notebook's name `check` rebound to a namespace of passes",
        ),
        Student(
            "patched_result",
            L01,
            answer_cells(
                code(
                    """
                    from course.check.results import CheckResult

                    CheckResult.assert_passed = lambda self: self
                    CheckResult.graded = lambda self: None
                    """
                )
            ),
            EXERCISES[L01],
            "CheckResult.assert_passed and CheckResult.graded replaced",
        ),
        Student(
            "patched_run_cases",
            L01,
            answer_cells(
                code(
                    """
                    import sys

                    from course.check.results import CheckResult


                    def run_cases(exercise, student, cases, *args, **kwargs):
                        return CheckResult(exercise, True, 1, "all cases pass")


                    for _module in list(sys.modules.values()):
                        if getattr(_module, "__name__", "").startswith("course.") and hasattr(
                            _module, "run_cases"
                        ):
                            _module.run_cases = run_cases
                    """
                )
            ),
            EXERCISES[L01],
            "run_cases replaced in every course module that has it",
        ),
        Student(
            "patched_allclose",
            L01,
            answer_cells(
                code(
                    """
                    np.allclose = lambda *args, **kwargs: True
                    np.isclose = lambda a, b, *args, **kwargs: np.ones(
                        np.broadcast(np.asarray(a), np.asarray(b)).shape, dtype=bool
                    )
                    """
                ),
                **WRONG_01,
            ),
            EXERCISES[L01],
            "np.allclose (and np.isclose) always true, wrong answers",
        ),
        Student(
            "patched_array_equal",
            L01,
            answer_cells("np.array_equal = lambda *args, **kwargs: True\n", **WRONG_01),
            EXERCISES[L01],
            "np.array_equal always true, wrong answers",
        ),
        Student(
            "graders_answers",
            L01,
            answer_cells(
                "from course.classroom.nbgrader import reference\n",
                next_level='next_level = reference("next_level")\n',
                recursive_bezier="from course.classroom.nbgrader import reference\n\n"
                'recursive_bezier = reference("recursive_bezier")\n',
            ),
            ("next_level", "recursive_bezier"),
            "course.classroom.nbgrader's grader answers (reference(name))",
        ),
        Student(
            "ordered_loop",
            L06,
            {
                "dithering_ordered": code(
                    """
                    from course.halftone.dither import _ordered_loop


                    def dithering_ordered(gray):
                        return _ordered_loop(np.asarray(gray, dtype=float))
                    """
                )
            },
            ("dithering_ordered",),
            "course.halftone.dither._ordered_loop, the library's loop form",
        ),
        Student(
            "error_diffusion_loop",
            L06,
            {
                "dithering_error_diffuse": code(
                    """
                    from course.halftone.diffusion import _error_diffusion_loop


                    def dithering_error_diffuse(gray):
                        offsets = [(1, 0, 7 / 16), (-1, 1, 3 / 16), (0, 1, 5 / 16), (1, 1, 1 / 16)]
                        image = np.asarray(gray, dtype=float)
                        return _error_diffusion_loop(image, offsets, False)[0]
                    """
                )
            },
            ("dithering_error_diffuse",),
            "course.halftone.diffusion._error_diffusion_loop, the library's loop form",
        ),
        Student(
            "private_de_casteljau",
            L01,
            answer_cells(
                "from course.curves.bezier import _de_casteljau\n",
                next_level=code(
                    """
                    def next_level(control_points, t):
                        points = np.asarray(control_points, dtype=float)
                        edges = [points[i : i + 2] for i in range(len(points) - 1)]
                        return np.array([_de_casteljau(edge, np.array([t]))[0] for edge in edges])
                    """
                ),
                recursive_bezier=code(
                    """
                    from course.curves.bezier import _de_casteljau


                    def recursive_bezier(control_points, t):
                        points = np.asarray(control_points, dtype=float)
                        return _de_casteljau(points, np.array([t]))[0]
                    """
                ),
            ),
            ("next_level", "recursive_bezier"),
            "course.curves.bezier._de_casteljau, the library's private kernel",
        ),
        Student(
            "source_exec",
            L01,
            answer_cells(
                code(
                    """
                    import inspect

                    from course.curves import bezier as _library

                    _namespace = dict(vars(_library))
                    for _name in ("de_casteljau_levels", "de_casteljau_recursive"):
                        exec(inspect.getsource(getattr(_library, _name)), _namespace)
                    """
                ),
                next_level="def next_level(control_points, t):\n"
                '    return _namespace["de_casteljau_levels"](control_points, t)[1]\n',
                recursive_bezier='recursive_bezier = _namespace["de_casteljau_recursive"]\n',
            ),
            ("next_level", "recursive_bezier"),
            "inspect.getsource of library functions, exec'd into new code objects",
        ),
        Student(
            "teachers_notebook",
            L01,
            {function: teachers + TEACHERS_CELLS for function in EXERCISES[L01]},
            EXERCISES[L01],
            "the teacher's notebook through NOTEBOOKS, its solution cells exec'd (each cell)",
        ),
        Student(
            "frame_walk",
            L01,
            answer_cells(
                FROM_THE_CHECKER,
                next_level="def next_level(control_points, t):\n"
                "    return _answer_from_the_checker()\n",
                recursive_bezier="def recursive_bezier(control_points, t):\n"
                "    return _answer_from_the_checker()\n",
                bezier="def bezier(control_points, window):\n"
                "    window[...] = _answer_from_the_checker()\n",
            ),
            EXERCISES[L01],
            "frames walked up to the checker's expected answer (or its reference)",
        ),
        Student(
            "profile_off",
            L01,
            answer_cells(
                "import sys\n\n"
                "from course.curves.bezier import de_casteljau, de_casteljau_levels\n",
                **{
                    name: source.replace("):\n", "):\n    sys.setprofile(None)\n", 1)
                    for name, source in LIBRARY_01.items()
                },
            ),
            ("next_level", "recursive_bezier"),
            "sys.setprofile(None) switches off the watch, then the library's answer",
        ),
        Student(
            "fake_nbgrader_module",
            L01,
            answer_cells(
                code(
                    """
                    import contextlib
                    import sys
                    import types


                    @contextlib.contextmanager
                    def _swallowing(function, *names):
                        try:
                            yield
                        except BaseException:
                            pass


                    _fake = types.ModuleType("course.classroom.nbgrader")
                    _fake.earlier_exercises = _swallowing
                    sys.modules["course.classroom.nbgrader"] = _fake
                    """
                )
            ),
            ("recursive_bezier", "bezier"),
            'a fake sys.modules["course.classroom.nbgrader"] whose earlier_exercises '
            "swallows the failure",
        ),
        Student(
            "fail_message_table",
            L01,
            lambda: answer_cells(**tables(None)),
            ("next_level", "recursive_bezier"),
            "a table of the fixed cases' answers, as the FAIL messages print them",
        ),
        Student(
            "edited_test_cells",
            L01,
            {},
            EXERCISES[L01],
            "every test cell's source replaced by `pass`",
            edit=edited,
        ),
        Student(
            "deleted_test_cells",
            L01,
            {},
            EXERCISES[L01],
            "every test cell deleted",
            edit=deleted,
        ),
        Student(
            "repointed_test_cells",
            L01,
            {},
            EXERCISES[L01],
            "each test cell's nbgrader metadata moved onto a `pass` cell of the student's",
            edit=repointed,
        ),
        Student(
            "system_exit",
            L01,
            {
                name: f"def {name}({params}):\n    raise SystemExit(0)\n"
                for name, params in PARAMETERS_01.items()
            },
            EXERCISES[L01],
            "each function raises SystemExit",
        ),
        Student(
            "os_exit",
            L01,
            {
                name: f"import os\n\n\ndef {name}({params}):\n    os._exit(0)\n"
                for name, params in PARAMETERS_01.items()
            },
            EXERCISES[L01],
            "each function ends its process with os._exit(0)",
        ),
        Student(
            "corrupt_json",
            L01,
            {},
            EXERCISES[L01],
            "the submitted file cut in half: not JSON",
            edit=corrupt,
        ),
        Student(
            "leftover_thread",
            L01,
            answer_cells(
                code(
                    """
                    import threading
                    import time

                    from course.check.results import CheckResult


                    def _keep_patching():
                        while True:
                            CheckResult.graded = lambda self: None
                            CheckResult.assert_passed = lambda self: self
                            time.sleep(0.0005)


                    threading.Thread(target=_keep_patching, daemon=True).start()
                    """
                )
            ),
            EXERCISES[L01],
            "a thread left running that keeps patching CheckResult",
        ),
        Student(
            "cases_cleared",
            L01,
            answer_cells(
                FROM_THE_CHECKER,
                next_level="def next_level(control_points, t):\n"
                "    return _answer_from_the_checker(clear_cases=True)\n",
                recursive_bezier="def recursive_bezier(control_points, t):\n"
                "    return _answer_from_the_checker(clear_cases=True)\n",
            ),
            ("next_level", "recursive_bezier"),
            'f_locals["cases"].clear() after the first case (answered from the frames)',
        ),
        Student(
            "always_equal",
            L01,
            answer_cells(
                code(
                    """
                    class _AlwaysEqual(np.ndarray):
                        def __eq__(self, other):
                            return np.ones(np.shape(self), dtype=bool)

                        def __ne__(self, other):
                            return np.zeros(np.shape(self), dtype=bool)

                        def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
                            return np.True_
                    """
                ),
                next_level="def next_level(control_points, t):\n"
                "    return np.zeros((len(control_points) - 1, 2)).view(_AlwaysEqual)\n",
                recursive_bezier="def recursive_bezier(control_points, t):\n"
                "    return np.zeros(2).view(_AlwaysEqual)\n",
            ),
            ("next_level", "recursive_bezier"),
            "answers whose ==, != and every ufunc say equal",
        ),
    ]


def beyond_tricks() -> list[Student]:
    """Tricks past the issue's 25: one more on the kernel, and the library, the teacher's
    notebook or the graded cases reached from where the grader runs the answer now."""
    teachers = code(
        f"""
        import json

        # The path a student reads in their kernel: classroom.notebooks.NOTEBOOKS.
        with open({str(NOTEBOOKS / f"{L01}.ipynb")!r}, encoding="utf-8") as _file:
            _teacher = json.load(_file)
        """
    )
    return [
        Student(
            "no_nbgrader_execution",
            L01,
            answer_cells("import os\n\nos.environ.pop('NBGRADER_EXECUTION', None)\n", **WRONG_01),
            EXERCISES[L01],
            "NBGRADER_EXECUTION unset in the kernel, so .graded() never raises; wrong answers",
        ),
        Student(
            "child_site_packages",
            L01,
            answer_cells(
                code(
                    """
                    import os
                    import site

                    import numpy

                    # The child's numpy is a link into the real site-packages; its .pth files
                    # make the course importable again.
                    site.addsitedir(os.path.dirname(os.path.dirname(os.path.realpath(numpy.__file__))))
                    from course.curves.bezier import de_casteljau, de_casteljau_levels
                    """
                ),
                **LIBRARY_01,
            ),
            ("next_level", "recursive_bezier"),
            "in the grader's child, site.addsitedir(numpy's real folder): the course "
            "imports again, its library answers",
        ),
        Student(
            "child_subprocess",
            L01,
            answer_cells(
                next_level=code(
                    """
                    import json
                    import subprocess
                    import sys

                    _PROGRAM = (
                        "import json, sys\\n"
                        "import numpy as np\\n"
                        "from course.curves.bezier import de_casteljau_levels\\n"
                        "points, t = json.loads(sys.argv[1])\\n"
                        "print(json.dumps(de_casteljau_levels(np.array(points), t)[1].tolist()))\\n"
                    )


                    def next_level(control_points, t):
                        points = np.asarray(control_points, dtype=float).tolist()
                        argument = json.dumps([points, float(t)])
                        command = [sys.executable, "-c", _PROGRAM, argument]
                        done = subprocess.run(command, capture_output=True, text=True)
                        return np.array(json.loads(done.stdout))
                    """
                )
            ),
            ("next_level",),
            "in the grader's child, a subprocess of sys.executable (without -I -S) computes "
            "the library's answer",
        ),
        Student(
            "child_reads_teachers_notebook",
            L01,
            {function: teachers + TEACHERS_CELLS for function in EXERCISES[L01]},
            EXERCISES[L01],
            "in the grader's child, the teacher's notebook opened by its absolute path, its "
            "solution cells exec'd",
        ),
        Student(
            "graded_table",
            L01,
            lambda: answer_cells(**tables(submission_seed("graded_table", L01))),
            ("next_level", "recursive_bezier"),
            "a table of the graded cases, drawn in the kernel from the public seed "
            "(submission_seed(student, assignment)) and answered with the library",
        ),
    ]


def tables(seed: int | None) -> dict[str, str]:
    """next_level's and recursive_bezier's answer cells, each from its table."""
    return {
        function: table_answers(function, seed) for function in ("next_level", "recursive_bezier")
    }


def honest() -> list[Student]:
    solved01, solved06 = solutions(L01), solutions(L06)
    stderr = dict(solved01)
    stderr["next_level"] = "import sys\n\n\n" + solved01["next_level"].replace(
        '"""\n',
        '"""\n    print("debug: a level of", len(control_points), "points", file=sys.stderr)\n',
        1,
    )
    warning = dict(solved06)
    warning["dithering_ordered"] = code(
        """
        def dithering_ordered(gray):
            # A sanity check: every threshold M / 9 is at most 1. 9 / M divides by the 0 in M,
            # so numpy warns (np.where then takes the other branch).
            assert np.all(np.where(M > 0, 9 / M, np.inf) >= 1)
            enlarged = np.repeat(np.repeat(gray, 3, axis=0), 3, axis=1)
            return (enlarged > np.tile(M / 9, gray.shape)).astype(float)
        """
    )
    return [
        Student("honest_stderr", L01, stderr, (), "a right answer that prints to stderr"),
        Student(
            "honest_warning",
            L06,
            warning,
            (),
            "a right answer that raises numpy's RuntimeWarning (np.where(M > 0, 9 / M, np.inf))",
        ),
    ]


def controls() -> list[Student]:
    """The teacher's answers and the stubs; and a witness whose answers are right in the
    kernel only (they call get_ipython first): 0 when the grade is the grader's."""
    witness = {
        function: source.replace('"""\n', '"""\n    get_ipython()\n', 1)
        for function, source in solutions(L01).items()
    }
    return (
        [
            Student(f"solved_{lesson[:2]}", lesson, solutions(lesson), (), "the teacher's answers")
            for lesson in LESSONS
        ]
        + [
            Student(f"stubs_{lesson[:2]}", lesson, {}, EXERCISES[lesson], "the edition's stubs")
            for lesson in LESSONS
        ]
        + [Student("kernel_only", L01, witness, EXERCISES[L01], "right in the kernel only")]
    )


#: Tricks past the issue's 25.
BEYOND = beyond_tricks()
TRICKS = issue_tricks() + BEYOND
HONEST = honest()
CONTROLS = controls()
STUDENTS = TRICKS + HONEST + CONTROLS


def submission(student: Student) -> str:
    """The student edition with the student's cells: its first code cell (the imports) and
    its nbgrader cells, the rest (pictures, apps) left out; then the student's edit."""
    notebook = json.loads(json.dumps(student_notebook(teacher(student.lesson))))
    answers = student.answers() if callable(student.answers) else student.answers
    kept, first_code = [], True
    for cell in notebook["cells"]:
        grade_id = cell["metadata"].get("nbgrader", {}).get("grade_id")
        if grade_id in answers:
            cell["source"] = answers[grade_id]
        if grade_id or (first_code and cell["cell_type"] == "code"):
            kept.append(cell)
        if cell["cell_type"] == "code":
            first_code = False
    notebook["cells"] = kept
    edited_notebook = student.edit(notebook) if student.edit else notebook
    return edited_notebook if isinstance(edited_notebook, str) else json.dumps(edited_notebook)


# --- nbgrader -----------------------------------------------------------------------------


def environment() -> dict[str, str]:
    """nbgrader on PATH (it runs alembic); nothing of the tests' on the kernel's path."""
    return {
        **os.environ,
        "PATH": f"{NBGRADER.parent}{os.pathsep}{os.environ['PATH']}",
        "MPLBACKEND": "Agg",
    }


def nbgrader(folder: Path, *arguments: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(NBGRADER), *arguments],
        cwd=folder,
        env=environment(),
        capture_output=True,
        text=True,
        timeout=1800,
    )


@dataclass
class Graded:
    """What one autograde run gave: each student's points per exercise, which submissions
    nbgrader refused, each test cell's outputs, the feedback pages, the seconds it took."""

    scores: dict[str, dict[str, float]]
    refused: set[str]
    outputs: dict[str, dict[str, list[dict]]]
    feedback: dict[str, str]
    seconds: float
    log: str


def grade_class(course: Path, students: list[Student], feedback: set[str]) -> Graded:
    start = time.perf_counter()
    for other in (course / "source").iterdir():  # the two lessons: one command for both
        if other.name not in LESSONS:
            shutil.rmtree(other)
    done = nbgrader(course, "generate_assignment", BOTH)
    assert done.returncode == 0, done.stderr[-3000:]
    for student in students:
        folder = course / "submitted" / student.name / student.lesson
        folder.mkdir(parents=True)
        (folder / f"{student.lesson}.ipynb").write_text(submission(student), encoding="utf-8")
    done = nbgrader(course, "autograde", BOTH, "--create")
    log = done.stdout + done.stderr
    refused = set(
        re.findall(r"There was an error processing assignment '\S+' for student '(\w+)'", log)
    )
    if feedback:  # named honest_*: one command for both lessons
        assert all(name.startswith("honest_") for name in feedback), feedback
        made = nbgrader(course, "generate_feedback", BOTH, "--student=honest_*")
        assert made.returncode == 0, made.stderr[-3000:]
    seconds = time.perf_counter() - start
    from nbgrader.api import Gradebook, MissingEntry

    scores: dict[str, dict[str, float]] = {}
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gradebook:
        for student in students:
            try:
                notebook = gradebook.find_submission_notebook(
                    student.lesson, student.lesson, student.name
                )
                scores[student.name] = {
                    grade.name.removesuffix("_test"): float(grade.score or 0)
                    for grade in notebook.grades
                }
            except MissingEntry:
                scores[student.name] = {}
    outputs: dict[str, dict[str, list[dict]]] = {}
    pages: dict[str, str] = {}
    for student in students:
        path = course / "autograded" / student.name / student.lesson / f"{student.lesson}.ipynb"
        if path.is_file():
            notebook = json.loads(path.read_text(encoding="utf-8"))
            outputs[student.name] = {
                cell["metadata"]["nbgrader"]["grade_id"].removesuffix("_test"): cell["outputs"]
                for cell in check_cells(notebook)
            }
        page = course / "feedback" / student.name / student.lesson / f"{student.lesson}.html"
        if page.is_file():
            pages[student.name] = unescape(page.read_text(encoding="utf-8"))
    return Graded(scores, refused, outputs, pages, seconds, log)


@pytest.fixture(scope="module")
def graded(tmp_path_factory) -> Graded:
    """Every submission, graded by nbgrader with the course's own nbgrader_config.py."""
    course = tmp_path_factory.mktemp("tricks") / "course"
    write_nbgrader_course(course)
    found = grade_class(course, STUDENTS, feedback={s.name for s in HONEST})
    print(f"\nnbgrader: {len(STUDENTS)} submissions graded in {found.seconds:.0f} s")
    print_table("The tricks, graded with the course's nbgrader_config.py:", found, STUDENTS)
    return found


def verdict(graded: Graded, student: str, exercise: str) -> str:
    """The report the grader put in the test cell (its first line), or what is there."""
    outputs = graded.outputs.get(student, {}).get(exercise)
    if outputs is None:
        return "refused by nbgrader" if student in graded.refused else "no test cell"
    for output in outputs:
        text = output.get("data", {}).get("text/plain")
        if text:
            return ("".join(text) if isinstance(text, list) else text).splitlines()[0]
    return "no report"


def print_table(title: str, found: Graded, students: list[Student]) -> None:
    print(f"\n{title}\nsubmission | targets | points on them | all points | first verdict")
    for student in students:
        scores = found.scores[student.name]
        points = sum(scores.get(e, 0) for e in student.targets)
        first = (student.targets or EXERCISES[student.lesson])[0]
        said = verdict(found, student.name, first)
        targets = ", ".join(student.targets) or "-"
        print(f"{student.name} | {targets} | {points:g} | {sum(scores.values()):g} | {said}")


def test_the_teachers_answers_get_every_point_and_the_stubs_none(graded):
    """The harness: solved lessons full marks, stubs 0, every exercise graded."""
    for student in CONTROLS:
        if student.name == "kernel_only":
            continue
        scores = graded.scores[student.name]
        assert set(scores) == set(EXERCISES[student.lesson]), (student.name, scores)
        assert scores == {e: (0.0 if student.targets else 1.0) for e in scores}, (
            student.name,
            scores,
            [verdict(graded, student.name, e) for e in scores],
        )


def test_the_grade_is_the_graders_not_the_kernels(graded):
    """A witness whose answers are right in the kernel only (each calls get_ipython()) gets
    0: the grade is the grader's verdict in the child, not what the kernel printed."""
    scores = graded.scores["kernel_only"]
    assert scores == {e: 0.0 for e in EXERCISES[L01]}, scores
    for exercise in EXERCISES[L01]:
        assert "NameError" in verdict(graded, "kernel_only", exercise)


@pytest.mark.parametrize("student", TRICKS, ids=[s.name for s in TRICKS])
def test_a_trick_scores_nothing_on_what_it_targets(student, graded):
    scores = graded.scores[student.name]
    won = {exercise: scores[exercise] for exercise in student.targets if scores.get(exercise)}
    assert not won, (
        f"{student.name} ({student.what}) scored {won}: "
        f"{[verdict(graded, student.name, e) for e in won]}"
    )
    if student.name not in graded.refused:  # each verdict a FAIL
        for exercise in student.targets:
            said = verdict(graded, student.name, exercise)
            assert said.startswith("FAIL") or said == "no test cell", (exercise, said)


@pytest.mark.parametrize("student", HONEST, ids=[s.name for s in HONEST])
def test_an_honest_answer_that_says_something_keeps_every_point(student, graded):
    scores = graded.scores[student.name]
    assert scores == {e: 1.0 for e in EXERCISES[student.lesson]}, (
        scores,
        [verdict(graded, student.name, e) for e in scores],
    )
    page = graded.feedback[student.name]
    said = "debug: a level of" if student.name == "honest_stderr" else "divide by zero"
    assert "What your code printed or warned (shown, never graded):" in page
    assert said in page, f"{said!r} is not in {student.name}'s feedback"
    assert "most recent call last" not in page


def test_nbgrader_refuses_only_what_it_cannot_run(graded):
    """nbgrader itself refuses a file that is not JSON, which scores 0, and nothing else. The
    kernel never calls the student's functions (it does not run the check cells), so
    functions that end their process (os._exit) end the grader's child alone: graded, 0,
    each verdict saying so."""
    assert graded.refused == {"corrupt_json"}, graded.refused
    assert not any(graded.scores["corrupt_json"].values())
    assert graded.scores["os_exit"] == {e: 0.0 for e in EXERCISES[L01]}
    for exercise in EXERCISES[L01]:
        assert verdict(graded, "os_exit", exercise).startswith("FAIL")
        report = str(graded.outputs["os_exit"][exercise])
        assert "your code ended the process it ran in" in report, report


@pytest.mark.skipif(not TODAY, reason="COURSE_TRICKS=today: the tricks against today's nbgrader")
def test_the_tricks_against_todays_nbgrader(tmp_path):
    """The same submissions graded without CheckOutsideKernel, for the record (printed with
    -s): what each trick scores when the kernel's outputs are the grade."""
    course = tmp_path / "course"
    write_nbgrader_course(course)
    with (course / "nbgrader_config.py").open("a", encoding="utf-8") as config:
        config.write(WITHOUT_THE_GRADER)
    found = grade_class(course, STUDENTS, feedback=set())
    print_table("The same tricks, graded by today's nbgrader (kernel outputs):", found, TRICKS)
    for student in HONEST:
        print(f"{student.name}: {found.scores[student.name]}")
    assert found.scores["solved_01"] == {e: 1.0 for e in EXERCISES[L01]}


#: Appended to the course's nbgrader_config.py: today's autograde, without the grader.
WITHOUT_THE_GRADER = (
    "\n_steps[_steps.index(ExecuteAnswers)] = Execute\n_steps.remove(CheckOutsideKernel)\n"
    "c.Autograde.autograde_preprocessors = _steps\n"
)


# --- the accidents ------------------------------------------------------------------------

#: How long the check may take on the wall clock: a case's wall-clock budget, after which
#: the grader kills the child, and a margin for a busy machine (the child's start, a fresh
#: interpreter importing numpy, is timed apart and not counted).
#: Each accident's time budget in the child: shorter than a lesson's (TIME_BUDGET), so that
#: the attacks only a limit stops take seconds, not tens; the limits are the same ones.
ACCIDENT_SECONDS = 1.0
WALL_BUDGET = ACCIDENT_SECONDS * outside._WALL_FACTOR + outside._WALL_EXTRA + 3.0

#: The attacks: the body of the student's function (indented by four), and how it is
#: stopped: "fast" (an error, or a refusal: well under a second), "cpu" (the child's
#: processor-time alarm, ACCIDENT_SECONDS) or "wall" (only the grader's kill on the wall clock).
ATTACKS: dict[str, tuple[str, str]] = {
    "python loop": ("while True:\n    pass", "cpu"),
    "loop catching the alarm": (
        "while True:\n    try:\n        while True:\n            pass\n"
        "    except BaseException:\n        pass",
        "wall",
    ),
    "alarm ignored": (
        "import signal\nsignal.signal(signal.SIGPROF, signal.SIG_IGN)\nwhile True:\n    pass",
        "wall",
    ),
    "time.sleep(60)": ("import time\ntime.sleep(60)", "wall"),
    "catastrophic regex": ("import re\nre.match(r'(a+)+$', 'a' * 64 + 'b')", "cpu"),
    "sum of a huge range, in C": ("return sum(range(10**13))", "wall"),
    "recursion without end": ("def again(n):\n    return again(n + 1)\nreturn again(0)", "fast"),
    "numpy memory at once": ("return np.ones((200_000, 200_000))", "fast"),
    "numpy memory growing": (
        "kept = []\nwhile True:\n    kept.append(np.ones(10**7))",
        "fast",
    ),
    "mmap of 3 GB": (
        "import mmap\nmapped = mmap.mmap(-1, 3 * 2**30)\n"
        "for i in range(0, len(mapped), 4096):\n    mapped[i] = 1\nreturn 0",
        "fast",
    ),
    "bytes growing": ("return b'x' * 2**34", "fast"),
    "a dtype that raises": (
        "class Lying:\n    shape = (2, 2)\n    @property\n    def dtype(self):\n"
        "        raise RuntimeError('no dtype')\n    def __array__(self, *a, **k):\n"
        "        raise RuntimeError('no array')\nreturn Lying()",
        "fast",
    ),
    "__eq__ always True": (
        "class Equal(float):\n    def __eq__(self, other):\n        return True\n"
        "    __hash__ = float.__hash__\nreturn Equal(1.0)",
        "fast",
    ),
    "__len__ lying": (
        "class Long(list):\n    def __len__(self):\n        return 10**12\nreturn Long([0.0, 1.0])",
        "fast",
    ),
    "endless iterator": ("import itertools\nreturn itertools.count()", "fast"),
    "endless generator": ("return (1.0 for _ in iter(int, 1))", "fast"),
    "lists nested deep": ("x = []\nfor _ in range(100_000):\n    x = [x]\nreturn x", "fast"),
    "a huge string": ("return 'x' * 300_000_000", "fast"),
    "SystemExit": ("raise SystemExit(3)", "fast"),
    "KeyboardInterrupt": ("raise KeyboardInterrupt", "fast"),
    "a BaseException of one's own": (
        "class Mine(BaseException):\n    pass\nraise Mine('mine')",
        "fast",
    ),
    "an exception whose str raises": (
        "class Odd(Exception):\n    def __str__(self):\n        raise SystemExit('str')\n"
        "raise Odd()",
        "fast",
    ),
    "os._exit(0)": ("import os\nos._exit(0)", "fast"),
    "SIGKILL to itself": ("import os, signal\nos.kill(os.getpid(), signal.SIGKILL)", "fast"),
    "garbage on the protocol's descriptors": (
        "import os\nfor fd in range(3, 32):\n    try:\n        os.write(fd, b'garbage\\n')\n"
        "    except OSError:\n        pass\nreturn 0",
        "fast",
    ),
    "forged answers on the protocol": (
        "import json, os\nfor fd in range(3, 32):\n    for asked in range(64):\n"
        "        forged = {'returned': 0.0, 'asked': asked, 'printed': ''}\n"
        "        try:\n            os.write(fd, (json.dumps(forged) + '\\n').encode())\n"
        "        except OSError:\n            pass\nraise ValueError('after the forgery')",
        "fast",
    ),
    "every descriptor closed": (
        "import os\nfor fd in range(32):\n    try:\n        os.close(fd)\n"
        "    except OSError:\n        pass\nreturn 0",
        "fast",
    ),
    "standard output closed": ("import sys\nsys.stdout.close()\nreturn 0", "fast"),
    "printing without end": ("while True:\n    print('x' * 1000)", "cpu"),
    "warnings without end": (
        "import warnings\nfor i in range(10**9):\n    warnings.warn(str(i))",
        "cpu",
    ),
}
#: How many checkers each kind of attack meets (of the 17).
MEETS = {"fast": 5, "cpu": 2, "wall": 1}
SEED = 33


def checker_parameters() -> dict[str, list[str]]:
    """Each declared exercise's function's parameters, from its teacher's answer cell."""
    import ast

    found = {}
    for path in sorted(NOTEBOOKS.glob("[0-9][0-9]_*.ipynb")):
        notebook = json.loads(path.read_text(encoding="utf-8"))
        for exercise in exercises(notebook):
            tree = ast.parse(cell_source(notebook["cells"][exercise.cell]))
            definition = next(
                node
                for node in ast.walk(tree)
                if isinstance(node, ast.FunctionDef) and node.name == exercise.function
            )
            found[exercise.function] = [argument.arg for argument in definition.args.args]
    return found


def checkers() -> list[str]:
    return sorted(e.name for chapter in course_exercises().values() for e in chapter)


def accident_pairs() -> list[tuple[str, str]]:
    """(attack, checker) pairs: each attack meets :data:`MEETS` checkers, dealt round a
    shuffled list so that every checker meets attacks of every kind it can; every attack
    meets every checker with ``COURSE_ACCIDENTS=all`` (510 pairs, about ten minutes)."""
    names = checkers()
    if os.environ.get("COURSE_ACCIDENTS") == "all":
        return [(attack, checker) for attack in ATTACKS for checker in names]
    rng = random.Random(SEED)
    rng.shuffle(names)
    pairs, position = [], 0
    for attack, (_, kind) in ATTACKS.items():
        for _ in range(MEETS[kind]):
            pairs.append((attack, names[position % len(names)]))
            position += 1
    return pairs


PAIRS = accident_pairs()
PARAMETERS = checker_parameters()
#: What the accidents gave, printed at the end of the module (-s).
ACCIDENTS: list[tuple[str, str, float, float, str]] = []


@pytest.fixture(scope="module", autouse=True)
def accident_table() -> Iterator[None]:
    yield
    if ACCIDENTS:
        print("\naccident | checker | start s | check s | report")
        for attack, checker, start, seconds, report in ACCIDENTS:
            print(f"{attack} | {checker} | {start:.1f} | {seconds:.1f} | {report}")


def attack_cell(attack: str, checker: str) -> tuple[str, str]:
    declaration = declared(checker)
    body, _ = ATTACKS[attack]
    parameters = ", ".join(PARAMETERS[declaration.name])
    cell = f"def {declaration.name}({parameters}):\n{textwrap.indent(body, '    ')}\n"
    return declaration.name, cell


@pytest.mark.parametrize(("attack", "checker"), PAIRS, ids=[f"{a}-{c}" for a, c in PAIRS])
def test_an_accident_in_the_graders_child_is_a_fail_within_the_budget(attack, checker):
    function, cell = attack_cell(attack, checker)
    start = time.perf_counter()
    stand_in = outside.outside_function([cell], function, seconds=ACCIDENT_SECONDS)
    checking = time.perf_counter()
    try:
        with grading(submission_seed("accident", checker)):
            result = declared(checker).checker(stand_in)
    finally:
        stand_in.close()
    seconds = time.perf_counter() - checking
    report = str(result)
    ACCIDENTS.append((attack, checker, checking - start, seconds, report.splitlines()[0][:110]))
    assert not result.passed, report
    assert "most recent call last" not in report and "Traceback" not in report, report
    assert str(REPOSITORY / "course") not in report and "course/" not in report, report
    assert seconds < WALL_BUDGET, f"{seconds:.1f} s (budget {WALL_BUDGET:g} s): {report}"


def test_the_pairs_reach_every_checker_and_every_attack():
    """The sample: all 17 checkers, each meeting at least five attacks; every attack met."""
    met: dict[str, set[str]] = {name: set() for name in checkers()}
    for attack, checker in PAIRS:
        met[checker].add(attack)
    assert len(met) == 17, sorted(met)
    assert all(len(attacks) >= 5 for attacks in met.values()), met
    assert {attack for attack, _ in PAIRS} == set(ATTACKS)


LINGERS = "import time; time.sleep(120)"


@pytest.mark.parametrize(
    "start",
    [
        f"subprocess.Popen([sys.executable, '-c', {LINGERS!r}]).pid",
        f"os.posix_spawn(sys.executable, [sys.executable, '-c', {LINGERS!r}], {{}})",
        "os.fork() or 0",
        "os.system('sleep 120 &')",
        "os.kill(os.getppid(), 0)",
    ],
)
def test_the_students_code_starts_no_process_and_signals_none(start):
    """The child refuses to start a process or to signal one; and were one started, the
    child's session is killed with it: no process is left on the grading server."""
    cell = "import os\nimport subprocess\nimport sys\n\n\n"
    cell += f"def next_level(control_points, t):\n    return {start}\n"
    before = sessions_of(os.getpid())
    stand_in = outside.outside_function([cell], "next_level")
    try:
        with pytest.raises((PermissionError, ImportError), match="grading process"):
            stand_in(np.zeros((2, 2)), 0.5)
    finally:
        stand_in.close()
    time.sleep(0.2)
    assert sessions_of(os.getpid()) <= before


def sessions_of(parent: int) -> set[int]:
    """The live pids whose parent is ``parent``, and those in a session one of them leads
    (Linux's /proc; elsewhere, none)."""
    if not Path("/proc").is_dir():
        return set()
    found: dict[int, tuple[int, int]] = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if fields[0] != "Z":
            found[int(entry.name)] = (int(fields[1]), int(fields[3]))
    children = {pid for pid, (ppid, _) in found.items() if ppid == parent}
    return children | {pid for pid, (_, session) in found.items() if session in children}
