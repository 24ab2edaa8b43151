"""course.classroom.edition: the student edition's stubs fail their checkers, the solutions pass."""

import ast
import copy
import difflib
import importlib.util
import itertools
import json
import re
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

from course.classroom.cli import main
from course.classroom.edition import (
    HIDDEN_NOTE,
    KERNELSPEC,
    hidden_note,
    reveals,
    solution_cells,
)
from course.classroom.edition_folder import MANIFEST, write_student_edition
from course.classroom.notebooks import notebooks
from course.classroom.release import EXERCISE_POINTS, exercises, student_notebook
from course.classroom.stubs import (
    BEGIN_SOLUTION,
    END_SOLUTION,
    STUB_LINE,
    exercise_stub,
    stub_line,
)
from course.classroom.twins import code_skeleton

SOLUTION = '''import math


@functools.cache
def area(w, h):
    """Width times height.

    More words.
    """
    if w < 0:  # the answer
        return 0
    return w * h


def perimeter(w,
              h):
    # the formula: 2 (w + h)
    return 2 * (w + h)


check.area(area)  # keep me
'''


def test_stub_keeps_signatures_docstrings_and_other_statements_only():
    stub = exercise_stub(SOLUTION)
    assert stub == (
        "import math\n\n\n@functools.cache\ndef area(w, h):\n"
        '    """Width times height.\n\n    More words.\n    """\n'
        f"    {STUB_LINE}\n\n\ndef perimeter(w,\n              h):\n    {STUB_LINE}\n\n\n"
        "check.area(area)  # keep me"
    )
    assert "the answer" not in stub and "formula" not in stub
    ast.parse(stub)


def test_stub_refuses_cells_without_a_function_or_with_a_one_line_body():
    with pytest.raises(ValueError, match="no def"):
        exercise_stub("x = 1\ncheck.x(x)")
    with pytest.raises(ValueError, match="own lines"):
        exercise_stub("def f(x): return x\n")


def test_a_scaffold_keeps_the_cell_and_stubs_only_what_is_marked():
    scaffold = (
        "def bezier(control_points, window):\n"
        "    height, width = window.shape[:2]\n"
        "    for k in range(1001):\n"
        f"        {BEGIN_SOLUTION}\n"
        "        x, y = recursive_bezier(control_points, k / 1000)\n"
        "        window[int(y), int(x)] = (0, 1, 0)\n"
        f"        {END_SOLUTION}\n"
        "\n\ncheck.bezier(bezier)"
    )
    assert exercise_stub(scaffold) == (
        "def bezier(control_points, window):\n"
        "    height, width = window.shape[:2]\n"
        "    for k in range(1001):\n"
        f"        {STUB_LINE}\n"
        "\n\ncheck.bezier(bezier)"
    )
    with pytest.raises(ValueError, match="without"):
        exercise_stub(f"def f():\n    {BEGIN_SOLUTION}\n    return 1")
    with pytest.raises(ValueError, match="never opened"):
        exercise_stub(f"def f():\n    return 1\n    {END_SOLUTION}")


def code_cell(source, tags=()):
    return {"cell_type": "code", "metadata": {"tags": list(tags)}, "source": source}


def test_cells_that_print_source_or_solve_a_variant_reveal_a_solution():
    assert reveals(code_cell("print(source_of(de_casteljau_recursive))"))
    assert reveals(code_cell("import inspect\ninspect.getsource(f)"))
    assert reveals(code_cell("de_casteljau??"))
    assert reveals(code_cell("def wrong(p, t): ...", tags=["reveals"]))
    assert not reveals(code_cell("check.f(f)  # source_of( in a solution cell", ["solution"]))
    assert not reveals(code_cell("de_casteljau(points, 0.5)"))
    assert not reveals({"cell_type": "markdown", "metadata": {}, "source": "source_of(f)"})


def test_student_notebook_is_nbgraders_release_and_leaves_the_input_alone():
    """Each exercise: its stub in an answer cell, its check in a locked cell under it; a cell
    that reveals an answer is a note, the source printer's import is gone, outputs cleared."""
    for book in notebooks(index=True):
        original = json.loads(book.path.read_text(encoding="utf-8"))
        untouched = copy.deepcopy(original)
        student = student_notebook(original)
        assert original == untouched
        assert solution_cells(student) == []
        assert "source_of" not in json.dumps(student)
        by_cell = {exercise.cell: exercise for exercise in exercises(original)}
        shown = iter(student["cells"])
        for index, before in enumerate(original["cells"]):
            text = "".join(before["source"])
            if before["cell_type"] == "code" and not reveals(before):
                text = "\n".join(
                    line for line in text.split("\n") if "import source_of" not in line
                ).strip("\n")
                if not text.strip():
                    continue  # only the source printer's import: no cell
            after = next(shown)
            if reveals(before):
                assert after["cell_type"] == "markdown" and after["source"] == HIDDEN_NOTE
            elif index in by_cell:
                exercise = by_cell[index]
                answer = "\n".join(text.splitlines()[: exercise.check_line - 1]).rstrip()
                assert "exercise" in after["metadata"]["tags"]
                assert after["source"] == exercise_stub(answer)
                assert after["metadata"]["nbgrader"]["grade_id"] == exercise.function
                check = next(shown)
                assert check["source"].endswith(f"{exercise.check}.graded()")
                assert check["metadata"]["editable"] is False
                assert check["metadata"]["nbgrader"]["points"] == EXERCISE_POINTS
            elif after["cell_type"] == "code":
                assert after["outputs"] == [] and after["execution_count"] is None
                assert "".join(after["source"]).strip("\n") == text
            else:
                assert after == before
        assert next(shown, None) is None
        nbformat.validate(nbformat.from_dict(student))


def test_write_student_edition_refuses_a_non_empty_folder_unless_forced(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(FileExistsError):
        write_student_edition(tmp_path)
    assert main(["student", "--out", str(tmp_path)]) == 2
    assert main(["student", "--out", str(tmp_path), "--force"]) == 0
    names = sorted(path.name for path in tmp_path.iterdir())
    expected = [book.path.name for book in notebooks(index=True)] + ["notes.txt", MANIFEST]
    assert names == sorted(expected)
    for path in tmp_path.glob("*.ipynb"):
        nbformat.validate(nbformat.read(path, as_version=4))


def lesson_folder(folder, *sources):
    """A folder of lessons 01, 02, ... whose single code cell has each source."""
    folder.mkdir(exist_ok=True)
    for number, source in enumerate(sources, start=1):
        notebook = {
            "cells": [
                {"cell_type": "markdown", "metadata": {}, "source": f"# Lesson {number}"},
                code_cell(source, ["solution"]) | {"outputs": [], "execution_count": None},
            ],
            "metadata": {},
            "nbformat": 4,
            "nbformat_minor": 5,
        }
        (folder / f"{number:02d}_lesson.ipynb").write_text(json.dumps(notebook))
    return folder


def edit(path, source):
    notebook = json.loads(path.read_text())
    notebook["cells"][1]["source"] = source
    path.write_text(json.dumps(notebook))


def test_rebuilding_the_edition_never_overwrites_a_students_work(tmp_path):
    lessons = lesson_folder(tmp_path / "lessons", "def f(x):\n    return x\n\n\ncheck.f(f)")
    out = tmp_path / "student"
    first = write_student_edition(out, lessons)
    assert [path.name for path in first.written] == ["01_lesson.ipynb"]
    lesson = out / "01_lesson.ipynb"
    assert STUB_LINE in json.loads(lesson.read_text())["cells"][1]["source"]
    # Run only (outputs, counts): not work; an unchanged lesson is left as it is.
    ran = json.loads(lesson.read_text())
    ran["cells"][1]["outputs"] = [{"output_type": "stream", "name": "stdout", "text": "FAIL"}]
    lesson.write_text(json.dumps(ran))
    again = write_student_edition(out, lessons)
    assert again.unchanged == [lesson] and again.written == []
    # The student writes the function; a rebuild keeps it, and a new lesson is added.
    edit(lesson, "def f(x):\n    return x  # mine\n\n\ncheck.f(f)")
    lesson_folder(
        lessons, "def f(x):\n    return x\n\n\ncheck.f(f)", "def g():\n    pass\n\n\ncheck.g(g)"
    )
    kept = write_student_edition(out, lessons)
    assert kept.kept == [lesson] and [p.name for p in kept.written] == ["02_lesson.ipynb"]
    assert "# mine" in lesson.read_text()
    # The lesson changes under the student's edits: the new one goes beside, and says so.
    lesson_folder(
        lessons, "def f(x, y):\n    return x\n\n\ncheck.f(f)", "def g():\n    pass\n\n\ncheck.g(g)"
    )
    changed = write_student_edition(out, lessons)
    beside = out / "01_lesson.new.ipynb"
    assert changed.beside == [(lesson, beside)]
    assert "# mine" in lesson.read_text() and "def f(x, y)" in beside.read_text()
    assert "01_lesson.new.ipynb, beside it" in changed.lines()[0]
    # A lesson the student never edited is updated in place.
    edit(lessons / "02_lesson.ipynb", "def g(y):\n    pass\n\n\ncheck.g(g)")
    updated = write_student_edition(out, lessons)
    assert out / "02_lesson.ipynb" in updated.written
    assert "def g(y)" in (out / "02_lesson.ipynb").read_text()
    assert sorted(p.name for p in out.iterdir()) == [
        MANIFEST, "01_lesson.ipynb", "01_lesson.new.ipynb", "02_lesson.ipynb"
    ]  # fmt: skip


def test_a_target_the_edition_cannot_write_is_refused_before_anything_is_written(tmp_path, capsys):
    lessons = lesson_folder(
        tmp_path / "lessons",
        "def f():\n    pass\n\n\ncheck.f(f)",
        "def g():\n    pass\n\n\ncheck.g(g)",
    )
    out = tmp_path / "student"
    (out / "02_lesson.ipynb").mkdir(parents=True)
    assert main(["student", "--notebooks", str(lessons), "--out", str(out), "--force"]) == 2
    error = capsys.readouterr().err
    assert "02_lesson.ipynb is a folder" in error and len(error.strip().splitlines()) == 1
    assert sorted(p.name for p in out.iterdir()) == ["02_lesson.ipynb"]  # nothing half-written


@pytest.mark.parametrize(
    "call",
    [
        lambda: solution_cells({}),
        lambda: solution_cells([]),
        lambda: student_notebook({"cells": [{}]}),
        lambda: student_notebook({"cells": [{"cell_type": "code", "source": 3}]}),
        lambda: reveals({"cell_type": "code", "source": "", "metadata": None}),
        lambda: exercise_stub("def f(:\n"),
        lambda: student_notebook(
            {
                "cells": [
                    {"cell_type": "code", "source": "def f(:", "metadata": {"tags": ["solution"]}}
                ]
            }
        ),
    ],
)
def test_a_malformed_notebook_or_cell_is_a_value_error(call):
    with pytest.raises(ValueError, match=r"^(notebook|cell|source)"):
        call()


@pytest.mark.parametrize(
    "text, said",
    [("{}", "not an nbformat 4 notebook"), ("[1, 2]", "not an nbformat 4 notebook"),
     ("{", "not a notebook file")],
)  # fmt: skip
@pytest.mark.parametrize("command", ["student", "gallery", "nbgrader"])
def test_a_malformed_notebook_is_one_line_and_exit_2_for_every_command(
    tmp_path, capsys, text, said, command
):
    (tmp_path / "lessons").mkdir()
    (tmp_path / "lessons" / "01_x.ipynb").write_text(text)
    out = tmp_path / "out"
    code = main([command, "--notebooks", str(tmp_path / "lessons"), "--out", str(out)])
    error = capsys.readouterr().err
    assert code == 2 and said in error and len(error.strip().splitlines()) == 1, error
    assert not out.exists() or not any(out.iterdir())


def test_every_lesson_carries_the_kernelspec_jupyterlab_writes():
    for book in notebooks(index=True):
        notebook = json.loads(book.path.read_text(encoding="utf-8"))
        assert notebook["metadata"]["kernelspec"] == KERNELSPEC, book.path.name


def make_variable(name: str, bin_folder: Path) -> list[str]:
    """The command the Makefile names ``name``, split into words, with ``$(BIN)`` filled in."""
    makefile = (Path(__file__).parents[1] / "Makefile").read_text(encoding="utf-8")
    found = re.search(rf"^{name} = ((?:.*\\\n)*.*)$", makefile, re.MULTILINE)
    assert found, f"the Makefile defines no {name}"
    return found[1].replace("\\\n", " ").replace("$(BIN)", str(bin_folder)).split()


def test_no_stored_cell_splits_its_printed_lines_in_two_outputs():
    """JupyterLab joins a cell's consecutive stream outputs; a stored split is a diff at save."""
    for path in sorted(Path(__file__).parents[1].glob("notebooks/**/*.ipynb")):
        notebook = json.loads(path.read_text(encoding="utf-8"))
        for cell in notebook["cells"]:
            names = [out.get("name") for out in cell.get("outputs", [])]
            twice = [a for a, b in itertools.pairwise(names) if a is not None and a == b]
            assert not twice, (path.name, cell.get("id"), twice)


#: Exercises whose checker draws no picture on a pass: a number or a table says it all.
NO_PASS_PICTURE = {"comb", "bilinear_sample"}


def test_every_stored_pass_shows_its_picture_in_both_languages():
    """A pass picture that raises is dropped in silence by the checker: its absence is the sign."""
    passes = 0
    for path in sorted(Path(__file__).parents[1].glob("notebooks/**/[0-9][0-9]_*.ipynb")):
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            outputs = cell.get("outputs", [])
            texts = ["".join(out["data"].get("text/plain", "")) for out in outputs if "data" in out]
            found = re.match(r"PASS (\w+)|(\w+) 通过：", texts[0]) if texts else None
            if found is None or (found[1] or found[2]) in NO_PASS_PICTURE:
                continue
            passes += 1
            assert any("image/png" in out["data"] for out in outputs if "data" in out), (
                path.name,
                cell["id"],
            )
    assert passes >= 2 * 15


def test_executing_and_stripping_as_make_notebooks_does_leaves_the_kernelspec(tmp_path):
    """``make notebooks`` runs nbconvert --execute, joins the streams, then nbstripout.

    The metadata stays, the cell keeps its id (the twins' catalogs are keyed by it), and a
    cell's two flushes of stdout are saved as one output, as JupyterLab saves them.
    """
    lesson = json.loads((notebooks()[0].path).read_text(encoding="utf-8"))
    notebook = {
        "cells": [
            code_cell("import sys\nprint(6 * 7)\nsys.stdout.flush()\nprint(6 * 9)")
            | {"outputs": [], "execution_count": None, "id": "code-kept"}
        ],
        "metadata": lesson["metadata"],
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    path = tmp_path / "01_small.ipynb"
    path.write_text(json.dumps(notebook))
    bin_folder = Path(sys.executable).parent
    for command in (
        [bin_folder / "jupyter", "nbconvert", "--to", "notebook", "--execute", "--inplace", path],
        [*make_variable("COALESCE", bin_folder), path],
        [*make_variable("STRIP", bin_folder), path],
    ):
        done = subprocess.run(command, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
    executed = json.loads(path.read_text())
    assert ["".join(out["text"]) for out in executed["cells"][0]["outputs"]] == ["42\n54\n"]
    assert executed["metadata"]["kernelspec"] == KERNELSPEC
    assert executed["cells"][0]["id"] == notebook["cells"][0]["id"]


def result_text(cell) -> str:
    """The checker's report: the check cell's last output with text (its picture follows)."""
    texts = [
        out["data"]["text/plain"]
        for out in cell.outputs
        if out.output_type in ("execute_result", "display_data") and "text/plain" in out["data"]
    ]
    assert texts, f"the check cell must show the checker's report; got {cell.outputs}"
    return texts[-1]


EXERCISE_BOOKS = [
    book
    for book in notebooks()
    if solution_cells(json.loads(book.path.read_text(encoding="utf-8")))
]


def solution_triples(original_source: str) -> set[tuple[str, ...]]:
    """Every three consecutive non-blank lines of what the stub removes from a solution cell."""
    before = original_source.splitlines()
    after = exercise_stub(original_source).splitlines()
    triples = set()
    matcher = difflib.SequenceMatcher(a=before, b=after, autojunk=False)
    for kind, start, end, _, _ in matcher.get_opcodes():
        if kind in ("replace", "delete"):
            removed = [line.strip() for line in before[start:end] if line.strip()]
            triples |= {tuple(removed[i : i + 3]) for i in range(len(removed) - 2)}
    return triples


def text_triples(text: str) -> set[tuple[str, ...]]:
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return {tuple(lines[i : i + 3]) for i in range(len(lines) - 2)}


def output_text(cell) -> str:
    parts = []
    for out in cell.get("outputs", []):
        parts.append("".join(out.get("text", "")))
        for kind, value in out.get("data", {}).items():
            if kind.startswith("text/"):
                parts.append("".join(value))
    return "\n".join(parts)


@pytest.mark.parametrize("book", EXERCISE_BOOKS, ids=lambda book: book.path.stem)
def test_every_exercise_fails_as_shipped_passes_restored_and_nothing_gives_it_away(book):
    original = nbformat.read(book.path, as_version=4)
    student = nbformat.from_dict(student_notebook(original))
    solutions = solution_cells(original)
    answers = set().union(*(solution_triples(original.cells[i].source) for i in solutions))
    client = NotebookClient(
        student,
        timeout=300,
        kernel_name="python3",
        resources={"metadata": {"path": str(book.path.parent)}},
    )
    found = {exercise.function: exercise for exercise in exercises(original)}
    checked = 0
    shipped_cells = {}
    with client.setup_kernel():
        for index, cell in enumerate(student.cells):
            if cell.cell_type != "code":
                continue
            client.execute_cell(cell, index)
            grade_id = cell.metadata.get("nbgrader", {}).get("grade_id", "")
            if not grade_id.endswith("_test"):
                continue
            shipped = result_text(cell)
            shipped_cells[index] = copy.deepcopy(cell)  # executing the solution replaces it
            assert shipped.startswith("FAIL "), shipped
            assert "NotImplementedError: your code here" in shipped
            restored = copy.deepcopy(original.cells[found[grade_id.removesuffix("_test")].cell])
            restored.outputs = []
            client.execute_cell(restored, index)
            assert result_text(restored).startswith("PASS "), result_text(restored)
            again = copy.deepcopy(cell)
            client.execute_cell(again, index)
            assert result_text(again).startswith("PASS "), result_text(again)
            checked += 1
    assert checked == len(solutions) > 0
    # The edition as run, sources and outputs, holds no three lines of any solution.
    cells = [shipped_cells.get(index, cell) for index, cell in enumerate(student.cells)]
    shown = "\n".join(cell.source + "\n" + output_text(cell) for cell in cells)
    leaked = answers & text_triples(shown)
    assert not leaked, f"{book.path.name} shows solution lines: {sorted(leaked)[:3]}"


# The published website (site/stage.py) is the student edition too.
_spec = importlib.util.spec_from_file_location(
    "stage", Path(__file__).resolve().parent.parent / "site" / "stage.py"
)
stage = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(stage)


def site_text(value) -> str:
    return value if isinstance(value, str) else "".join(value)


def site_solution_triples(source: str) -> set[tuple[str, ...]]:
    """Every three consecutive lines the stub takes out of a solution."""
    kept = {line.strip() for line in exercise_stub(source).splitlines()}
    removed = [line.strip() for line in source.splitlines() if line.strip()]
    removed = [line for line in removed if line not in kept]
    return {tuple(removed[i : i + 3]) for i in range(len(removed) - 2)}


def shown_triples(notebook: dict) -> set[tuple[str, ...]]:
    """Every three consecutive lines a page shows: sources and text outputs."""
    parts = []
    for cell in notebook["cells"]:
        parts.append(site_text(cell["source"]))
        for output in cell.get("outputs", []):
            parts.append(site_text(output.get("text", "")))
            for kind, value in output.get("data", {}).items():
                if kind.startswith("text/"):
                    parts.append(site_text(value))
    lines = [line.strip() for part in parts for line in part.splitlines() if line.strip()]
    return {tuple(lines[i : i + 3]) for i in range(len(lines) - 2)}


def fake_mathjax(folder: Path) -> Path:
    for part in stage.MATHJAX_PARTS:
        path = folder / part if part.endswith(".js") else folder / part / "x.js"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(f"// {part}")
    (folder / "sre").mkdir()
    (folder / "sre" / "big.js").write_text("// not needed by a page")
    return folder


def test_the_published_source_shows_stubs_and_no_solution_and_the_teachers_keeps_them(tmp_path):
    stage.stage(tmp_path / "site", captions={}, mathjax=fake_mathjax(tmp_path / "es5"))
    stage.stage(tmp_path / "teacher", captions={}, teacher=True)
    leaking_pages = 0
    exercises = 0
    for book in notebooks(index=True):
        teacher = json.loads(book.path.read_text(encoding="utf-8"))
        name = "index.ipynb" if book.number == "00" else book.path.name
        page = json.loads((tmp_path / "site" / name).read_text(encoding="utf-8"))
        answers = set()
        for before, after in zip(teacher["cells"], page["cells"], strict=False):
            if "solution" in before.get("metadata", {}).get("tags", []):
                exercises += 1
                answers |= site_solution_triples(site_text(before["source"]))
                assert STUB_LINE in after["source"] and after["outputs"] == []
            elif reveals(before):
                assert after["source"] == HIDDEN_NOTE
        if answers & shown_triples(page):
            leaking_pages += 1
        kept = json.loads((tmp_path / "teacher" / name).read_text(encoding="utf-8"))
        assert answers <= shown_triples(kept), "the teacher's build keeps the solutions"
    assert exercises > 0
    assert leaking_pages == 0
    bundled = tmp_path / "site" / "_mathjax" / "mathjax"
    assert (bundled / "tex-mml-chtml.js").is_file()
    assert (bundled / "output" / "chtml" / "fonts" / "woff-v2" / "x.js").is_file()
    assert not (bundled / "sre").exists()


def unsummed(metadata: dict) -> dict:
    """Cell metadata without nbgrader's checksum, which a translated comment changes."""
    grading = {k: v for k, v in metadata.get("nbgrader", {}).items() if k != "checksum"}
    return {**metadata, "nbgrader": grading} if grading else metadata


def uncommented(source) -> str:
    lines = "".join(source).splitlines()
    return "\n".join(line for line in lines if not line.lstrip().startswith("#"))


def test_the_chinese_student_edition_is_the_english_one_with_the_chinese_text():
    """The twins go through the same parser: the same stubs, hidden cells and tags."""
    from course.classroom.notebooks import language_folder
    from course.i18n import LANGUAGE_LINES

    english_books = notebooks(index=True)
    chinese_books = notebooks(language_folder(english_books[0].path.parent, "zh-CN"), index=True)
    assert [book.path.name for book in chinese_books] == [book.path.name for book in english_books]
    for english_book, chinese_book in zip(english_books, chinese_books, strict=True):
        english = student_notebook(json.loads(english_book.path.read_text(encoding="utf-8")))
        chinese = student_notebook(json.loads(chinese_book.path.read_text(encoding="utf-8")))
        assert len(chinese["cells"]) == len(english["cells"]), chinese_book.path.name
        first_code = True
        for ours, theirs in zip(chinese["cells"], english["cells"], strict=True):
            assert (ours["cell_type"], unsummed(ours["metadata"])) == (
                theirs["cell_type"],
                unsummed(theirs["metadata"]),
            )
            if "hidden" in ours["metadata"].get("tags", []):
                assert ours["source"] == hidden_note("zh-CN") != theirs["source"] == HIDDEN_NOTE
            if ours["cell_type"] != "code":
                continue
            source = "".join(ours["source"])
            if first_code:
                assert source.startswith(LANGUAGE_LINES), chinese_book.path.name
                source, first_code = source[len(LANGUAGE_LINES) :], False
            if ours["metadata"].get("nbgrader", {}).get("locked"):  # a check: its comments differ
                source, theirs = uncommented(source), {"source": uncommented(theirs["source"])}
            # The same code but the stubs' message, the docstrings and the comments.
            source = code_skeleton(source.replace(stub_line("zh-CN"), STUB_LINE))
            assert source == code_skeleton("".join(theirs["source"])), (
                chinese_book.path.name,
                ours["id"],
            )
            assert ours["outputs"] == [] and ours["execution_count"] is None
        chinese_text = json.dumps(chinese, ensure_ascii=False)
        assert "your code here" not in chinese_text, chinese_book.path.name
        stubs = chinese_text.count(stub_line("zh-CN"))
        assert stubs == json.dumps(english).count(STUB_LINE)
        text = "".join(
            "".join(cell["source"]) for cell in chinese["cells"] if cell["cell_type"] == "markdown"
        )
        assert sum("\u4e00" <= letter <= "\u9fff" for letter in text) > 100, chinese_book.path.name


def test_the_chinese_student_editions_stubs_and_the_checkers_report_of_them_are_chinese(
    tmp_path,
):
    from course.classroom.notebooks import NOTEBOOKS, language_folder
    from course.i18n import message_language
    from course.lessons.l01_de_casteljau import check

    lessons = tmp_path / "lessons"
    lessons.mkdir()
    name = "01_de_casteljau.ipynb"
    (lessons / name).write_bytes((language_folder(NOTEBOOKS, "zh-CN") / name).read_bytes())
    write_student_edition(tmp_path / "student", lessons)
    text = (tmp_path / "student" / name).read_text(encoding="utf-8")
    assert "your code here" not in text
    answers = [
        "".join(cell["source"])
        for cell in json.loads(text)["cells"]
        if "exercise" in cell["metadata"].get("tags", [])
    ]
    assert answers and all('raise NotImplementedError("在这里写你的代码")' in a for a in answers)
    namespace = {}
    exec(answers[0], namespace)  # next_level, as the student edition hands it out
    with message_language("zh-CN"):
        report = str(check.next_level(namespace["next_level"]))
    said = "你还没有写这个函数（它抛出了 NotImplementedError：“在这里写你的代码”）"
    assert report.startswith(f"next_level 未通过：{said}\n"), report
    english = str(check.next_level(namespace["next_level"]))  # English is the source's own
    assert "not written yet: your function raised NotImplementedError: 在这里写你的代码" in english


def test_the_chinese_published_source_shows_stubs_and_no_solution(tmp_path):
    from course.classroom.notebooks import language_folder

    twins = language_folder(notebooks()[0].path.parent, "zh-CN")
    pictures = stage.stage(tmp_path / "site", twins, captions={}, language="zh-CN")
    assert pictures > 0
    exercises = 0
    for book in notebooks(twins, index=True):
        teacher = json.loads(book.path.read_text(encoding="utf-8"))
        name = "index.ipynb" if book.number == "00" else book.path.name
        page = json.loads((tmp_path / "site" / name).read_text(encoding="utf-8"))
        answers = set()
        for before, after in zip(teacher["cells"], page["cells"], strict=False):
            if "solution" in before.get("metadata", {}).get("tags", []):
                exercises += 1
                answers |= site_solution_triples(site_text(before["source"]))
                assert stub_line("zh-CN") in after["source"] and after["outputs"] == []
        assert not answers & shown_triples(page), name
    assert exercises > 0
    alt = json.loads((tmp_path / "site" / "alt.json").read_text(encoding="utf-8"))
    # No caption given: each picture is described by its Chinese page's own words.
    assert alt and all(any("\u4e00" <= c <= "\u9fff" for c in text) for text in alt.values())
