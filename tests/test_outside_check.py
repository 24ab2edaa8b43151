"""course.check.outside: a student's function run in a child process, under the OS's limits.

The stand-in must behave as the function for a checker (values, parameters, errors, changed
arguments, budgets), while nothing of the grader's process is reachable from the child.
"""

from __future__ import annotations

import inspect
import io
import json
import re
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import course
from course.check._wire import BYTES, Unreadable, decode, encode, read_message, write_message
from course.check.outside import outside_function
from course.check.references import CallBudget, call_budget
from course.check.sandbox import CaseStopped, student_line

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the child's limits are POSIX")


@pytest.fixture
def stand_in():
    made = []

    def make(source: str, function: str, **options):
        made.append(outside_function([source], function, **options))
        return made[-1]

    yield make
    for function in made:
        function.close()


def test_values_cross_as_plain_numbers_text_lists_and_arrays(stand_in):
    echo = stand_in(
        "def echo(x):\n    return x, [1, 2.5, 'a', None, True], 2**80, float('nan'), 1 + 2j",
        "echo",
    )
    array = np.arange(6.0).reshape(2, 3)
    (back, plain, big, nan, complex_number) = echo(array)
    assert isinstance(back, np.ndarray) and np.array_equal(back, array)
    assert plain == [1, 2.5, "a", None, True] and big == 2**80
    assert np.isnan(nan) and complex_number == 1 + 2j
    assert str(inspect.signature(echo)) == "(x)"


ARRAYS = [
    np.arange(6.0).reshape(2, 3).T,  # not contiguous
    np.array(2.5),  # no dimensions
    np.zeros((0, 3)),
    np.array([True, False]),
    np.arange(4, dtype=np.uint8),
    np.arange(3, dtype=">i4"),  # big-endian
    np.array([1 + 2j, -3j], dtype=np.complex64),
    np.random.default_rng(0).random((700, 700, 3)),  # a lesson's window
]


def test_arrays_of_every_kind_cross_and_come_back_writable(stand_in):
    echo = stand_in("def echo(*arrays):\n    return list(arrays)", "echo")
    back = echo(*ARRAYS)
    assert len(back) == len(ARRAYS)
    for sent, got in zip(ARRAYS, back, strict=True):
        assert got.dtype == sent.dtype and got.shape == sent.shape
        assert np.array_equal(got, sent) and got.flags.writeable


def test_an_iterator_arrives_as_its_items_and_an_object_as_its_type(stand_in):
    pixels = stand_in("def pixels(n):\n    return ((i, i) for i in range(n))", "pixels")
    assert pixels(3) == [(0, 0), (1, 1), (2, 2)]
    odd = stand_in("class Odd:\n    pass\n\ndef odd():\n    return Odd()", "odd")
    assert repr(odd()) == "<Odd>"


def test_an_argument_the_function_changed_comes_back_changed(stand_in):
    paint = stand_in("def paint(window):\n    window[0, 0] = 1.0", "paint")
    window = np.zeros((2, 2))
    assert paint(window) is None
    assert window[0, 0] == 1.0


def test_errors_keep_their_type_and_the_student_s_line(stand_in):
    broken = stand_in("def broken(x):\n    y = 1\n    return y / x", "broken")
    with pytest.raises(ZeroDivisionError) as raised:
        broken(0)
    assert student_line(raised.value) == "in your cell: return y / x"
    stub = stand_in('def stub():\n    raise NotImplementedError("your code here")', "stub")
    with pytest.raises(NotImplementedError, match="your code here"):
        stub()
    leaving = stand_in("def leaving():\n    raise SystemExit(3)", "leaving")
    with pytest.raises(Exception) as left:  # never a SystemExit in the grader
        leaving()
    assert type(left.value).__name__ == "SystemExit" and isinstance(left.value, Exception)


def test_the_child_has_numpy_but_not_the_course_nor_the_grader(stand_in):
    probe = stand_in(
        "import sys\n\ndef probe(name):\n"
        "    try:\n        __import__(name)\n    except ImportError:\n        return False\n"
        "    return True",
        "probe",
    )
    assert probe("numpy") is True
    assert probe("course") is False and probe("nbgrader") is False and probe("pytest") is False


def test_a_loop_that_does_not_end_is_stopped_and_the_next_case_runs(stand_in):
    spin = stand_in("def spin(n):\n    while n:\n        pass\n    return 7", "spin", seconds=0.5)
    started = time.monotonic()
    with pytest.raises(CaseStopped, match=r"did not stop within 0\.5 s"):
        spin(1)
    assert time.monotonic() - started < 8
    assert spin(0) == 7  # a fresh child for the next case


def test_a_call_that_waits_is_killed_on_the_wall_clock(stand_in):
    wait = stand_in("import time\n\ndef wait():\n    time.sleep(60)", "wait", seconds=0.2)
    started = time.monotonic()
    with pytest.raises(CaseStopped):
        wait()
    assert time.monotonic() - started < 10


def test_memory_past_the_limit_stops_the_case(stand_in):
    hog = stand_in(
        "import numpy as np\n\ndef hog():\n    return np.ones(2**31)", "hog", memory=256 * 2**20
    )
    with pytest.raises(CaseStopped, match="memory"):
        hog()


def test_an_endless_iterator_is_stopped_not_listed(stand_in):
    endless = stand_in(
        "import itertools\n\ndef endless():\n    return itertools.count()", "endless", seconds=1
    )
    started = time.monotonic()
    with pytest.raises(CaseStopped):
        endless()
    assert time.monotonic() - started < 10


def test_a_call_budget_is_kept_in_the_child(stand_in):
    comb = stand_in(
        "def comb(m, n):\n    if n in (0, m):\n        return 1\n"
        "    return comb(m - 1, n) + comb(m - 1, n - 1)",
        "comb",
    )
    with call_budget(max_calls=1000), pytest.raises(CallBudget, match="more than 1,000"):
        comb(30, 15)
    assert comb(5, 2) == 10


def test_what_the_code_printed_or_warned_is_kept_apart(stand_in):
    noisy = stand_in(
        "import sys\nimport numpy as np\n\ndef noisy(m):\n"
        "    print('debug', file=sys.stderr)\n    return np.where(m > 0, 9 / m, np.inf)",
        "noisy",
    )
    assert noisy(np.array([0.0, 3.0])).tolist() == [np.inf, 3.0]
    assert "debug" in "".join(noisy.outside.printed)
    assert any("divide by zero" in warning for warning in noisy.outside.warned)


def test_a_cell_that_does_not_define_the_function_is_a_name_error(stand_in):
    empty = stand_in("x = 1", "missing")
    with pytest.raises(NameError, match="does not define missing"):
        empty()


def test_lines_written_to_the_grader_s_channel_are_not_taken_for_the_answer(stand_in):
    forger = stand_in(
        "import os\n\ndef forger():\n"
        "    for descriptor in range(3, 20):\n"
        "        try:\n"
        '            os.write(descriptor, b\'garbage\\n{"returned": 42, "asked": 999}\\n\')\n'
        "        except OSError:\n"
        "            pass\n"
        "    return 1",
        "forger",
    )
    assert forger() == 1
    assert forger() == 1  # and the channel is still in step


def test_arrays_written_to_the_grader_s_channel_are_not_taken_for_the_answer(stand_in):
    # A forged answer with the bytes of an array, for a question not asked: read and skipped.
    forger = stand_in(
        "import os\n\ndef forger(window):\n"
        "    window[0, 0] = 7.0\n"
        "    for descriptor in range(3, 20):\n"
        "        try:\n"
        '            os.write(descriptor, b\'{"returned": {"array": ["<f8", [1], 0]}, \'\n'
        '                     b\'"asked": 999, "buffers": [8]}\\n\' + bytes(8))\n'
        "        except OSError:\n"
        "            pass\n"
        "    return window.sum()",
        "forger",
    )
    window = np.zeros((4, 4))
    assert forger(window) == 7.0 and window[0, 0] == 7.0
    assert forger(np.ones((2, 2))) == 10.0  # and the channel is still in step


def framed(*messages: tuple[dict, list]) -> io.BytesIO:
    stream = io.BytesIO()
    for message, buffers in messages:
        write_message(stream, message, buffers)
    stream.seek(0)
    return stream


def test_a_message_s_arrays_travel_as_bytes_after_its_line():
    buffers: list = []
    message = {"values": [encode(array, buffers) for array in ARRAYS[:-1]], "n": 1}
    stream = framed((message, buffers))
    line = stream.getvalue().split(b"\n", 1)[0]
    assert json.loads(line)["buffers"] == [array.nbytes for array in ARRAYS[:-1]]
    got, got_buffers = read_message(stream, 10**6)
    assert got["n"] == 1 and read_message(stream, 10**6) is None  # then the stream ends
    for sent, back in zip(ARRAYS, got["values"], strict=False):
        decoded = decode(back, got_buffers)
        assert decoded.dtype == sent.dtype and np.array_equal(decoded, sent)


def test_reading_skips_what_is_not_a_message_and_stops_at_a_cut_buffer():
    stream = io.BytesIO(
        b"garbage \xff\xfe\n"  # not JSON, not even UTF-8
        b"[1, 2]\n"  # not an object
        b'{"buffers": [-1]}\n'  # not sizes
        b'{"buffers": [1000]}\n'  # more than the bound
        + b"x" * 50  # a line longer than the bound: skipped in pieces
        + b'\n{"asked": 3, "buffers": [2, 0]}\nab{"asked": 4}\n'
        + b'{"asked": 5, "buffers": [4]}\nab'  # its buffer cut short: the child died
    )
    assert read_message(stream, 40) == (
        {"asked": 3, "buffers": [2, 0]},
        [bytearray(b"ab"), bytearray()],
    )
    assert read_message(stream, 40) == ({"asked": 4}, [])
    assert read_message(stream, 40) is None


@pytest.mark.parametrize(
    "spec",
    [
        ["|O", [1], 0],  # objects
        ["<U1", [2], 0],  # text
        ["<f8", [3], 0],  # more than the buffer holds
        ["<f8", [-1], 0],
        ["<f8", [1], 5],  # no such buffer
        ["not a dtype", [1], 0],
        "<f8",
    ],
)
def test_an_array_its_buffer_cannot_hold_is_refused(spec):
    with pytest.raises(Unreadable) as refused:
        decode({"array": spec}, [bytearray(8)])
    assert refused.value.args == (BYTES, 0)


def test_a_forged_answer_for_the_question_asked_is_a_case_stopped_if_unreadable(stand_in):
    # The load is question 1, the first call question 2: its forged answer says 3 numbers
    # lie in 8 bytes.
    forger = stand_in(
        "import os\n\ndef forger():\n"
        "    for descriptor in range(3, 20):\n"
        "        try:\n"
        '            os.write(descriptor, b\'{"returned": {"array": ["<f8", [3], 0]}, \'\n'
        '                     b\'"asked": 2, "buffers": [8]}\\n\' + bytes(8))\n'
        "        except OSError:\n"
        "            pass\n"
        "    return 1",
        "forger",
    )
    with pytest.raises(CaseStopped, match="bytes do not match its shape and type"):
        forger()


COURSE_FILE = str(Path(course.__file__).resolve())


@pytest.mark.parametrize(
    ("body", "refused"),
    [
        # The library's source, and the site packages' .pth files that make it importable.
        (f"return open({COURSE_FILE!r}).read()", "reads no file"),
        (
            "import os, site\n"
            "site.addsitedir(os.path.dirname(os.path.dirname(os.path.realpath(np.__file__))))\n"
            "import course\n"
            "return 1",
            "No module named 'course'",
        ),
        # numpy's folder is a link: climbing out of it would reach the site packages.
        (
            "import os\n"
            "return open(os.path.dirname(np.__file__) + '/../course/__init__.py').read()",
            "'..'",
        ),
        ("open('/tmp/course-outside-escape.txt', 'w').write('x')\nreturn 1", "writes only"),
        ("import ctypes\nreturn 1", "does not load"),
        ("import socket\nreturn socket.socket()", "does not allow socket"),
        ("import gc\nreturn len(gc.get_objects())", "does not allow gc.get_objects"),
    ],
)
def test_the_child_reads_nothing_of_the_course_and_starts_nothing(stand_in, body, refused):
    cell = "def escape():\n" + "".join(f"    {line}\n" for line in body.splitlines())
    with pytest.raises(Exception, match=re.escape(refused)):
        stand_in(cell, "escape")()
    assert not Path("/tmp/course-outside-escape.txt").exists()


def test_the_child_writes_and_reads_its_own_folder_and_uses_the_standard_library(stand_in):
    body = (
        "import fractions, json, statistics\n"
        "def work():\n"
        "    with open('notes.json', 'w') as notes:\n"
        "        json.dump([1, 2, 3], notes)\n"
        "    with open('notes.json') as notes:\n"
        "        numbers = json.load(notes)\n"
        "    half = float(fractions.Fraction(1, 2))\n"
        "    return statistics.mean(numbers) + half + np.linalg.norm([3, 4])\n"
    )
    assert stand_in(body, "work")() == 7.5
