"""Lesson 03's figures in Chinese: Chinese words, every glyph found, English unchanged."""

import pytest
from chinese import CHINESE, check_chinese_figure, drawn
from drawn_figures import figures_drawn

from course.lessons.l03_lines_and_triangles import figures

FIGURES = [
    (figures.line_figure, ()),
    (figures.edge_rules_figure, (3,)),
    (figures.scanline_figure, ()),
    (figures.mesh_figure, (8, 4)),
]


@pytest.mark.parametrize(("figure", "arguments"), FIGURES, ids=[f.__name__ for f, _ in FIGURES])
def test_a_figure_in_chinese_has_chinese_words_and_every_glyph(
    figure, arguments, monkeypatch, caplog
):
    check_chinese_figure(figure, arguments, monkeypatch, caplog)


def test_the_figures_show_english_until_the_language_is_set_and_after_it_is_reset(monkeypatch):
    with drawn(monkeypatch, "en") as english_texts:
        english = figures.line_figure().caption
    with drawn(monkeypatch) as chinese_texts:
        chinese = figures.line_figure().caption
    assert english == (
        "(0, 0) to (7, 3): 8 pixels, one per column; the farthest centre is 0.429 px off in y"
    )
    assert (
        chinese == "从 (0, 0) 到 (7, 3)：8 个像素，每列一个；最远的像素中心在 y 方向偏离 0.429 像素"
    )
    assert figures.line_figure().caption == english
    assert not any(CHINESE.search(text) for text in english_texts[0])
    assert any(CHINESE.search(text) for text in chinese_texts[0])


def test_the_colour_figure_marks_the_centre_its_caption_gives_the_weights_of(monkeypatch):
    # A reader could not find "the centre (14.5, 7.5)" of the caption on the picture.
    with figures_drawn(monkeypatch) as drawn_figures:
        still = figures.colour_figure()
    assert "at the centre (14.5, 7.5)" in still.caption
    (axes,) = drawn_figures[0].axes
    assert "(14.5, 7.5)" in [text.get_text() for text in axes.texts]
    marks = [
        tuple(artist.get_xydata()[0]) for artist in axes.lines if len(artist.get_xydata()) == 1
    ]
    assert (14.5, 7.5) in marks
