"""What a Chinese student sees (course.classroom.chinese_review), and the controls it names.

The gatherers on small examples; then, read from the committed files and drawn in Chinese,
no Latin word outside the allow-list in the twins' outputs and in every chapter's figures
and apps, and every control the prose names a label of the lesson's apps, in both
languages. Nothing is executed: the twins' outputs are read as committed (``make
notebooks`` writes them).
"""

from __future__ import annotations

import ipywidgets as widgets
import pytest
from chinese import latin_report, listed

from course.classroom import chinese_review as review
from course.classroom import chinese_text as text

LESSONS = review.lesson_numbers()
TWINS = sorted(path.name[:2] for path in (text.NOTEBOOKS / "zh-CN").glob("[0-9][0-9]_*.ipynb"))


def test_output_text_is_what_jupyterlab_shows():
    picture = {"output_type": "display_data", "data": {"image/png": "", "text/plain": "a b"}}
    html = {"output_type": "execute_result", "data": {"text/html": "<b>通过</b> &amp;"}}
    plain = {"output_type": "execute_result", "data": {"text/plain": "True"}}
    assert review.output_text(picture) == ""
    assert review.output_text(html).split() == ["通过", "&"]
    assert review.output_text(plain) == "True"


def test_a_printed_listing_is_read_for_its_docstrings_and_comments():
    listing = 'def f(x):\n    """Twice x."""\n    return 2 * x  # doubled\n'
    assert review.code_listing_text(listing) == "Twice x.\n# doubled"
    assert review.code_listing_text("x = 1") is None  # a line of code, no listing


def test_widget_labels_read_descriptions_options_and_labels():
    box = widgets.VBox(
        [
            widgets.ToggleButtons(options=[("按计数", "count"), ("按弧长", "arc_length")]),
            widgets.IntSlider(description="控制点数"),
            widgets.Label("残差 0.1"),
            widgets.Button(description="重置", tooltip="回到开头"),
        ]
    )
    assert sorted(review.widget_labels(box)) == sorted(
        ["按计数", "按弧长", "控制点数", "残差 0.1", "重置", "回到开头"]
    )
    bare = widgets.ToggleButtons(options=["count", "arc_length"])
    assert review.widget_labels(bare) == ["count", "arc_length"]


def test_a_figure_parameter_without_default_or_sample_is_named():
    def drawing(mystery, t=0.5):
        return mystery

    with pytest.raises(LookupError, match="'mystery'"):
        review._call(drawing, {})
    assert review._call(drawing, {"mystery": 3}) == 3


def test_control_mentions_in_both_languages():
    english = "Drag the points and move *segments*. * Raise *points* to 10. A *gap* is..."
    assert review.control_mentions(english, "en") == ["segments", "points"]
    chinese = "调整 *线段数*。* 把 *控制点数* 调到 10，再把 *采样方式* 切换成“报告的采样”。"
    assert review.control_mentions(chinese, "zh-CN") == [
        "线段数",
        "控制点数",
        "采样方式",
        "报告的采样",
    ]
    assert review.unknown_controls(["控制点数", "points"], {"控制点数："}) == ["points"]


@pytest.fixture(scope="module")
def output_names() -> frozenset[str]:
    return text.code_names(parameters=False)


@pytest.fixture(scope="module")
def outputs() -> list[text.Shown]:
    return review.twin_outputs()


@pytest.mark.parametrize("number", TWINS)
def test_no_latin_words_in_a_twins_outputs(number, outputs, output_names):
    shown = [text for text in outputs if text.lesson == number]
    assert latin_report(shown, output_names) == [], listed(latin_report(shown, output_names))


@pytest.mark.parametrize("number", LESSONS)
def test_no_latin_words_in_a_chapters_figures(number):
    found = latin_report(review.figure_texts(number))
    assert found == [], listed(found)


@pytest.mark.parametrize("number", LESSONS)
def test_no_latin_words_in_a_chapters_apps(number):
    found = latin_report(review.app_texts(number))
    assert found == [], listed(found)


@pytest.mark.parametrize("code", ["en", "zh-CN"])
@pytest.mark.parametrize("number", LESSONS)
def test_the_prose_names_controls_the_apps_show(number, code):
    prose = review.english_markdown() if code == "en" else review.twin_markdown()
    labels = review.app_labels(number, code)
    found = [
        f"{number} {text.where}: *{name}* is no label of the lesson's apps"
        for text in prose
        if text.lesson == number
        for name in review.unknown_controls(review.control_mentions(text.text, code), labels)
    ]
    assert found == [], listed(found) + f"\nlabels: {sorted(labels)}"
