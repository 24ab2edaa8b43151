"""Lesson 06's figures and table in Chinese: Chinese words, every glyph found, columns kept."""

import re

import numpy as np
import pytest
from chinese import check_chinese_figure
from drawn_figures import figures_drawn

from course.halftone import dither
from course.i18n import language
from course.lessons.l06_dithering import figures, floyd_steinberg

FIGURES = [
    (floyd_steinberg.diffusion_figure, ()),
    (figures.wavefront_figure, ()),
    (floyd_steinberg.by_hand_figure, (np.array([[0.2, 0.7], [0.4, 0.9]]), 20)),
    (figures.wraparound_figure, (np.full((12, 12), 0.3), (6, 6), 6, 2)),
]


@pytest.mark.parametrize(("figure", "arguments"), FIGURES, ids=[f.__name__ for f, _ in FIGURES])
def test_a_figure_in_chinese_has_chinese_words_and_every_glyph(
    figure, arguments, monkeypatch, caplog
):
    check_chinese_figure(figure, arguments, monkeypatch, caplog)


def test_the_table_names_the_lab_methods_in_chinese_and_keeps_its_columns():
    dots = np.zeros((4, 4))
    dots[0, 0] = 1
    with language("zh-CN"):
        header, row = figures.clumps_and_holes({"blue noise": dots}, 0.1).splitlines()
    with language("en"):
        english_header, _row = figures.clumps_and_holes({"x": dots}, 0.1).splitlines()
    assert header.startswith("灰度 0.100") and row.startswith("蓝噪声")

    def columns(text: str) -> int:  # a Chinese character or full-width sign takes two
        return len(text) + len(re.findall("[\u3000-\u303f\u4e00-\u9fff\uff01-\uff60]", text))

    assert columns(row) == 15 + 6 + 22 + 20
    # Each header ends where it ends in English, one column before its numbers.
    assert columns(header) == len(english_header) == columns(row) - 1


def test_a_patch_without_dots_has_an_endless_hole_said_in_the_tables_language():
    empty = np.zeros((4, 4))
    (english,) = figures.clumps_and_holes({"threshold": empty}, 0.1).splitlines()[1:]
    with language("zh-CN"):
        (chinese,) = figures.clumps_and_holes({"threshold": empty}, 0.1).splitlines()[1:]
    assert english.endswith(" inf") and len(english) == 15 + 6 + 22 + 20
    assert chinese.endswith(" 无穷大") and not re.search("[A-Za-z]", chinese)


def test_the_slip_s_difference_title_counts_the_whole_image_not_the_window(monkeypatch):
    flat = np.full((40, 40), 0.3)
    changed = dither.error_diffusion(flat) != dither.error_diffusion_wraparound(flat)
    in_window = changed[12:28, 22:38].sum()  # crop of centre (30, 20), size 16
    assert changed.sum() != in_window  # so the title's number tells which it counts
    with figures_drawn(monkeypatch) as drawn:
        figures.wraparound_figure(flat, (30, 20), 16)
    titles = [axes.get_title() for axes in drawn[0].axes]
    assert f"difference in the window\n({changed.sum()} pixels in the whole image)" in titles
