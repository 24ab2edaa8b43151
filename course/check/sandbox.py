"""Running a student's function safely: its budget, its inputs kept, its errors read.

The call itself runs under a time and a memory budget (:func:`run_bounded`,
:class:`CaseStopped`, from :mod:`course.check.budget`, re-exported here); the
checker's own work runs in :class:`course.check.views.CheckersView`. This module
copies a case's inputs for the call (:func:`copies`) and finds what the call
changed in them (:func:`changed_argument`), reads the student's function
before it runs (:func:`arity_problem`, :func:`is_stub`) and the line of theirs
an error came from (:func:`student_line`).

Unchecked: this is the checkers' kernel (``UNCHECKED = True``). It runs and
copies whatever it is given, NaN included; ``course.check.base`` validates
what reaches it.
"""

from __future__ import annotations

import ast
import copy
import inspect
import os
import sys
import textwrap
import traceback
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from course.check.budget import MEMORY_BUDGET, TIME_BUDGET, CaseStopped, run_bounded
from course.i18n import _

UNCHECKED = True  # see the module docstring

__all__ = [
    "MEMORY_BUDGET",
    "TIME_BUDGET",
    "CaseStopped",
    "arity_problem",
    "case_inputs",
    "changed_argument",
    "copies",
    "describe_function",
    "is_notebook_cell",
    "is_stub",
    "run_bounded",
    "student_line",
]

_COURSE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Frames in these folders are the course's, Python's or a library's, never the student's.
_NOT_THEIRS = tuple(
    {_COURSE, *(os.path.abspath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix))}
)

# Held from import: a cell that patches copy.deepcopy does not share the inputs.
_deepcopy = copy.deepcopy


def copies(values: tuple[Any, ...]) -> tuple[Any, ...]:
    """Deep copies of a case's inputs, so the student's code cannot change the checker's."""
    return tuple(_deepcopy(value) for value in values)


def changed_argument(
    names: tuple[str, ...], before: tuple[Any, ...], after: tuple[Any, ...]
) -> str | None:
    """The first argument the call changed, and where, in words; None if none changed.

    Examples
    --------
    >>> changed_argument(("a", "b"), (1, np.zeros(3)), (1, np.array([0.0, 2.0, 0.0])))
    'b: element [1] was 0, is now 2'
    >>> changed_argument(("a",), ([1, 2],), ([1, 2, 3],)) is None
    False
    """
    for name, old, new in zip(names, before, after, strict=True):
        where = _first_change(old, new)
        if where is not None:
            return _("{name}: {where}").format(name=name, where=where)
    return None


def _first_change(old: Any, new: Any) -> str | None:
    if isinstance(old, np.ndarray):
        if not isinstance(new, np.ndarray) or new.shape != old.shape:
            return _("its shape was {old}, is now {new}").format(old=old.shape, new=np.shape(new))
        if old.dtype.kind in "fc":
            differ = ~((old == new) | (np.isnan(old) & np.isnan(new)))
        else:
            differ = old != new
        if not differ.any():
            return None
        index = tuple(int(i) for i in np.argwhere(differ)[0])
        where = "[" + ", ".join(map(str, index)) + "]"
        before, after = _told_apart(old[index], new[index])
        return _("element {where} was {old}, is now {new}").format(
            where=where, old=before, new=after
        )
    if isinstance(old, (list, tuple)):
        if not isinstance(new, type(old)) or len(new) != len(old):
            return _("it was {old}, is now {new}").format(old=_short(old), new=_short(new))
        for index, (a, b) in enumerate(zip(old, new, strict=True)):
            inner = _first_change(a, b)
            if inner is not None:
                return _("item [{index}]: {inner}").format(index=index, inner=inner)
        return None
    try:
        same = bool(old == new)
    except Exception:
        return None
    if same:
        return None
    return _("it was {old}, is now {new}").format(old=_short(old), new=_short(new))


def _told_apart(old: Any, new: Any) -> tuple[str, str]:
    """Two differing array elements in words, with as many digits as it takes to tell them apart.

    Six significant digits, unless both look the same at six: then each is written in full
    (the shortest text that reads back as that number), so a change of one part in ten million
    is not shown as "was 1, is now 1".

    Examples
    --------
    >>> _told_apart(np.float64(0.5), np.float64(2.0))
    ('0.5', '2')
    >>> _told_apart(np.float64(1.0), np.float64(1.0000001))
    ('1.0', '1.0000001')
    >>> _told_apart(np.int64(12345678), np.int64(12345679))
    ('12345678', '12345679')
    """
    old, new = np.asarray(old).item(), np.asarray(new).item()
    if isinstance(old, (bool, int)) and isinstance(new, (bool, int)):
        return str(old), str(new)
    try:
        short = f"{old:.6g}", f"{new:.6g}"
    except (TypeError, ValueError):  # an object array's elements: their own text
        return _short(old), _short(new)
    if short[0] != short[1]:
        return short
    return repr(old), repr(new)


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def arity_problem(function: Callable[..., Any], parameters: tuple[str, ...]) -> str | None:
    """Why ``function`` cannot be called with the handout's parameters by position, or None.

    Examples
    --------
    >>> arity_problem(lambda p: p, ("control_points", "t"))
    'expected 2 parameters, (control_points, t); your function takes 1, (p)'
    >>> arity_problem(lambda a, b, c=0: a, ("control_points", "t")) is None
    True
    """
    try:
        signature = inspect.signature(function)
    except Exception:  # a builtin without a signature, an odd callable: the call will tell
        return None
    try:
        signature.bind(*parameters)
        return None
    except TypeError:
        pass
    names = [
        p.name
        for p in signature.parameters.values()
        if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
    ]
    count = len(parameters)
    if count == 1:
        text = _("expected {count} parameter, ({expected}); your function takes {taken}, ({names})")
    else:
        text = _(
            "expected {count} parameters, ({expected}); your function takes {taken}, ({names})"
        )
    return text.format(
        count=count, expected=", ".join(parameters), taken=len(names), names=", ".join(names)
    )


def is_stub(function: Callable[..., Any]) -> bool:
    """Whether ``function``'s body does nothing yet: a docstring, ``pass``, ``...`` or a raise."""
    try:
        source = textwrap.dedent(inspect.getsource(function))
        tree = ast.parse(source)
    except Exception:  # no source to read (a builtin, an odd callable): not a stub
        return False
    definitions = [n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)]
    if not definitions:
        return False
    body = list(definitions[0].body)
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
        body = body[1:]  # the docstring
    for statement in body:
        if isinstance(statement, (ast.Pass, ast.Raise)):
            continue
        if isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant):
            continue  # `...`
        if isinstance(statement, ast.Return) and statement.value is None:
            continue
        return False
    return True


def student_line(error: BaseException) -> str | None:
    """The line of the student's code that raised ``error``: the last frame outside the course.

    Examples
    --------
    >>> def mine():
    ...     return 1 / 0
    >>> try:
    ...     mine()
    ... except ZeroDivisionError as error:
    ...     print(student_line(error))
    line 2 of mine: return 1 / 0
    """
    told = getattr(error, "course_student_line", None)  # from a child (course.check.outside)
    if isinstance(told, str):
        return told
    frames = traceback.extract_tb(error.__traceback__)
    own = [
        f
        for f in frames
        if not os.path.abspath(f.filename).startswith(tuple(p + os.sep for p in _NOT_THEIRS))
    ]
    if not own:
        return None
    frame = own[-1]
    text = (frame.line or "").strip()
    if is_notebook_cell(frame.filename):
        # IPython compiles each cell on its own, so the line number counts from the cell's top.
        where = _("line {line} of your cell, in {function}").format(
            line=frame.lineno, function=frame.name
        )
    else:
        where = _("line {line} of {function}").format(line=frame.lineno, function=frame.name)
    return _("{where}: {code}").format(where=where, code=text) if text else where


def is_notebook_cell(filename: str) -> bool:
    """Whether ``filename`` is a notebook cell's: ipykernel's ``.../ipykernel_N/M.py``, or older
    IPython's ``<ipython-input-N-...>``."""
    if filename.startswith("<ipython-input-"):
        return True
    folder = os.path.basename(os.path.dirname(filename))
    return folder.startswith("ipykernel_") and filename.endswith(".py")


def describe_function(function: Any) -> str:
    """A short name for what the student passed in place of a function."""
    return getattr(function, "__name__", type(function).__name__)


def case_inputs(case: Mapping[str, Any], show: Callable[[Any], str]) -> str:
    """A case's inputs in one line, as the handout names them."""
    return ", ".join(f"{name}={show(value)}" for name, value in case.items())
