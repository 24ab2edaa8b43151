"""course.check.sandbox.student_line: the line a student's error came from, as they see it."""

import linecache

import pytest

from course.check import sandbox


def _raised_from(filename: str, source: str) -> BaseException:
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    namespace: dict = {}
    exec(compile(source, filename, "exec"), namespace)
    with pytest.raises(ZeroDivisionError) as caught:
        namespace["f"](1)
    return caught.value


@pytest.mark.parametrize(
    "filename", ["/tmp/ipykernel_4242/3141592653.py", "<ipython-input-7-0123456789ab>"]
)
def test_an_error_in_a_notebook_cell_is_placed_on_the_cells_own_line(filename):
    # ipykernel compiles each cell on its own (nbconvert on a real kernel gives "line 6 of your
    # cell" for an error on the cell's sixth line), so the number counts from the cell's top.
    error = _raised_from(filename, "x = 1\n\n\ndef f(a):\n    y = 2\n    return a / 0\n")
    assert sandbox.student_line(error) == "line 6 of your cell, in f: return a / 0"


def test_an_error_in_a_file_keeps_the_files_line():
    error = _raised_from("/tmp/their_module.py", "def f(a):\n    return a / 0\n")
    assert sandbox.student_line(error) == "line 2 of f: return a / 0"
