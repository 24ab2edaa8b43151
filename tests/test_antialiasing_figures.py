"""Lesson 05's figures in Chinese: Chinese words, every glyph found (tests/chinese.py)."""

import pytest
from chinese import check_chinese_figure
from drawn_figures import figures_drawn
from matplotlib.patches import Rectangle

from course.antialias import arc_length_step
from course.images import SEED_000_CUBIC
from course.lessons.l05_antialiasing import figures, measurements


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
