"""The glossary (course.classroom.glossary): its file, its checks, and the course against it.

The checks pass a small good example and fail a small bad one; then no forbidden variant
may appear in the twins' markdown, the catalogs or the twins' outputs, and each first-use
gloss must be where its row says.
"""

from __future__ import annotations

import pytest

from course.classroom import chinese_review as review
from course.classroom import chinese_text as text
from course.classroom import glossary


def listed(found: list[str]) -> str:
    return f"{len(found)} found:\n" + "\n".join(found)


@pytest.fixture(scope="module")
def terms() -> list[glossary.Term]:
    return glossary.load_glossary()


def test_the_glossary_has_one_term_per_concept(terms):
    assert len(terms) >= 19
    for term in terms:
        assert term.chinese not in term.forbidden, term
        assert not term.gloss or term.chinese in term.gloss, term
        for variant, pattern in term.variants():
            assert not pattern.search(term.chinese), (term, variant)
            assert not pattern.search(term.gloss), (term, variant)


def test_a_bad_glossary_row_is_refused(tmp_path):
    heading = "\t".join(("concept", "chinese", "forbidden", "gloss", "gloss_lessons", "scope"))
    path = tmp_path / "glossary.tsv"
    path.write_text(f"# a comment\n{heading}\nloop\t循环\t回圈\n", encoding="utf-8")
    with pytest.raises(ValueError, match="columns"):
        glossary.load_glossary(path)
    path.write_text(f"{heading}\nloop\t循环\t/(/\t\t\t\n", encoding="utf-8")
    with pytest.raises(ValueError, match="row 2"):
        glossary.load_glossary(path)
    path.write_text(f"{heading}\na\t循环\t\t\t\t\nb\t循环\t\t\t\t\n", encoding="utf-8")
    with pytest.raises(ValueError, match="twice"):
        glossary.load_glossary(path)
    path.write_text(f"{heading}\nloop\t循环\t回圈 | /圈$/\t\t\t03\n", encoding="utf-8")
    (term,) = glossary.load_glossary(path)
    assert term.forbidden == ("回圈", "/圈$/") and term.scope == ("03",)


def test_forbidden_variants_are_found_in_scope_and_outside_code():
    term = glossary.Term("wrap bug", "笔误", ("失误",), "", (), ("06",))
    texts = [
        text.Shown("06", "cell 1", "这个失误改变了像素"),
        text.Shown("06", "cell 2", "这个笔误改变了像素，`失误`"),
        text.Shown("05", "cell 3", "一次失误"),
    ]
    (found,) = glossary.forbidden_variants([term], texts)
    assert found.startswith("06 cell 1: 失误 (use 笔误)")
    regex = glossary.Term("degree 3", "三次曲线", (r"/\d+ ?次曲线/",), "", (), ())
    assert glossary.forbidden_variants([regex], [text.Shown("", "x", "一条三次曲线")]) == []
    assert glossary.forbidden_variants([regex], [text.Shown("", "x", "一条 3 次曲线")]) != []


def test_first_use_glosses():
    term = glossary.Term("anti-aliasing", "反走样", (), "反走样（抗锯齿）", ("00", "05"), ())
    good = {"00": "反走样（抗锯齿）……反走样", "05": "本课讲反走样（抗锯齿）"}
    assert glossary.missing_glosses([term], good) == []
    late = {"00": "反走样……反走样（抗锯齿）", "05": "没有"}
    assert glossary.missing_glosses([term], late) == [
        "00: 反走样 is first used without its gloss «反走样（抗锯齿）»",
        "05: no «反走样（抗锯齿）» at the first use of 反走样",
    ]
    once = glossary.Term("splat", "泼溅", (), "泼溅（splat）", ("first",), ())
    assert glossary.missing_glosses([once], {"05": "泼溅（splat）与泼溅（splat）"}) == [
        "05: «泼溅（splat）» given 2 times"
    ]


def test_no_forbidden_variant_in_twins_catalogs_and_outputs(terms):
    texts = [*review.twin_markdown(), *review.catalog_messages(), *review.twin_outputs()]
    found = glossary.forbidden_variants(terms, texts)
    assert found == [], listed(found)


def test_every_first_use_gloss_is_given(terms):
    lessons = dict(review.by_lesson(review.twin_markdown()))
    found = glossary.missing_glosses(terms, lessons)
    assert found == [], listed(found)
