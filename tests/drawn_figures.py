"""The matplotlib figures a lesson's Still is made of, kept for a test to inspect.

A figure function returns PNG bytes and a caption; a test of what the picture shows (a
colour range, a legend's entries, which artist is on top) needs the Figure itself.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import pytest
from matplotlib.figure import Figure

from course.widgets.picture import Still


@contextmanager
def figures_drawn(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[Figure]]:
    """Every Figure turned into a Still inside the block, in order."""
    figures: list[Figure] = []
    of = Still.of.__func__

    def keeping(cls, figure, caption):
        figures.append(figure)
        return of(cls, figure, caption)

    with monkeypatch.context() as patch:
        patch.setattr(Still, "of", classmethod(keeping))
        yield figures
