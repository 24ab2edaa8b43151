"""The library's source, as "Going further" shows it: a function, or one form of it.

A function with choices (``method="loop"`` and a fast default, listed in its
``<FUNCTION>_METHODS`` tuple) keeps each form in a private function of its
module named ``_<function>_<method>``: ``course.raster.line(method="loop")``
runs ``course.raster.lines._line_loop``. :func:`source_of` finds that form by the
convention, so a notebook reads the library without importing a private
name, and adds the private helpers it calls, so the reader sees all of it.
In a language other than English (:func:`course.i18n.current_language`) the
listing leaves out the docstrings and the comments, which are English: the
code itself is shown unchanged (:func:`without_comments`, by ``ast`` and
``tokenize``). Standard library only.

Classroom tooling for the course's authors and its browser tests: its
inputs come from the lesson registry, never from a student, so this module
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import ast
import inspect
import io
import sys
import textwrap
import tokenize
import types
from collections.abc import Callable, Iterator
from typing import Any

from course.i18n import _, current_language

__all__ = ["form_of", "source_of", "without_comments"]

UNCHECKED = True  # see the module docstring

# Input checks are not the algorithm: their source is never followed.
_NOT_FOLLOWED = ("course._validate",)


def form_of(function: Callable[..., Any], method: str) -> Callable[..., Any]:
    """The private function that runs ``function(..., method=method)``.

    Examples
    --------
    >>> from course import raster
    >>> form_of(raster.line, "loop").__name__
    '_line_loop'
    """
    module = sys.modules[function.__module__]
    choices = getattr(module, f"{function.__name__.upper()}_METHODS", None)
    if choices is None:
        raise ValueError(
            _("function: {module}.{function} has no method choices ({upper}_METHODS)").format(
                module=function.__module__,
                function=function.__name__,
                upper=function.__name__.upper(),
            )
        )
    if method not in choices:
        raise ValueError(
            _("method must be one of {choices}; got {method}").format(
                choices=", ".join(map(repr, choices)), method=repr(method)
            )
        )
    return getattr(module, f"_{function.__name__}_{method}")


def source_of(function: Callable[..., Any], method: str | None = None) -> str:
    """The source of ``function`` (or of its form ``method``) and the private helpers it calls.

    Helpers are the functions and classes of the ``course`` package that the
    code names and that are private (an underscore in their name or their
    module's), followed through every helper in turn, each shown once, in
    the order first met. Input checks are left out. In a language other than
    English, the docstrings and comments are left out too (:func:`without_comments`).

    Examples
    --------
    >>> from course import raster
    >>> print(source_of(raster.line, "loop").splitlines()[0])
    def _line_loop(
    """
    start = function if method is None else form_of(function, method)
    english = current_language() == "en"
    return "\n\n\n".join(
        (source if english else without_comments(source)).rstrip()
        for source in (inspect.getsource(part) for part in _parts(start))
    )


def without_comments(source: str) -> str:
    r"""``source`` without its docstrings and comments, its code unchanged.

    The docstrings are found by ``ast`` (a module's, a class's or a function's first
    statement, a string), the comments by ``tokenize``: a line holding only a docstring
    or a comment goes, with the blank lines right after a docstring; a comment after code
    is cut off with the spaces before it. A body that held only a docstring keeps ``...``.

    Examples
    --------
    >>> code = "def f(x):\n    '''Twice x.\n\n    More.\n    '''\n\n    # double\n"
    >>> print(without_comments(code + "    return 2 * x  # '#' in a comment\n"))
    def f(x):
        return 2 * x
    <BLANKLINE>
    >>> print(without_comments("class A:\n    'Only a docstring.'\n"))
    class A:
        ...
    <BLANKLINE>
    >>> without_comments("s = '# not a comment'  # a comment\n")
    "s = '# not a comment'\n"
    """
    text = textwrap.dedent(source)
    lines = text.splitlines(keepends=True)
    dropped: set[int] = set()  # 0-based line numbers
    cut: dict[int, int] = {}  # line -> column where a comment after code starts
    emptied: dict[int, str] = {}  # a docstring's first line -> "..." at its indent
    for node in ast.walk(ast.parse(text)):
        if not isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        first = node.body[0] if node.body else None
        if not (
            isinstance(first, ast.Expr)
            and isinstance(first.value, ast.Constant)
            and isinstance(first.value.value, str)
        ):
            continue
        start, end = first.lineno - 1, first.end_lineno - 1
        if lines[start][: first.col_offset].strip() or lines[end][first.end_col_offset :].strip():
            continue  # shares its line with code: `def f(): "doc"`
        span = set(range(start, end + 1))
        after = end + 1
        while after < len(lines) and not lines[after].strip():
            span.add(after)
            after += 1
        dropped |= span
        if len(node.body) == 1:
            emptied[start] = " " * first.col_offset + "...\n"
    for token in tokenize.generate_tokens(io.StringIO(text).readline):
        if token.type != tokenize.COMMENT:
            continue
        row, column = token.start[0] - 1, token.start[1]
        if lines[row][:column].strip():
            cut[row] = column
        else:
            dropped.add(row)
    kept = []
    for number, line in enumerate(lines):
        if number in emptied:
            kept.append(emptied[number])
        elif number in cut:
            kept.append(line[: cut[number]].rstrip() + "\n")
        elif number not in dropped:
            kept.append(line)
    return "".join(kept)


def _parts(function: Any) -> list[Any]:
    seen: list[Any] = []

    def visit(part: Any) -> None:
        if part in seen:
            return
        seen.append(part)
        for helper in _helpers(part):
            visit(helper)

    visit(function)
    return seen


def _helpers(part: Any) -> Iterator[Any]:
    code = getattr(part, "__code__", None)
    if code is None:
        return
    namespace = vars(sys.modules[part.__module__])
    for name in _names(code):
        value = namespace.get(name)
        if isinstance(value, (types.FunctionType, type)) and _is_private_helper(value):
            yield value


def _names(code: types.CodeType) -> Iterator[str]:
    yield from code.co_names
    for constant in code.co_consts:
        if isinstance(constant, types.CodeType):  # nested functions and lambdas
            yield from _names(constant)


def _is_private_helper(value: Any) -> bool:
    module = getattr(value, "__module__", "") or ""
    if not module.startswith("course.") or module in _NOT_FOLLOWED:
        return False
    return value.__name__.startswith("_") or module.rsplit(".", 1)[-1].startswith("_")
