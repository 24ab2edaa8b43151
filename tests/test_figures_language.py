"""Lessons 03 and 05-08's figures, the apps' status lines and the course map in Chinese.

Each figure module draws a few of its cheapest figures under ``course.use_language("zh-CN")``:
every title, label, legend and caption that is words must be Chinese, and the picture
must render with no glyph missing (matplotlib's warning is an error here). English stays
the source's own strings, checked against the doctests' captions.
"""

from __future__ import annotations

import re
import warnings

import ipywidgets as widgets
import numpy as np
import pytest
from matplotlib.text import Text

import course
from course.classroom.course_map import HANDOUTS, course_map, handout_key
from course.classroom.notebooks import NOTEBOOKS
from course.classroom.registry import lessons
from course.i18n import language
from course.widgets import (
    antialiasing_figures,
    dithering_figures,
    filtering_figures,
    lines_and_triangles_figures,
    poisson_figures,
)
from course.widgets.base import SliderApp, pad, parse_points
from course.widgets.picture import Still

CHINESE = re.compile("[\u4e00-\u9fff]")
# A figure's own text that need not be words: numbers, formulas, names of code.
NOT_WORDS = re.compile(r"^[-+−\d.\s/x=()',:;dyfg+ -]*$|^'\w[\w-]*'$|^f \+ g$|^(dx|dy) = [\d.]+$")


@pytest.fixture
def chinese():
    course.use_language("zh-CN")
    yield
    course.use_language("en")


@pytest.fixture
def drawn(monkeypatch):
    """The texts of every figure a Still is made of, drawn with missing glyphs as errors."""
    texts: list[list[str]] = []
    of = Still.of.__func__

    def recording(cls, figure, caption):
        texts.append([t.get_text() for t in figure.findobj(Text) if t.get_text()])
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # "Glyph ... missing from font" fails the test
            return of(cls, figure, caption)

    monkeypatch.setattr(Still, "of", classmethod(recording))
    return texts


def words(texts: list[str]) -> list[str]:
    return [text for text in texts if not NOT_WORDS.match(text)]


FIGURES = [
    (antialiasing_figures.pixel_area_figure, ()),
    (antialiasing_figures.splat_figure, ()),
    (dithering_figures.diffusion_figure, ()),
    (dithering_figures.wavefront_figure, ()),
    (dithering_figures.by_hand_figure, (np.array([[0.2, 0.7], [0.4, 0.9]]), 20)),
    (dithering_figures.wraparound_figure, (np.full((12, 12), 0.3), (6, 6), 6, 2)),
    (filtering_figures.false_edges_figure, (4,)),
    (lines_and_triangles_figures.line_figure, ()),
    (lines_and_triangles_figures.edge_rules_figure, (3,)),
    (lines_and_triangles_figures.scanline_figure, ()),
    (lines_and_triangles_figures.mesh_figure, (8, 4)),
    (poisson_figures.tiny_clone_figure, (None, None, 10)),
]


@pytest.mark.parametrize(
    ("figure", "arguments"), FIGURES, ids=[f.__module__[15:] + "." + f.__name__ for f, _ in FIGURES]
)
def test_a_figure_in_chinese_has_chinese_words_and_every_glyph(
    figure, arguments, chinese, drawn, caplog
):
    still = figure(*arguments)
    assert CHINESE.search(still.caption), still.caption
    (texts,) = drawn
    shown = words(texts)
    assert shown, texts
    assert [text for text in shown if not CHINESE.search(text)] == []
    # Mathtext has no fallback font: it logs a missing glyph instead of warning; and a font
    # without a bold face is logged too ("findfont: Failed to find font weight bold").
    logged = [r.getMessage() for r in caplog.records]
    assert [m for m in logged if "does not have a glyph" in m or "findfont" in m] == []


def test_the_figures_show_english_until_the_language_is_set_and_after_it_is_reset(drawn):
    english = lines_and_triangles_figures.line_figure().caption
    assert english == (
        "(0, 0) to (7, 3): 8 pixels, one per column; the farthest centre is 0.429 px off in y"
    )
    with language("zh-CN"):
        chinese = lines_and_triangles_figures.line_figure().caption
    assert chinese == "(0, 0) 到 (7, 3)：8 个像素，每列一个；最远的像素中心在 y 方向偏离 0.429 像素"
    assert lines_and_triangles_figures.line_figure().caption == english
    assert not any(CHINESE.search(text) for texts in drawn[::2] for text in texts)


def test_printed_lines_follow_the_language(chinese):
    assert poisson_figures.strip_and_square() == (
        "3 x 3 正方形：0.7071；3 x 30 长条：0.8510；3 x 300 长条：0.8535；3 x 无穷：0.8536"
    )
    table = dithering_figures.clumps_and_holes({"blue noise": np.eye(4)}, 0.25).splitlines()
    assert table[0].startswith("灰度 0.250") and table[1].startswith("蓝噪声")


def test_a_table_pads_chinese_by_the_columns_it_takes():
    assert pad("lit", 6, ">") == f"{'lit':>6s}" and pad("lit", 6) == f"{'lit':6s}"
    assert pad("点亮", 6, ">") == "  点亮" and pad("过长的名字", 4) == "过长的名字"
    dots = np.zeros((4, 4))
    dots[0, 0] = 1
    with language("zh-CN"):
        header, row = dithering_figures.clumps_and_holes({"阈值": dots}, 0.1).splitlines()
    with language("en"):
        english_header, _row = dithering_figures.clumps_and_holes({"x": dots}, 0.1).splitlines()

    def columns(text: str) -> int:  # a Chinese character or full-width sign takes two
        return len(text) + len(re.findall("[\u3000-\u303f\u4e00-\u9fff\uff01-\uff60]", text))

    assert columns(row) == 15 + 6 + 22 + 20
    # Each header ends where it ends in English, one column before its numbers.
    assert columns(header) == len(english_header) == columns(row) - 1


class _Slider(SliderApp):
    def __init__(self):
        super().__init__({"t": widgets.FloatSlider(value=0.5)}, shape=(40, 40), dpi=40)
        self.points = np.zeros((2, 2))

    def update(self):
        pass


def test_the_status_line_speaks_the_language_and_clears_after_a_refused_value(chinese):
    app = _Slider()
    app.controls["t"].value = float("nan")
    assert app.status.value == "拒绝了 t = nan：应为有限的数；保留 0.5"
    app.controls["t"].value = 0.25
    assert app.status.value == ""
    app._on_message(None, {"kind": "down"}, [])
    assert app.status.value == "忽略了一条指针消息：缺少 x, y"


def test_a_point_typed_wrong_is_explained_in_the_language(chinese):
    with pytest.raises(ValueError, match="不读取小数逗号") as error:
        parse_points("90,5 610,5")
    assert "第 1 个点" in str(error.value)


def test_the_course_map_in_chinese_shows_chinese_lessons_handouts_and_guide(chinese):
    shown = course_map(NOTEBOOKS / "zh-CN")
    assert shown.startswith("### 练习怎么做")
    assert "| 课 | 学完你能够 | 它解答的讲义任务 | 时长 |" in shown
    assert "[第 01 课 · " in shown and "60 分钟" in shown
    assert "用反复的线性插值，手算贝塞尔曲线上的一个点" in shown
    # Each lesson's row: its title, what it teaches and its handout task, in Chinese.
    rows = [line for line in shown.splitlines() if line.startswith("| [")]
    assert len(rows) == len(lessons())
    assert all(len(CHINESE.findall(row)) > 20 for row in rows)
    assert lessons()["08"].outcomes[0] == "通过求解泊松方程，把一幅图像无缝地贴进另一幅"
    key = handout_key()
    assert key.startswith("| 课程里的称呼 |") and "| GAMES101 作业报告 |" in key
    # The handouts' own titles stay as the student holds them, in both languages.
    assert "| HW4:绘制贝塞尔曲线 + 线性插值反走样 |" in key and "| Lab01 Report |" in key
    assert HANDOUTS[0].title.startswith("作业 4 的题目：GAMES101 作业报告在“题目”下引用")


def test_the_course_map_in_english_is_the_registry_as_written():
    assert HANDOUTS[0].title == (
        "作业 4 的题目: quoted under 题目 in the GAMES101 report, and as 作业要求 in the VS2022 "
        "report"
    )
    assert "anti-aliasing as the 提高部分" in HANDOUTS[0].holds
    assert lessons()["08"].outcomes[0] == (
        "paste one image into another with no seam, by solving a Poisson equation"
    )
    assert not CHINESE.search(course_map(guide=True).split("| [")[0])
