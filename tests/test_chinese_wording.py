"""What a Chinese student reads from the checkers and lessons 07-08 (issue 36).

Each test holds one thing the reader found: a Latin name or a Python boolean in Chinese
output, an ASCII joiner between Chinese clauses, Markdown backticks shown as they are, a
range "from 0 to 0", a bare «你的» title, a label drawn over a curve.
"""

import re
from pathlib import Path

import numpy as np
import pytest
from babel.messages.pofile import read_po
from matplotlib.text import Annotation

from course.check.answers import show_value
from course.i18n import language
from course.lessons.l05_antialiasing.check import _show_splat
from course.lessons.l07_filtering import lesson as l07
from course.lessons.l08_poisson import convergence
from course.lessons.l08_poisson import lesson as l08
from course.lessons.l08_poisson.apps import PoissonIterationApp
from course.lessons.l08_poisson.convergence import convergence_figure, lab_sweeps

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
