"""course.check.sandbox.student_line: the line a student's error came from, as they see it."""

import linecache

import numpy as np
import pytest

from course.check import budget, sandbox


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


def test_the_line_is_joined_to_its_place_as_the_language_joins_them():
    from course.i18n import message_language

    error = _raised_from("/tmp/ipykernel_4242/2718281828.py", "def f(a):\n    return a / 0\n")
    with message_language("zh-CN"):
        assert sandbox.student_line(error) == "你的单元格第 2 行，在 f 中：return a / 0"


def test_an_error_in_a_file_keeps_the_files_line():
    error = _raised_from("/tmp/their_module.py", "def f(a):\n    return a / 0\n")
    assert sandbox.student_line(error) == "line 2 of f: return a / 0"


CPU_CLOCK = pytest.mark.skipif(
    not hasattr(budget.time, "pthread_getcpuclockid"), reason="no per-thread CPU clock here"
)


@CPU_CLOCK
def test_a_case_that_waits_is_not_stopped_by_the_budget_for_computing():
    # A right answer on a busy machine waits for a core: the budget counts its computing only.
    def waits():
        budget.time.sleep(0.3)
        return "done"

    assert sandbox.run_bounded(waits, seconds=0.1) == "done"


def test_a_case_that_waits_forever_is_stopped_on_the_wall_clock():
    def waits_forever():
        while True:
            budget.time.sleep(0.01)

    with pytest.raises(sandbox.CaseStopped, match=r"did not stop within 0\.02 s"):
        sandbox.run_bounded(waits_forever, seconds=0.02)


def test_a_loop_that_computes_forever_is_stopped():
    def computes_forever():
        total = 0
        while True:
            total += 1

    with pytest.raises(sandbox.CaseStopped) as stopped:
        sandbox.run_bounded(computes_forever, seconds=0.05)
    assert stopped.value.kind == "time"


@pytest.mark.parametrize(
    ("before", "after", "said"),
    [
        ([1.0, 1.0], [1.0, 1.0000001], "element [1] was 1.0, is now 1.0000001"),
        ([0.0, 0.5], [0.0, 2.0], "element [1] was 0.5, is now 2"),
        ([12345678], [12345679], "element [0] was 12345678, is now 12345679"),
    ],
)
def test_a_changed_element_is_shown_with_the_digits_that_tell_its_values_apart(before, after, said):
    names, old, new = ("image",), (np.array(before),), (np.array(after),)
    assert sandbox.changed_argument(names, old, new) == f"image: {said}"
