"""Lesson 07's figures in Chinese: Chinese words, every glyph found (tests/chinese.py)."""

from chinese import check_chinese_figure

from course.lessons.l07_filtering import figures


def test_a_figure_in_chinese_has_chinese_words_and_every_glyph(monkeypatch, caplog):
    check_chinese_figure(figures.false_edges_figure, (4,), monkeypatch, caplog)
