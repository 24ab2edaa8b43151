"""The library's source, as "Going further" shows it: a function, or one form of it.

A function with choices (``method="loop"`` and a fast default, listed in its
``<FUNCTION>_METHODS`` tuple) keeps each form in a private function of its
module named ``_<function>_<method>``: ``course.raster.line(method="loop")``
runs ``course.raster.lines._line_loop``. :func:`source_of` finds that form by the
convention, so a notebook reads the library without importing a private
name, and adds the private helpers it calls, so the reader sees all of it.
Standard library only.

Classroom tooling for the course's authors and its browser tests: its
inputs come from the lesson registry, never from a student, so this module
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import inspect
import sys
import types
from collections.abc import Callable, Iterator
from typing import Any

from course.i18n import _

__all__ = ["form_of", "source_of"]

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
    the order first met. Input checks are left out.

    Examples
    --------
    >>> from course import raster
    >>> print(source_of(raster.line, "loop").splitlines()[0])
    def _line_loop(
    """
    start = function if method is None else form_of(function, method)
    return "\n\n\n".join(inspect.getsource(part).rstrip() for part in _parts(start))


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
