"""Lesson 05's figures in Chinese: Chinese words, every glyph found (tests/chinese.py)."""

import pytest
from chinese import check_chinese_figure

from course.widgets import antialiasing_figures as figures


@pytest.mark.parametrize("figure", [figures.pixel_area_figure, figures.splat_figure])
def test_a_figure_in_chinese_has_chinese_words_and_every_glyph(figure, monkeypatch, caplog):
    check_chinese_figure(figure, (), monkeypatch, caplog)
