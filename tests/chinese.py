"""What the tests of the Chinese figures share: every figure a ``Still`` is made of,
recorded and drawn in Chinese with a missing glyph as an error; and the scans' report of the
Latin words they find (:func:`latin_report`, :func:`listed`).

A figure module's test draws a few of its cheapest figures under
``course.use_language("zh-CN")`` (and English again after, whatever happens): every
title, label, legend and caption that is words must be Chinese, and the picture must
render with no glyph missing (matplotlib's warning is an error here, and its logged
complaints fail the test).
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import pytest
from matplotlib.text import Text

from course.classroom.chinese_text import Shown
from course.i18n import language
from course.widgets.picture import Still

CHINESE = re.compile("[\u4e00-\u9fff]")
# A figure's own text that need not be words: numbers, formulas, names of code.
NOT_WORDS = re.compile(r"^[-+−\d.\s/x=()',:;dyfg+ -]*$|^'\w[\w-]*'$|^f \+ g$|^(dx|dy) = [\d.]+$")


@contextmanager
def drawn(monkeypatch: pytest.MonkeyPatch, code: str = "zh-CN") -> Iterator[list[list[str]]]:
    """In language ``code``: the texts of every figure a Still is made of, glyphs checked."""
    texts: list[list[str]] = []
    of = Still.of.__func__

    def recording(cls, figure, caption):
        texts.append([t.get_text() for t in figure.findobj(Text) if t.get_text()])
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # "Glyph ... missing from font" fails the test
            return of(cls, figure, caption)

    with monkeypatch.context() as patch, language(code):
        patch.setattr(Still, "of", classmethod(recording))
        yield texts


def check_chinese_figure(
    figure: Callable, arguments: tuple, monkeypatch: pytest.MonkeyPatch, caplog
) -> None:
    """``figure(*arguments)``, drawn in Chinese: Chinese words only, and every glyph found."""
    with drawn(monkeypatch) as texts:
        still = figure(*arguments)
    assert CHINESE.search(still.caption), still.caption
    (shown,) = texts
    words = [text for text in shown if not NOT_WORDS.match(text)]
    assert words, shown
    assert [text for text in words if not CHINESE.search(text)] == []
    # Mathtext has no fallback font: it logs a missing glyph instead of warning; and a font
    # without a bold face is logged too ("findfont: Failed to find font weight bold").
    logged = [r.getMessage() for r in caplog.records]
    assert [m for m in logged if "does not have a glyph" in m or "findfont" in m] == []


def listed(found: list[str]) -> str:
    return f"{len(found)} found:\n" + "\n".join(found)


def latin_report(texts: list[Shown], names: frozenset[str] = frozenset()) -> list[str]:
    found = []
    for shown in texts:
        words = shown.latin(names)
        if words:
            excerpt = shown.text.strip().replace("\n", " ")[:90]
            found.append(f"{shown.lesson} {shown.where}: {sorted(set(words))} in «{excerpt}»")
    return sorted(set(found))
