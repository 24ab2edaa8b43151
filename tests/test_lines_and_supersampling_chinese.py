"""Lessons 03 and 04 in Chinese: the rules, Wu's line and the sampling figures say Chinese.

A Chinese student read «规则 'top-left'» on the rule toggle and the titles of lesson 03, «Wu»
in its line app, and English legends and captions in lesson 04's folding and photograph
figures (issue 36). The values the code takes stay the English ones.
"""

import re

import pytest
from chinese import drawn

from course.i18n import language
from course.lessons.l03_lines_and_triangles import figures as line_figures
from course.lessons.l03_lines_and_triangles.apps import LineApp, TriangleApp
from course.lessons.l04_supersampling import figures as sampling_figures
from course.raster.triangles import EDGE_RULES

# Latin words a figure of these lessons may show: a person's name, the triangles' vertices,
# functions of math and the differences of the line's ends.
ALLOWED = {"Bresenham", "ABC", "ACD", "AC", "cos", "sinc", "max", "dx", "dy", "px"}


def latin_words(texts):
    return sorted({word for text in texts for word in re.findall(r"[A-Za-z]{2,}", text)} - ALLOWED)


def test_the_rule_toggle_names_the_rules_in_the_students_language_and_keeps_the_values():
    with language("zh-CN"):
        app = TriangleApp(rule="closed")
        app.refresh()
        toggle = app.controls["rule"]
        assert toggle.options == (
            ("左上规则", "top-left"),
            ("闭合规则", "closed"),
            ("开放规则", "open"),
        )
        assert app.value("rule") == "closed"
        assert app.left.get_title().startswith("闭合规则：")
    english = TriangleApp()
    english.refresh()
    assert english.controls["rule"].options == tuple((rule, rule) for rule in EDGE_RULES)
    assert english.left.get_title().startswith("rule top-left: ")


def test_wus_line_is_named_in_chinese_in_the_line_app():
    with language("zh-CN"):
        app = LineApp()
        app.refresh()
        assert app.panels["wu"].axes.get_title().startswith("吴小林直线：")
    assert line_figures.rule_name("open") == "open"


@pytest.mark.parametrize(
    ("figure", "arguments"),
    [
        (line_figures.edge_rules_figure, (3,)),
        (line_figures.mesh_figure, (8, 4)),
        (sampling_figures.folding_figure, ()),
        (sampling_figures.photograph_figure, ((1, 2), 2)),
    ],
    ids=["edge_rules", "mesh", "folding", "photograph"],
)
def test_a_figure_shows_no_english_word_in_chinese(figure, arguments, monkeypatch):
    with drawn(monkeypatch) as texts:
        still = figure(*arguments)
    assert latin_words([still.caption, *texts[0]]) == []
    assert ", " not in still.caption


def test_the_photograph_figure_keeps_its_english():
    still = sampling_figures.photograph_figure((1, 2), 2)
    assert re.fullmatch(r"RMS against rate 2: rate 1 [\d.]+, rate 2 0\.0000", still.caption)
