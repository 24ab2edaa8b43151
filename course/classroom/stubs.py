"""A solution cell's answers, and the stub that replaces them in the student edition.

Standard library only, as the editions that use it: the student edition
(:mod:`course.classroom.edition`), the nbgrader edition
(:mod:`course.classroom.nbgrader`) and the course's website (``site/stage.py``).

An exercise cell defines the student's function and ends with the checker
call, for example::

    def recursive_bezier(control_points, t):
        ...the working solution...


    check.recursive_bezier(recursive_bezier)

Its answers are the bodies of its top-level functions (:func:`solution_bodies`):
each ``def`` line (with its decorators) and docstring stay, and the body
becomes ``raise NotImplementedError("your code here")`` (:data:`STUB_LINE`), its
message in the lesson's language (:func:`stub_line`: the Chinese edition's stubs say
``"在这里写你的代码"``, from the library's catalog).
A partial scaffold marks what to remove instead, with the lines ``### BEGIN
SOLUTION`` and ``### END SOLUTION`` (nbgrader's markers): only the lines
between them go, replaced by the stub at the marker's indentation, and the
rest of the cell stays for the student to build on (:func:`exercise_stub`).
"""

from __future__ import annotations

import ast

from course.i18n import LANGUAGES, N_, _, gettext_catalog

__all__ = [
    "BEGIN_SOLUTION",
    "END_SOLUTION",
    "STUB_LINE",
    "STUB_MESSAGE",
    "exercise_stub",
    "parse_solution",
    "solution_bodies",
    "stub_line",
]

#: What a stub says, in English; the lesson's language's in :func:`stub_line`.
STUB_MESSAGE = N_("your code here")
#: The English edition's stub.
STUB_LINE = 'raise NotImplementedError("your code here")'
BEGIN_SOLUTION = "### BEGIN SOLUTION"
END_SOLUTION = "### END SOLUTION"


def stub_line(language: str = "en") -> str:
    """The stub of a lesson in ``language`` (``"en"`` or ``"zh-CN"``): its message translated.

    Examples
    --------
    >>> stub_line() == STUB_LINE
    True
    >>> stub_line("zh-CN")
    'raise NotImplementedError("在这里写你的代码")'
    """
    if not isinstance(language, str) or language not in LANGUAGES:
        raise ValueError(
            _("language: expected one of {choices}; got {language:.60}").format(
                choices=", ".join(LANGUAGES), language=repr(language)
            )
        )
    locale = LANGUAGES[language]
    message = STUB_MESSAGE if locale is None else gettext_catalog(locale).gettext(STUB_MESSAGE)
    # The message goes between double quotes: a translation holds neither one nor a backslash.
    return f'raise NotImplementedError("{message}")'


def exercise_stub(source: str, language: str = "en") -> str:
    """The cell ``source`` with its solution replaced by a stub in ``language``
    (:func:`stub_line`).

    With ``### BEGIN SOLUTION`` / ``### END SOLUTION`` markers, the lines
    between each pair (and the markers) become one stub line at the begin
    marker's indentation; otherwise each top-level function's body does.

    Examples
    --------
    >>> print(exercise_stub('''def area(w, h):
    ...     \"\"\"Width times height.\"\"\"
    ...     return w * h
    ...
    ...
    ... check.area(area)'''))
    def area(w, h):
        \"\"\"Width times height.\"\"\"
        raise NotImplementedError("your code here")
    <BLANKLINE>
    <BLANKLINE>
    check.area(area)
    """
    if not isinstance(source, str):
        raise TypeError(
            _("source: expected a cell's source text; got {source_type}").format(
                source_type=type(source).__name__
            )
        )
    stub = stub_line(language)
    if BEGIN_SOLUTION in source or END_SOLUTION in source:
        return _scaffold_stub(source, stub)
    lines = source.splitlines()
    # Replace from the bottom up, so earlier line numbers stay valid.
    for start, end, indent in reversed(solution_bodies(source)):
        lines[start:end] = [indent + stub]
    return "\n".join(lines)


def parse_solution(source: str, where: str) -> ast.Module:
    """The syntax tree of a solution cell's ``source``; a ValueError, beginning ``where``, if none.

    Examples
    --------
    >>> parse_solution("def f(:", "cell 3").body
    Traceback (most recent call last):
    ...
    ValueError: cell 3: a solution cell must be valid Python; line 1: invalid syntax
    """
    if not isinstance(source, str):
        raise TypeError(
            _("source: expected a cell's source text; got {source_type}").format(
                source_type=type(source).__name__
            )
        )
    try:
        return ast.parse(source)
    except (SyntaxError, ValueError) as error:  # ValueError: a NUL byte
        raise ValueError(
            _("{where}: a solution cell must be valid Python; line {line}: {problem}").format(
                where=where,
                line=getattr(error, "lineno", "?"),
                problem=getattr(error, "msg", error),
            )
        ) from None


def solution_bodies(source: str) -> list[tuple[int, int, str]]:
    """Where a solution cell's answers are: ``(start, end, indent)`` for each top-level function.

    ``lines[start:end]`` (0-based, of ``source.splitlines()``) is the body
    after the ``def`` line and docstring; ``indent`` is its indentation. The
    student edition replaces it by a stub, the nbgrader edition puts it
    between nbgrader's markers.

    Examples
    --------
    >>> solution_bodies("def f(x):\\n    return 2 * x\\n\\nf(1)")
    [(1, 2, '    ')]
    """
    tree = parse_solution(source, "source")
    functions = [
        node for node in tree.body if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
    ]
    if not functions:
        raise ValueError(
            _(
                "source: a solution cell must define the exercise's function at top level (def "
                "name(...): ...); got no def in:\n{source}"
            ).format(source=source)
        )
    lines = source.splitlines()
    bodies = []
    for function in functions:
        body = function.body
        first = body[0]
        has_docstring = (
            isinstance(first, ast.Expr)
            and isinstance(first.value, ast.Constant)
            and isinstance(first.value.value, str)
        )
        if first.lineno == function.lineno:
            raise ValueError(
                _(
                    "source: put the body of {name} on its own lines, not after 'def ...:' (line "
                    "{lineno})"
                ).format(name=function.name, lineno=function.lineno)
            )
        indent = " " * first.col_offset
        if has_docstring:
            keep = first.end_lineno
        else:
            # Comments above the first statement belong to the body (they may give
            # the answer away); the header ends at the last code line before them.
            keep = first.lineno - 1
            while keep > function.lineno and lines[keep - 1].strip()[:1] in ("", "#"):
                keep -= 1
        bodies.append((keep, function.end_lineno, indent))
    return bodies


def _scaffold_stub(source: str, stub: str = STUB_LINE) -> str:
    """Replace each marked region, markers included, by the stub at the marker's indentation.

    Examples
    --------
    >>> print(_scaffold_stub('''def f(x):
    ...     y = 2 * x
    ...     ### BEGIN SOLUTION
    ...     y += 1
    ...     ### END SOLUTION
    ...     return y'''))
    def f(x):
        y = 2 * x
        raise NotImplementedError("your code here")
        return y
    """
    lines, kept, inside = source.splitlines(), [], False
    for number, line in enumerate(lines, start=1):
        marker = line.strip()
        if marker == BEGIN_SOLUTION:
            if inside:
                raise ValueError(
                    _("source: line {number} opens a solution inside another").format(number=number)
                )
            inside = True
            kept.append(line[: len(line) - len(line.lstrip())] + stub)
        elif marker == END_SOLUTION:
            if not inside:
                raise ValueError(
                    _("source: line {number} closes a solution never opened").format(number=number)
                )
            inside = False
        elif not inside:
            kept.append(line)
    if inside:
        raise ValueError(
            _("source: {begin} without {end}").format(
                begin=repr(BEGIN_SOLUTION), end=repr(END_SOLUTION)
            )
        )
    return "\n".join(kept)
