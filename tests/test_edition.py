"""course.classroom.edition: the student edition's stubs fail their checkers, the solutions pass."""

import ast
import copy
import json

import nbformat
import pytest
from nbclient import NotebookClient

from course.classroom.cli import main
from course.classroom.edition import (
    STUB_LINE,
    exercise_stub,
    solution_cells,
    student_notebook,
    write_student_edition,
)
from course.classroom.notebooks import notebooks

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


def test_student_notebook_replaces_solutions_clears_outputs_and_leaves_the_input_alone():
    book = notebooks()[0]
    original = json.loads(book.path.read_text(encoding="utf-8"))
    untouched = copy.deepcopy(original)
    student = student_notebook(original)
    assert original == untouched
    assert solution_cells(student) == []
    assert len(student["cells"]) == len(original["cells"])
    for before, after in zip(original["cells"], student["cells"], strict=True):
        if after["cell_type"] == "code":
            assert after["outputs"] == [] and after["execution_count"] is None
        if "solution" in before["metadata"].get("tags", []):
            assert "exercise" in after["metadata"]["tags"]
            assert after["source"] == exercise_stub("".join(before["source"]))
        else:
            assert after["source"] == before["source"]


def test_write_student_edition_refuses_a_non_empty_folder_unless_forced(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(FileExistsError):
        write_student_edition(tmp_path)
    assert main(["student", "--out", str(tmp_path)]) == 2
    assert main(["student", "--out", str(tmp_path), "--force"]) == 0
    names = sorted(path.name for path in tmp_path.iterdir())
    assert names == sorted([book.path.name for book in notebooks(index=True)] + ["notes.txt"])
    for path in tmp_path.glob("*.ipynb"):
        nbformat.validate(nbformat.read(path, as_version=4))


def result_text(cell) -> str:
    results = [out for out in cell.outputs if out.output_type == "execute_result"]
    assert results, f"the exercise cell must end with its checker call; got {cell.outputs}"
    return results[-1]["data"]["text/plain"]


EXERCISE_BOOKS = [
    book
    for book in notebooks()
    if solution_cells(json.loads(book.path.read_text(encoding="utf-8")))
]


@pytest.mark.parametrize("book", EXERCISE_BOOKS, ids=lambda book: book.path.stem)
def test_every_exercise_fails_as_shipped_and_passes_with_the_solution_restored(book):
    original = nbformat.read(book.path, as_version=4)
    student = nbformat.from_dict(student_notebook(original))
    solutions = solution_cells(original)
    client = NotebookClient(
        student,
        timeout=300,
        kernel_name="python3",
        resources={"metadata": {"path": str(book.path.parent)}},
    )
    checked = 0
    with client.setup_kernel():
        for index, cell in enumerate(student.cells):
            if cell.cell_type != "code":
                continue
            client.execute_cell(cell, index)
            if index not in solutions:
                continue
            shipped = result_text(cell)
            assert shipped.startswith("FAIL "), shipped
            assert "NotImplementedError: your code here" in shipped
            restored = copy.deepcopy(original.cells[index])
            restored.outputs = []
            client.execute_cell(restored, index)
            assert result_text(restored).startswith("PASS "), result_text(restored)
            checked += 1
    assert checked == len(solutions) > 0
