"""The rules of a Chinese text (course.classroom.chinese_text), on examples and on the catalogs.

Each scanner passes a small good example and fails a small bad one; then the library's
catalog ``course.po`` must hold no Latin word outside the allow-list, and every Chinese
message (the library's and the lessons') Chinese punctuation between Chinese words.

The checkers' and lessons 07-08's own wording follows (issue 36): one test for each thing a
Chinese reader found (a Python boolean, an ASCII joiner, Markdown backticks in plain text, a
range "from 0 to 0", a bare «你的» title, a label drawn over a curve).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from babel.messages.pofile import read_po
from chinese import latin_report, listed
from matplotlib.text import Annotation

from course.check.shown import show_value
from course.classroom import chinese_review as review
from course.classroom import chinese_text as text
from course.i18n import language
from course.lessons.l05_antialiasing.check import _show_splat
from course.lessons.l07_filtering import lesson as l07
from course.lessons.l08_poisson import convergence
from course.lessons.l08_poisson import lesson as l08
from course.lessons.l08_poisson.apps import PoissonIterationApp
from course.lessons.l08_poisson.convergence import convergence_figure, lab_sweeps


@pytest.fixture(scope="module")
def messages() -> list[text.Shown]:
    return review.catalog_messages()


def test_latin_words_allow_symbols_units_acronyms_spans_and_glosses():
    good = (
        "在 t = 0.25 处，B(t) 经过 P0 与 P3；宽 1.5 px、用时 3 ms，误差 1e-05；"
        "GAMES101 作业报告、VS2022 作业报告、OpenCV、numpy、Python、Jupyter、RGB 图像；"
        "泼溅（splat）与 `count`、$B_{i,n}(t)$、{name}、dx = 0.5、Gx、见 01_de_casteljau.ipynb"
    )
    assert text.latin_words(good) == []


def test_latin_words_find_english_and_identifiers_on_a_label():
    assert text.latin_words("the GAMES101 report 与 naive_bezier 对比") == [
        "the",
        "report",
        "naive_bezier",
    ]
    assert text.latin_words("规则 'top-left'") == ["top-left"]
    assert text.latin_words("按 arc_length 加权") == ["arc_length"]
    # An author's or a program's name of NAMES stays Latin; one with a Chinese term does not.
    assert text.latin_words("Agg（matplotlib）与 Bresenham 算法") == []
    assert text.latin_words("Wu 直线与 Jacobi 迭代") == ["Wu", "Jacobi"]
    assert text.latin_words("3 × 3 的窗口") == []
    # A triangle by its vertices is a symbol, as P0 is; a repeated letter is not a vertex name.
    assert text.latin_words("只属于 ABC，公共边 AC，AAB") == ["AAB"]
    # A gloss follows a Chinese term, or a numbered term's number; not any number.
    assert text.latin_words("任务 1（Task 1）、泼溅（splat）") == []
    assert text.latin_words("步长 0.5（step）") == ["step"]


def test_loose_text_allows_code_but_not_a_bare_value_or_a_name():
    names = frozenset({"comb", "image"})
    loose = "你的 comb 对 image 调用 int(x)、np.floor 与 cv::Point，method='rows'：抛出 ValueError"
    assert text.latin_words(loose, loose=True, names=names) == []
    assert text.latin_words(loose, loose=False) != []
    assert text.latin_words("wavefront：逐位相同：True", loose=True) == ["wavefront", "True"]
    assert text.latin_words("用 Jacobi 迭代", loose=True, names=names) == ["Jacobi"]
    # A keyword argument's value typed against its name is code; the same value shown is not.
    assert text.latin_words("请传入 force=True", loose=True) == []
    assert text.latin_words("应为 True 或 False", loose=True) == ["True", "False"]
    assert text.latin_words("请传入 force=True") == ["True"]


def test_backticks_printed_as_they_are_are_found():
    assert text.latin_words("讲义里的 `float t`", loose=True, markup=False) == ["`float t`"]
    assert text.latin_words("讲义里的 `float t`", loose=True) == []


def test_code_names_hold_definitions_builtins_and_on_request_parameters():
    names = text.code_names(parameters=False)
    assert {"de_casteljau", "SliderApp", "int", "ValueError"} <= names
    assert not {"True", "False", "None"} & names
    assert "points" in text.code_names(parameters=True)


def test_ascii_punctuation_between_chinese_clauses():
    assert text.ascii_punctuation("期望 16，得到 10；g 中差别最大") == []
    assert text.ascii_punctuation("对 x, y >= 0：`a, b`、$x: y$ 与 (t, 1 - t)") == []
    assert text.ascii_punctuation("for k in range(3): t = k / 2; x, y = f(t)") == []
    assert text.ascii_punctuation("期望 16，得到 10; g 中差别最大") != []
    assert text.ascii_punctuation("像素 (2, 1) 得 0.25, 像素 (2, 2) 得 0.25") != []
    assert text.ascii_punctuation("原地更新: 高斯-赛德尔") != []
    assert text.ascii_punctuation("{name}, 得到 {value}") != []
    assert text.ascii_punctuation("规则 (左上) 画一次") != []


def test_quotation_marks_keep_the_editions_convention():
    assert text.quotation_marks("提示“在这里写你的代码”；把「规则」切换成「左上规则」") == []
    assert text.quotation_marks('`raise NotImplementedError("在这里写你的代码")`') == []
    assert text.quotation_marks("提示«在这里写你的代码»") == ["«", "»"]
    assert text.quotation_marks("『规则』") == ["『", "』"]
    assert text.quotation_marks('提示"在这里写你的代码"') == ['"在这里写你的代码"']
    assert text.quotation_marks("提示“在这里写你的代码") == ["“ without ”"]
    assert text.quotation_marks("「规则」」") == ["」 without 「"]


def test_chinese_texts_quote_with_the_editions_marks(messages):
    shown = [*messages, *review.twin_markdown(), *review.twin_outputs()]
    found = [
        f"{text_.lesson or '--'} {text_.where[:70]}: {marks}"
        for text_ in shown
        for marks in [text.quotation_marks(text_.text)]
        if marks
    ]
    assert found == [], listed(found)


def test_no_latin_words_in_the_catalog(messages):
    library = [text for text in messages if text.where.startswith("course.po")]
    found = latin_report(library, text.code_names(parameters=True))
    assert found == [], listed(found)


def test_chinese_messages_use_chinese_punctuation(messages):
    found = [
        f"{shown.lesson or '--'} {shown.where[:70]}: «{context}»"
        for shown in messages
        for context in text.ascii_punctuation(shown.text)
    ]
    assert found == [], listed(found)


# --- the checkers' and the lessons' own wording ------------------------------------

ROOT = Path(__file__).resolve().parents[1]
POT = ROOT / "course" / "locale" / "course.pot"
# Modules whose messages are Markdown, rendered in a notebook: backticks there are code.
MARKDOWN_MESSAGES = {"course/classroom/course_map.py"}


def test_an_array_of_one_value_is_said_to_be_all_that_value():
    assert show_value(np.zeros((30, 30), dtype=np.int64)).endswith(", all 0")
    with language("zh-CN"):
        chinese = show_value(np.zeros((30, 30), dtype=np.int64))
    assert chinese.endswith("全为 0") and "从 0 到 0" not in chinese


def test_no_plain_text_message_shows_markdown_backticks():
    with POT.open("rb") as file:
        template = read_po(file)
    shown = [
        message.id
        for message in template
        if message.id
        and "`" in str(message.id)
        and {path for path, _line in message.locations} - MARKDOWN_MESSAGES
    ]
    assert shown == []


def test_the_splat_table_joins_its_pixels_in_the_students_language():
    table = np.array([[2, 1, 0.75], [3, 1, 0.25]])
    assert _show_splat(table) == "pixel (2, 1) gets 0.75, pixel (3, 1) gets 0.25"
    with language("zh-CN"):
        chinese = _show_splat(table)
    assert chinese == "像素 (2, 1) 得 0.75、像素 (3, 1) 得 0.25"


@pytest.mark.parametrize(
    ("method", "name"),
    [("dst", "离散正弦变换"), ("direct", "稀疏直接分解"), ("capacitance", "电容矩阵法")],
)
def test_the_exact_solvers_and_their_verdict_print_in_chinese(capsys, method, name):
    with language("zh-CN"):
        l08.print_residual_below(method, True)
    printed = capsys.readouterr().out.strip()
    assert printed.startswith(name) and printed.endswith("是")
    assert not re.search(r"[A-Za-z]{2,}", printed), printed


def test_lesson_07s_verdicts_print_yes_or_no(capsys):
    with language("zh-CN"):
        l07.print_sobel_against_scipy(False)
    assert capsys.readouterr().out.strip().endswith("否")
    l07.print_sobel_against_scipy(True)
    assert capsys.readouterr().out.strip().endswith(": yes")


def test_the_sweep_apps_methods_are_named_in_chinese():
    with language("zh-CN"):
        app = PoissonIterationApp(
            np.full((20, 20), 0.5), np.full((8, 8), 0.4), (5, 5), stops=(0, 1, 10)
        )
        app.refresh()
    labels = [label for label, _value in app.controls["method"].options]
    assert labels == ["雅可比迭代", "高斯-赛德尔迭代", "超松弛迭代"]
    assert app.caption.get_text().startswith("雅可比迭代")


class _Kept:
    """Stands in for Still: keeps the figure instead of rendering it."""

    @staticmethod
    def of(figure, caption):
        return figure


def test_the_convergence_figures_labels_are_chinese_and_clear_of_the_sor_curve(monkeypatch):
    monkeypatch.setattr(convergence, "Still", _Kept)
    with language("zh-CN"):
        figure = convergence_figure()
    axes = figure.axes[0]
    legend = [text.get_text() for text in axes.get_legend().get_texts()]
    assert legend[:2] == ["雅可比迭代", "高斯-赛德尔迭代（实验的循环）"]
    (grey_level,) = [
        child
        for child in axes.get_children()
        if isinstance(child, Annotation) and child.get_text() == "一个灰度级"
    ]
    # The SOR curve stops at its last sweep; the label sits past it, under the other two.
    assert grey_level.xy[0] > lab_sweeps()["sor"]["sweeps"][-1]


def test_the_kernel_apps_presets_are_named_in_chinese_and_keep_their_values(capsys):
    from course.lessons.l07_filtering.apps import KernelApp

    with language("zh-CN"):
        app = KernelApp()
        l07.print_kernel_presets()
    labels = dict(app.controls["preset"].options)
    assert labels["盒式"] == "box" and labels["高斯"] == "Gaussian" and labels["自定义"] == "typed"
    assert capsys.readouterr().out.startswith("盒式          高斯")
