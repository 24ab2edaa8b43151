"""Lesson 05's figures in Chinese: Chinese words, every glyph found (tests/chinese.py)."""

import pytest
from chinese import check_chinese_figure
from drawn_figures import figures_drawn
from matplotlib.patches import Rectangle

from course.antialias import arc_length_step
from course.i18n import language
from course.images import SEED_000_CUBIC
from course.lessons.l05_antialiasing import figures, measurements
from course.lessons.printed import display_width


@pytest.mark.parametrize("figure", [figures.pixel_area_figure, figures.splat_figure])
def test_a_figure_in_chinese_has_chinese_words_and_every_glyph(figure, monkeypatch, caplog):
    check_chinese_figure(figure, (), monkeypatch, caplog)


def test_the_variants_table_keeps_the_strokes_out_of_the_counted_columns():
    lines = measurements.variants_table().splitlines()
    step = arc_length_step(SEED_000_CUBIC)
    assert lines[0].endswith(f"step {step:.3g}") and "step 0.001" in lines[0]
    assert lines[1].split()[-2:] == ["area,", "once"]
    rows = {line[:34].strip(): line[75:].split() for line in lines[3:]}
    assert len(rows) == 9
    for name, cells in rows.items():
        if name in ("the stroke's area (library)", "Agg (matplotlib)"):
            assert cells[:4] == ["—"] * 4 and "—" not in cells[4:], (name, cells)
        else:
            assert cells[4:] == ["—"] * 2 and "—" not in cells[:4], (name, cells)


def test_the_rmse_on_its_log_axis_is_dots_not_bars(monkeypatch):
    with figures_drawn(monkeypatch) as drawn:
        measurements.variants_figure()
    (error_axes,) = [axes for axes in drawn[0].axes if axes.get_xscale() == "log"]
    assert [patch for patch in error_axes.patches if isinstance(patch, Rectangle)] == []
    dots = [line for line in error_axes.lines if line.get_marker() not in (None, "None", "")]
    assert sorted(len(line.get_xdata()) for line in dots) == [2, 7, 7]


def test_the_tables_say_their_columns_in_chinese_and_keep_them_lined_up():
    with language("zh-CN"):
        table = measurements.variants_table().splitlines()
        study = measurements.step_study(steps=(0.001,)).splitlines()
    assert "RMSE" not in "\n".join(table) and "CV" not in "\n".join(table + study)
    assert "均方根误差" in table[2] and "变异系数" in study[0]
    # Every row of numbers ends where the headings above it end.
    ends = {display_width(line) for line in table[1:]}
    assert len(ends) == 1, table
    assert display_width(study[0]) == display_width(study[1]), study
    # The rows name the plain loops and the weightings by the lesson's terms.
    assert table[3].startswith("朴素循环") and "所在的像素" in table[3]
    assert "按计数" in study[1] and "按弧长" in study[1]
