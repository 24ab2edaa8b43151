"""The library's source as "Going further" lists it: outside English, without its English prose.

The docstrings and comments of the library are English: a Chinese listing leaves them out
(``course.classroom.source.without_comments``) and keeps the code itself, token for token.
"""

from __future__ import annotations

import ast
import io
import tokenize

import pytest

from course.classroom.source import source_of, without_comments
from course.curves.bezier import bezier_bernstein, de_casteljau, de_casteljau_recursive
from course.i18n import language


def _code(source: str) -> str:
    """The source's syntax tree without docstrings: what the code does."""
    tree = ast.parse(source)
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if (
            isinstance(body, list)
            and body
            and isinstance(body[0], ast.Expr)
            and isinstance(body[0].value, ast.Constant)
            and isinstance(body[0].value.value, str)
        ):
            node.body = body[1:] or [ast.Expr(ast.Constant(...))]
    return ast.dump(tree)


def _comments(source: str) -> list[str]:
    tokens = tokenize.generate_tokens(io.StringIO(source).readline)
    return [token.string for token in tokens if token.type == tokenize.COMMENT]


LISTINGS = [
    (de_casteljau, None),
    (de_casteljau_recursive, None),
    (bezier_bernstein, "horner"),
    (bezier_bernstein, "loop"),
]


@pytest.mark.parametrize(("function", "method"), LISTINGS)
def test_a_chinese_listing_is_the_code_without_docstrings_or_comments(function, method):
    english = source_of(function, method)
    with language("zh-CN"):
        chinese = source_of(function, method)
    assert '"""' in english  # the English listing keeps its prose
    assert '"""' not in chinese and _comments(chinese) == []
    assert _code(chinese) == _code(english)
    lines = english.splitlines()  # each line as it was, or cut before its comment
    assert all(any(other.startswith(line) for other in lines) for line in chinese.splitlines())


def test_without_comments_keeps_strings_that_look_like_comments():
    source = 'def f():\n    """Doc."""\n    return "# kept"  # dropped\n'
    assert without_comments(source) == 'def f():\n    return "# kept"\n'
    assert without_comments("class A:\n    # only a comment\n    'Doc.'\n") == "class A:\n    ...\n"
