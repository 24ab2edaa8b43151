"""What a student's code does, read from its source: lesson 02's checkers ask it.

:func:`multiplies` finds a product in a ``comb`` (Pascal's rule only adds), and
:func:`names_comb` whether a ``naive_bezier`` weights its points with the student's own
``comb``. Each reads the function's code and the code of the student's own functions it
calls, never running them; code that cannot be read (the library's, code made by ``exec``,
a function run in the grader's child process) tells nothing.

The checkers call these with the function they are checking (``UNCHECKED = True``).
"""

from __future__ import annotations

import ast
import inspect
import textwrap
from collections.abc import Callable, Iterator
from typing import Any

__all__ = ["multiplies", "names_comb"]

UNCHECKED = True  # see the module docstring


def _student_code(function: Callable[..., Any]) -> Iterator[ast.AST]:
    """The parsed code of ``function`` and of the student's own functions it calls, in turn.

    The library's functions are skipped, and so is code whose source cannot be read.
    """
    seen: set[Any] = set()
    todo = [function]
    while todo:
        current = inspect.unwrap(todo.pop())
        code = getattr(current, "__code__", None)
        if code is None or code in seen or _is_library(current):
            continue
        seen.add(code)
        try:
            tree = ast.parse(textwrap.dedent(inspect.getsource(current)))
        except (OSError, TypeError, SyntaxError):
            continue
        names = {**getattr(current, "__globals__", {}), **_closed_over(current)}
        yield tree
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
                if callable(names.get(node.func.id)):
                    todo.append(names[node.func.id])


def _closed_over(function: Any) -> dict[str, Any]:
    """The names a nested function reads from the function around it, with their values."""
    cells = getattr(function, "__closure__", None) or ()
    found = {}
    for name, cell in zip(function.__code__.co_freevars, cells, strict=False):
        try:
            found[name] = cell.cell_contents
        except ValueError:  # a cell not filled yet
            continue
    return found


def multiplies(function: Callable[..., Any]) -> str | None:
    """The first multiplication or division in ``function``'s code, and the helpers it calls.

    Pascal's rule only adds; ``[0] * (m + 1)``, a list made longer, is not a product.

    Examples
    --------
    >>> def by_product(m, n):
    ...     return m * n
    >>> by_product.__module__ = "__main__"  # a notebook's, not the library's
    >>> multiplies(by_product), multiplies(len)
    ('m * n', None)
    """
    for tree in _student_code(function):
        for node in ast.walk(tree):
            if isinstance(node, (ast.BinOp, ast.AugAssign)) and isinstance(
                node.op, (ast.Mult, ast.Div, ast.FloorDiv)
            ):
                operands = (
                    [node.target, node.value]
                    if isinstance(node, ast.AugAssign)
                    else [
                        node.left,
                        node.right,
                    ]
                )
                if not any(isinstance(o, (ast.List, ast.ListComp, ast.Tuple)) for o in operands):
                    return ast.unparse(node).strip()
            if isinstance(node, ast.Call):
                called = node.func
                if isinstance(called, ast.Name) and called.id in {"prod", "factorial"}:
                    return ast.unparse(node)
                if isinstance(called, ast.Attribute) and called.attr in {"prod", "factorial"}:
                    return ast.unparse(node)
    return None


def names_comb(function: Callable[..., Any]) -> bool | None:
    """Whether ``function``'s code, or a helper of the student's it calls, names ``comb``:
    None when its code cannot be read (the library's, or code made by ``exec``).

    Examples
    --------
    >>> def comb(m, n):
    ...     return 1
    >>> def weight(n, i):
    ...     return comb(n, i)
    >>> def by_weights(points, t):
    ...     return weight(1, 0) * points[0]
    >>> def by_steps(points, t):
    ...     return (1 - t) * points[0] + t * points[1]
    >>> for function in (comb, weight, by_weights, by_steps):
    ...     function.__module__ = "__main__"  # a notebook's, not the library's
    >>> names_comb(by_weights), names_comb(by_steps), names_comb(len)
    (True, False, None)
    """
    readable = False
    for tree in _student_code(function):
        readable = True
        if any(isinstance(node, ast.Name) and node.id == "comb" for node in ast.walk(tree)):
            return True
    return False if readable else None


def _is_library(function: Any) -> bool:
    module = getattr(function, "__module__", "") or ""
    return module.split(".")[0] in {"course", "numpy", "math", "builtins", "scipy"}
