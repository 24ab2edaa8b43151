"""The rules of a Chinese text (course.classroom.chinese_text), on examples and on the catalogs.

Each scanner passes a small good example and fails a small bad one; then the library's
catalog ``course.po`` must hold no Latin word outside the allow-list, and every Chinese
message (the library's and the lessons') Chinese punctuation between Chinese words.
"""

from __future__ import annotations

import pytest

from course.classroom import chinese_review as review
from course.classroom import chinese_text as text


def listed(found: list[str]) -> str:
    return f"{len(found)} found:\n" + "\n".join(found)


def latin_report(texts: list[text.Shown], names: frozenset[str] = frozenset()) -> list[str]:
    found = []
    for shown in texts:
        words = shown.latin(names)
        if words:
            excerpt = shown.text.strip().replace("\n", " ")[:90]
            found.append(f"{shown.lesson} {shown.where}: {sorted(set(words))} in «{excerpt}»")
    return sorted(set(found))


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
