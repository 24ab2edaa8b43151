"""``python -m course mistakes``: the class's named mistakes, read after ``nbgrader autograde``.

Each autograded test cell displays its checker's report with ``metadata["course"]["check"]``
(passed, the named mistake's English name or null, the report's text). Per exercise, in
lesson order, this counts the students who passed, made each named mistake the checker knows
(0 when nobody did), failed without a named mistake, submitted nothing, or whose test did not
run; the class is every student of ``autograded/``, ``submitted/`` and ``gradebook.db``. One
example diagnosis per outcome is the report of the lowest student id, never a name. Labels
follow :func:`course.i18n.message_language`; reports keep the notebooks' language. Standard
library only at import: the checkers and matplotlib are imported when used.
"""

from __future__ import annotations

import argparse
import csv
import importlib
import io
import os
import sqlite3
import sys
import unicodedata
import warnings
from collections.abc import Iterator
from contextlib import closing, contextmanager, nullcontext
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from unittest import mock

from course.classroom.folders import check_output_folder, read_json_file, require_inside
from course.i18n import DEFAULT_LANGUAGE, LANGUAGES, N_, _, current_language, message_language

# The command-line helpers (add_mistakes_command, run) are for cli.py only.
__all__ = [
    "ExerciseOutcomes",
    "Outcome",
    "add_mistakes_command",
    "checker_mistakes",
    "class_mistakes",
    "mistakes_table",
    "run",
    "write_mistakes",
]

#: The outcomes besides the named mistakes, in their order; shown with ``_()``.
PASSED = N_("passed")
FAILED = N_("failed, not named")
NOT_SUBMITTED = N_("not submitted")
DID_NOT_RUN = N_("test did not run")
#: The CSV's columns, shown with ``_()``.
COLUMNS = (N_("lesson"), N_("exercise"), N_("outcome"), N_("students"), N_("example"))
#: The chart's width and each panel's height per bar, in inches, and its resolution.
CHART_WIDTH, BAR_HEIGHT, CHART_DPI = 11.0, 0.32, 100
#: The kinds of outcome, and each one's colour in the chart.
KINDS = ("passed", "mistake", "failed", "not submitted", "did not run")
COLOURS = dict(zip(KINDS, "#4c9a2a #e08a1e #c0392b #9e9e9e #616161".split(), strict=True))


@dataclass(frozen=True)
class Outcome:
    """How many students' tests ended one way (a :data:`KINDS`), its English ``name``."""

    kind: str
    name: str
    students: int
    example: str = ""  # one failing student's report (the lowest id's), or ""


@dataclass(frozen=True)
class ExerciseOutcomes:
    """One exercise of one assignment: the function the students wrote, its outcomes."""

    assignment: str
    function: str
    checker: str
    outcomes: tuple[Outcome, ...]


def checker_mistakes(checker: str) -> list[str]:
    """The English names of the mistakes the exercise's checker names, each once, in order.

    ``checker`` is the exercise's one name, its checker's. The checker runs
    once with ``run_cases`` and ``call_budget`` recording their ``mistakes`` and ``too_many``.

    Examples
    --------
    >>> checker_mistakes("next_level")[:2]
    ['the reversed step', 'one point short']
    """
    from course.check.base import CheckResult
    from course.check.exercises import declared
    from course.classroom.exercise_list import course_exercises

    course_exercises()  # imports every chapter's checkers, which declares them
    try:
        found = declared(checker)
    except (LookupError, TypeError) as error:
        raise ValueError(_("checker: {error}").format(error=error)) from None
    names: list[str] = []

    @contextmanager
    def budget(*args: Any, too_many: Any = None, **kwargs: Any) -> Iterator[None]:
        names.extend([too_many.name] if too_many is not None else [])
        yield

    def record(exercise: str, student: Any, cases: Any, *args: Any, **kwargs: Any) -> Any:
        names.extend(mistake.name for mistake in kwargs.get("mistakes", ()))
        with (kwargs.get("watch") or nullcontext)():  # comb's sets a call budget
            pass
        return CheckResult(exercise, True, 0, "recorded")

    module = importlib.import_module(found.module)
    swapped = {"run_cases": record, "call_budget": budget}
    recording = mock.patch.multiple(
        module, **{k: v for k, v in swapped.items() if hasattr(module, k)}
    )
    with message_language(DEFAULT_LANGUAGE), recording:
        found.checker(lambda *args: None)
    return list(dict.fromkeys(names))


def _read_json(path: Path) -> Any:
    try:
        return read_json_file(path)
    except (OSError, ValueError):  # a pipe, not UTF-8, not JSON, nested too deep
        return None  # an unreadable notebook is one whose tests did not run


def _folders(folder: Path) -> list[str]:
    if not folder.is_dir():
        return []
    return sorted(p.name for p in folder.iterdir() if p.is_dir() and not p.name.startswith("."))


def _class_list(course: Path) -> list[str]:
    """Every student nbgrader knows: submitted or autograded, or in the gradebook."""
    students = set(_folders(course / "autograded")) | set(_folders(course / "submitted"))
    database = course / "gradebook.db"
    if database.is_file():
        try:
            uri = f"{database.resolve().as_uri()}?mode=ro"
            with closing(sqlite3.connect(uri, uri=True)) as db:
                students |= {str(row[0]) for row in db.execute("SELECT id FROM student")}
        except sqlite3.Error:
            pass  # another nbgrader's schema: the folders still say who submitted
    return sorted(students)


def _assignments(course: Path) -> list[str]:
    found = set(_folders(course / "source")) | set(_folders(course / "release"))
    for kind in ("autograded", "submitted"):
        for student in _folders(course / kind):
            found |= set(_folders(course / kind / student))
    return sorted(found)


def _at(value: Any, *keys: str) -> Any:
    """``value[key][...]``, or None where a level is not a dict (a notebook edited by hand)."""
    for key in keys:
        value = value.get(key) if isinstance(value, dict) else None
    return value


def _test_cells(notebook: Any) -> Iterator[tuple[str, dict[str, Any]]]:
    """(function, cell) for each autograded test cell, ``grade_id`` ``<function>_test``."""
    for cell in _at(notebook, "cells") or []:
        grade_id = _at(cell, "metadata", "nbgrader", "grade_id")
        if _at(cell, "metadata", "nbgrader", "grade") and str(grade_id).endswith("_test"):
            yield str(grade_id).removesuffix("_test"), cell


def _check_of(cell: dict[str, Any]) -> dict[str, Any] | None:
    """The last checker's report the cell displayed (``metadata["course"]["check"]``)."""
    outputs = [o for o in _at(cell, "outputs") or [] if _at(o, "output_type") == "display_data"]
    checks = [_at(output, "metadata", "course", "check") for output in outputs]
    return next((check for check in reversed(checks) if isinstance(check, dict)), None)


def _exercises(assignment: str, notebooks: list[Any]) -> list[Any]:
    """The declared exercises the assignment's notebooks test, in their order."""
    from course.check.exercises import declared
    from course.classroom.exercise_list import course_exercises

    by_lesson = course_exercises()  # imports every chapter's checkers, which declares them
    found = []
    for notebook in notebooks:
        for function, _cell in _test_cells(notebook):
            try:
                exercise = declared(function)
            except LookupError:
                continue  # a test of the teacher's own, not a course exercise
            if exercise not in found:
                found.append(exercise)
    # No test cell anywhere (every notebook broken, no source/): the lesson's, by its number.
    found = found or list(by_lesson.get(assignment[:2], []))
    if not found:
        raise ValueError(
            _("assignments: {assignment} holds none of the course's exercises").format(
                assignment=repr(assignment)
            )
        )
    return found


def _english_mistake(name: str, known: list[str]) -> str:
    """A mistake's English name, also for a name a Chinese notebook gave in Chinese."""
    from course.i18n import gettext_catalog

    chinese = gettext_catalog("zh_CN").gettext
    return next((msgid for msgid in known if name in (msgid, chinese(msgid))), name)


def class_mistakes(
    course: str | os.PathLike[str], assignments: list[str] | None = None
) -> list[ExerciseOutcomes]:
    """Every exercise's outcomes in the autograded notebooks of the nbgrader ``course`` folder.

    ``assignments`` lists the assignments to read (by default every one the folder holds),
    reported in lesson order. A student without notebooks for an assignment did not submit
    it; a test cell without the checker's report did not run.

    Examples
    --------
    >>> class_mistakes("no-such-folder")
    Traceback (most recent call last):
    ...
    ValueError: course: no autograded nbgrader course at no-such-folder (run nbgrader autograde)
    """
    if isinstance(course, bool) or not isinstance(course, (str, os.PathLike)):
        raise TypeError(
            _("course: expected a folder path; got {course_type}").format(
                course_type=type(course).__name__
            )
        )
    folder = Path(course)
    if not (folder / "autograded").is_dir():
        raise ValueError(
            _("course: no autograded nbgrader course at {course} (run nbgrader autograde)").format(
                course=folder
            )
        )
    known = _assignments(folder)
    assignments = known if assignments is None else assignments
    if isinstance(assignments, str) or not isinstance(assignments, (list, tuple)):
        raise TypeError(
            _("assignments: expected a list of assignment names; got {assignments_type}").format(
                assignments_type=type(assignments).__name__
            )
        )
    missing = [name for name in assignments if name not in known]
    if missing:
        raise ValueError(
            _("assignments: no assignment {name} in {course} (it has: {known})").format(
                name=repr(missing[0]), course=folder, known=", ".join(known) or _("none")
            )
        )
    students = _class_list(folder)
    chosen = sorted(dict.fromkeys(assignments))
    return [row for name in chosen for row in _assignment_outcomes(folder, name, students)]


def _assignment_outcomes(
    course: Path, assignment: str, students: list[str]
) -> list[ExerciseOutcomes]:
    templates = sorted((course / "source" / assignment).glob("*.ipynb"))
    names = {path.name for path in templates}
    submitted: dict[str, list[Any]] = {}
    for student in students:
        paths = sorted((course / "autograded" / student / assignment).glob("*.ipynb"))
        paths = [path for path in paths if not names or path.name in names]
        if paths or (course / "submitted" / student / assignment).is_dir():
            submitted[student] = [_read_json(path) for path in paths]
    models = [_read_json(path) for path in templates] or [
        notebook for notebooks in submitted.values() for notebook in notebooks
    ]
    found = []
    for exercise in _exercises(assignment, models):
        # Each student's report of this exercise; None: submitted, but the test did not run.
        reports: dict[str, dict[str, Any] | None] = {}
        for student, notebooks in sorted(submitted.items()):
            cells = [c for nb in notebooks for f, c in _test_cells(nb) if f == exercise.name]
            reports[student] = next(filter(None, map(_check_of, cells)), None)
        outcomes = _counted(reports, checker_mistakes(exercise.name), len(students))
        found.append(ExerciseOutcomes(assignment, exercise.name, exercise.name, outcomes))
    return found


def _counted(
    reports: dict[str, dict[str, Any] | None], known: list[str], class_size: int
) -> tuple[Outcome, ...]:
    """The outcomes of the students' ``reports`` (by student id, in order)."""
    named: dict[str, list[str]] = {name: [] for name in known}
    passed, failed, silent = [], [], []
    for student, report in reports.items():
        if report is None:
            silent.append(student)
        elif report.get("passed") is True:
            passed.append(student)
        elif isinstance(report.get("mistake"), str) and report["mistake"]:
            named.setdefault(_english_mistake(report["mistake"], known), []).append(student)
        else:
            failed.append(student)

    def example(who: list[str]) -> str:
        text = (reports[who[0]] or {}).get("report", "") if who else ""
        return text if isinstance(text, str) else ""

    return (
        Outcome("passed", PASSED, len(passed)),
        *(Outcome("mistake", name, len(who), example(who)) for name, who in named.items()),
        Outcome("failed", FAILED, len(failed), example(failed)),
        Outcome("not submitted", NOT_SUBMITTED, class_size - len(reports)),
        Outcome("did not run", DID_NOT_RUN, len(silent)),
    )


def _width(text: str) -> int:
    """The columns ``text`` takes in a terminal: a CJK letter takes two."""
    return sum(2 if unicodedata.east_asian_width(c) in "WF" else 1 for c in text)


def mistakes_table(outcomes: list[ExerciseOutcomes]) -> str:
    """The counts as a terminal table, then each example diagnosis; in the current language.

    Examples
    --------
    >>> row = ExerciseOutcomes("01_de_casteljau", "next_level", "next_level",
    ...     (Outcome("passed", PASSED, 3), Outcome("failed", FAILED, 1, "FAIL next_level: ...")))
    >>> print(mistakes_table([row]))
    lesson           exercise    outcome            students
    01_de_casteljau  next_level  passed                    3
                                 failed, not named         1
    <BLANKLINE>
    01_de_casteljau, next_level, failed, not named:
        FAIL next_level: ...
    """
    if not isinstance(outcomes, list) or not all(
        isinstance(row, ExerciseOutcomes) for row in outcomes
    ):
        raise TypeError(_("outcomes: expected the list class_mistakes returns"))
    rows = [[_(column) for column in COLUMNS[:4]]]
    for row in outcomes:
        for i, outcome in enumerate(row.outcomes):
            first = [row.assignment, row.function] if i == 0 else ["", ""]
            rows.append([*first, _(outcome.name), str(outcome.students)])
    widths = [max(_width(line[column]) for line in rows) for column in range(4)]

    def cell(text: str, column: int) -> str:
        if column == 3:
            return text.rjust(widths[3])
        return text + " " * (widths[column] - _width(text))

    lines = ["  ".join(cell(text, c) for c, text in enumerate(line)).rstrip() for line in rows]
    for row in outcomes:
        for outcome in row.outcomes:
            if outcome.example:
                lines += ["", f"{row.assignment}, {row.function}, {_(outcome.name)}:"]
                lines += ["    " + line for line in outcome.example.splitlines()]
    return "\n".join(lines)


def _csv_text(outcomes: list[ExerciseOutcomes]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow([_(column) for column in COLUMNS])
    writer.writerows(
        [row.assignment, row.function, _(outcome.name), outcome.students, outcome.example]
        for row in outcomes
        for outcome in row.outcomes
    )
    return buffer.getvalue()


def _cjk_font() -> str | None:
    """A font family with Chinese letters: the Chinese lessons' own, or one matplotlib knows."""
    import matplotlib as mpl
    from matplotlib import font_manager

    from course.i18n import language

    try:
        with mpl.rc_context(), language("zh-CN"):  # adds the course's Noto Sans SC, as lessons do
            return str(mpl.rcParams["font.family"][-1])
    except (ImportError, OSError, RuntimeError, ValueError):
        pass
    hints = ("CJK", "Noto Sans SC", "Source Han", "WenQuanYi", "SimHei", "YaHei", "PingFang")
    names = sorted({entry.name for entry in font_manager.fontManager.ttflist})
    return next((name for name in names if any(hint in name for hint in hints)), None)


def _draw_chart(outcomes: list[ExerciseOutcomes], path: Path, font: str | None) -> None:
    """One panel per exercise, a bar per outcome, all on the class's scale; deterministic."""
    import matplotlib as mpl
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    heights = [0.9 + BAR_HEIGHT * len(row.outcomes) for row in outcomes] or [1.0]
    families = [*mpl.rcParams["font.family"], font] if font else mpl.rcParams["font.family"]
    with mpl.rc_context({"font.family": families, "font.size": 9}):
        size = (CHART_WIDTH, 0.6 + sum(heights))
        figure = Figure(figsize=size, dpi=CHART_DPI, layout="constrained")
        FigureCanvasAgg(figure)
        figure.suptitle(_("The class's mistakes"))
        axes = figure.subplots(max(1, len(outcomes)), 1, squeeze=False, height_ratios=heights)
        top = max([1] + [sum(outcome.students for outcome in row.outcomes) for row in outcomes])
        for panel, row in zip(axes[:, 0], outcomes, strict=False):
            counts = [outcome.students for outcome in row.outcomes]
            places = list(range(len(counts)))
            panel.barh(places, counts, color=[COLOURS[outcome.kind] for outcome in row.outcomes])
            panel.set_yticks(places, [_(outcome.name) for outcome in row.outcomes])
            panel.invert_yaxis()
            panel.set_title(f"{row.assignment} · {row.function}", loc="left")
            panel.set_xlim(0, top * 1.08)
            panel.set_xlabel(_("students"))
            panel.xaxis.get_major_locator().set_params(integer=True)
            for place, count in zip(places, counts, strict=True):
                panel.text(count + top * 0.01, place, str(count), va="center")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a missing glyph is said once, by run()
            figure.savefig(path, format="png", metadata={"Software": None})


def write_mistakes(outcomes: list[ExerciseOutcomes], out: str | os.PathLike[str]) -> list[Path]:
    """Write the counts as ``mistakes.csv`` and ``mistakes.png`` into ``out``; their paths.

    In the current language; a language other than English suffixes the names
    (``mistakes.zh-CN.csv``), so each language's files stay. The CSV has one row per
    exercise and outcome, UTF-8 with a byte-order mark (spreadsheets then read Chinese).
    A file of those names that is a link leading outside ``out`` is refused.
    """
    mistakes_table(outcomes)  # checks the outcomes
    check_output_folder(out, force=True)
    folder = Path(out)
    language = current_language()
    stem = "mistakes" if language == DEFAULT_LANGUAGE else f"mistakes.{language}"
    font = _cjk_font() if language != DEFAULT_LANGUAGE else None
    require_inside(folder, [folder / f"{stem}.csv", folder / f"{stem}.png"])
    try:
        folder.mkdir(parents=True, exist_ok=True)
        (folder / f"{stem}.csv").write_text(_csv_text(outcomes), encoding="utf-8-sig")
        _draw_chart(outcomes, folder / f"{stem}.png", font)
    except OSError as error:
        raise ValueError(
            _("out: cannot write into {out} ({reason})").format(
                out=folder, reason=error.strerror or error
            )
        ) from None
    return [folder / f"{stem}.csv", folder / f"{stem}.png"]


def add_mistakes_command(commands: argparse._SubParsersAction) -> None:
    """Add ``mistakes`` to ``python -m course``'s commands."""
    command = commands.add_parser(
        "mistakes", help="after nbgrader autograde: the class's named mistakes, per exercise"
    )
    add, folder = command.add_argument, "the nbgrader course folder (default: build/nbgrader)"
    add("--course", type=Path, default=Path("build", "nbgrader"), metavar="DIR", help=folder)
    add("--assignment", nargs="+", action="extend", metavar="NAME", help="default: every one")
    add("--out", type=Path, metavar="DIR", help="the files' folder (default: <course>/mistakes/)")
    add("--language", help=f"{' or '.join(LANGUAGES)} (default: $COURSE_LANG, else en)")


def run(args: argparse.Namespace) -> int:
    """``python -m course mistakes``: print the table, write the files; the exit status."""
    language = args.language or os.environ.get("COURSE_LANG") or DEFAULT_LANGUAGE
    try:
        if language not in LANGUAGES:
            raise ValueError(
                _("{named}: expected one of {choices}; got {language:.60}").format(
                    named="--language", choices=", ".join(LANGUAGES), language=repr(language)
                )
            )
        with message_language(language):
            outcomes = class_mistakes(args.course, args.assignment)
            print(mistakes_table(outcomes))
            if language != DEFAULT_LANGUAGE and _cjk_font() is None:
                warning = _(
                    "no Chinese font was found (pip install pylopdf-fonts-zh-cn): the chart shows "
                    "boxes for its Chinese letters; the table and the CSV are whole"
                )
                print(warning, file=sys.stderr)
            written = write_mistakes(outcomes, args.out or Path(args.course) / "mistakes")
            done = _("wrote {count} files to {out}").format(count=2, out=written[0].parent)
    except (OSError, ValueError, TypeError) as error:
        print(f"python -m course mistakes: {error}", file=sys.stderr)
        return 2
    print(done, file=sys.stderr)
    return 0
