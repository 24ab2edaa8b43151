"""The Chinese lessons: built from their catalogs, the same code as the English ones."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from babel.messages.pofile import read_po

from course.classroom import twins
from course.classroom.cli import main
from course.i18n import LANGUAGE_LINES

NOTEBOOKS = Path(__file__).resolve().parents[1] / "notebooks"
EXISTING_TWINS = sorted((NOTEBOOKS / twins.TWIN_FOLDER).glob("[0-9][0-9]_*.ipynb"))


def lesson(folder: Path, name: str = "01_x") -> Path:
    cells = [
        {
            "cell_type": "markdown",
            "id": "a",
            "metadata": {},
            "source": "# Lesson\n\nThe point $B(t)$ of `f`.",
        },
        {
            "cell_type": "code",
            "id": "b",
            "metadata": {},
            "source": "import math",
            "outputs": [],
            "execution_count": 1,
        },
        {
            "cell_type": "markdown",
            "id": "c",
            "metadata": {},
            "source": "See [the map](00_index.ipynb).",
        },
        {
            "cell_type": "code",
            "id": "d",
            "metadata": {},
            "source": "math.pi",
            "outputs": [
                {
                    "output_type": "execute_result",
                    "data": {"text/plain": "3.14"},
                    "metadata": {},
                    "execution_count": 2,
                }
            ],
            "execution_count": 2,
        },
    ]
    notebook = {"cells": cells, "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    path = folder / f"{name}.ipynb"
    path.write_text(json.dumps(notebook), encoding="utf-8")
    return path


def translate(po_path: Path, translations: dict[str, str]) -> None:
    catalog = twins.read_catalog(po_path)
    for message in catalog:
        if message.id:
            message.string = translations.get(message.context, "")
    twins.write_catalog(po_path, catalog)


def test_update_po_makes_one_untranslated_message_per_markdown_cell(tmp_path):
    english = lesson(tmp_path)
    assert twins.update_catalog(english, tmp_path / "zh-CN" / "01_x.po") == (2, 0)
    with (tmp_path / "zh-CN" / "01_x.po").open("rb") as file:
        catalog = read_po(file)
    assert [(m.context, m.id, m.string) for m in catalog if m.id] == [
        ("a", "# Lesson\n\nThe point $B(t)$ of `f`.", ""),
        ("c", "See [the map](00_index.ipynb).", ""),
    ]


def test_a_twin_has_the_translations_and_the_english_code(tmp_path, capsys):
    english = lesson(tmp_path)
    po_path = tmp_path / "zh-CN" / "01_x.po"
    twins.update_catalog(english, po_path)
    translate(po_path, {"a": "# 课\n\n`f` 的点 $B(t)$。", "c": "见[课程地图](00_index.ipynb)。"})
    assert main(["twins", "--notebooks", str(tmp_path), "--check"]) == 0
    assert "01_x: 2/2 markdown cells translated" in capsys.readouterr().out
    assert main(["twins", "--notebooks", str(tmp_path)]) == 0
    twin = json.loads((tmp_path / "zh-CN" / "01_x.ipynb").read_text(encoding="utf-8"))
    assert [c["source"] for c in twin["cells"] if c["cell_type"] == "markdown"] == [
        "# 课\n\n`f` 的点 $B(t)$。",
        "见[课程地图](00_index.ipynb)。",
    ]
    assert twins.english_code(twin) == ["import math", "math.pi"]
    assert twin["cells"][1]["source"] == LANGUAGE_LINES + "import math"
    assert all(c["outputs"] == [] for c in twin["cells"] if c["cell_type"] == "code")


def test_a_changed_english_cell_is_untranslated_until_its_message_is(tmp_path, capsys):
    english = lesson(tmp_path)
    po_path = tmp_path / "zh-CN" / "01_x.po"
    twins.update_catalog(english, po_path)
    translate(po_path, {"a": "# 课\n\n`f` 的点 $B(t)$。", "c": "见[课程地图](00_index.ipynb)。"})
    notebook = json.loads(english.read_text(encoding="utf-8"))
    notebook["cells"][2]["source"] = "See [the course map](00_index.ipynb)."
    english.write_text(json.dumps(notebook), encoding="utf-8")
    assert main(["twins", "--notebooks", str(tmp_path), "--check"]) == 1
    assert "untranslated: c" in capsys.readouterr().out
    assert twins.update_catalog(english, po_path) == (1, 1)
    catalog = twins.read_catalog(po_path)
    assert catalog.get("See [the course map](00_index.ipynb).", context="c").string == ""
    assert ("See [the map](00_index.ipynb).", "c") in catalog.obsolete


def test_inserting_moving_and_deleting_cells_keeps_every_other_translation(tmp_path):
    """Translations follow cell ids, not positions: a real lesson, edited, keeps them all."""
    english = tmp_path / "03_lines_and_triangles.ipynb"
    english.write_text((NOTEBOOKS / english.name).read_text(encoding="utf-8"), encoding="utf-8")
    po_path = tmp_path / "zh-CN" / "03_lines_and_triangles.po"
    po_path.parent.mkdir()
    po_path.write_text(
        (NOTEBOOKS / "zh-CN" / po_path.name).read_text(encoding="utf-8"), encoding="utf-8"
    )
    notebook = json.loads(english.read_text(encoding="utf-8"))
    before = {c["id"] for c in notebook["cells"] if c["cell_type"] == "markdown"}
    new = {"cell_type": "markdown", "id": "md-inserted", "metadata": {}, "source": "New words."}
    code = {"cell_type": "code", "id": "code-inserted", "metadata": {}, "source": "1 + 1"}
    code |= {"outputs": [], "execution_count": None}
    cells = notebook["cells"]
    moved = cells.pop(3)
    deleted = next(c for c in cells[5:] if c["cell_type"] == "markdown")
    cells.remove(deleted)
    notebook["cells"] = [cells[0], new, code, *cells[1:-2], moved, *cells[-2:]]
    english.write_text(json.dumps(notebook), encoding="utf-8")

    assert twins.update_catalog(english, po_path) == (1, 1)
    twin, report = twins.build_twin(english, twins.read_catalog(po_path))
    assert report.untranslated == ["md-inserted"]
    assert report.cells == len(before)  # one deleted, one inserted: all others translated
    assert report.problems == []
    assert [c["id"] for c in twin["cells"]] == [c["id"] for c in notebook["cells"]]


def test_writing_the_twins_rewrites_only_the_one_that_changed(tmp_path):
    for name in ("01_x", "02_y"):
        english = lesson(tmp_path, name)
        po_path = tmp_path / "zh-CN" / f"{name}.po"
        twins.update_catalog(english, po_path)
        translate(
            po_path, {"a": "# 课\n\n`f` 的点 $B(t)$。", "c": "见[课程地图](00_index.ipynb)。"}
        )
    twins.write_twins(tmp_path)
    executed = tmp_path / "zh-CN" / "02_y.ipynb"
    twin = json.loads(executed.read_text(encoding="utf-8"))
    twin["cells"][3]["outputs"] = [{"output_type": "stream", "name": "stdout", "text": "3.14"}]
    executed.write_text(json.dumps(twin), encoding="utf-8")
    untouched = executed.read_bytes()

    english = tmp_path / "01_x.ipynb"
    notebook = json.loads(english.read_text(encoding="utf-8"))
    notebook["cells"][3]["source"] = "math.tau"
    english.write_text(json.dumps(notebook), encoding="utf-8")
    twins.write_twins(tmp_path)
    assert executed.read_bytes() == untouched
    changed = json.loads((tmp_path / "zh-CN" / "01_x.ipynb").read_text(encoding="utf-8"))
    assert twins.english_code(changed) == ["import math", "math.tau"]


@pytest.mark.parametrize("path", sorted(NOTEBOOKS.glob("**/[0-9][0-9]_*.ipynb")), ids=str)
def test_every_lesson_cell_has_a_stable_id_of_its_own(path):
    """Ids that are not positions: nbstripout without --keep-id renumbers cells "0", "1", ..."""
    ids = [cell.get("id") for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]]
    assert all(ids) and len(set(ids)) == len(ids), path.name
    positional = [cell_id for cell_id in ids if re.fullmatch(r"\d+", cell_id)]
    assert not positional, f"{path.name}: positional cell ids {positional[:5]}"
    if path.parent.name == twins.TWIN_FOLDER:
        english = json.loads((NOTEBOOKS / path.name).read_text(encoding="utf-8"))
        assert ids == [cell["id"] for cell in english["cells"]], path.name


def test_a_translation_that_loses_a_formula_or_a_link_target_is_reported(tmp_path, capsys):
    english = lesson(tmp_path)
    po_path = tmp_path / "zh-CN" / "01_x.po"
    twins.update_catalog(english, po_path)
    translate(po_path, {"a": "# 课\n\n`f` 的点 B(t)。", "c": "见[课程地图](00_index_zh.ipynb)。"})
    assert main(["twins", "--notebooks", str(tmp_path), "--check"]) == 1
    out = capsys.readouterr().out
    assert "cell a: LaTeX/code/links differ: lost ['$B(t)$']" in out
    assert "cell c: LaTeX/code/links differ: lost ['](00_index.ipynb)']" in out


def test_a_catalog_written_by_the_builder_reads_back_exactly(tmp_path):
    source = "# Title\n\n" + "a long line of text " * 20 + "\n\n* item `x`\n  continued\n"
    catalog = twins.new_catalog("01_x")
    catalog.add(source, "标题 " * 40 + "\n", context="id-1")
    twins.write_catalog(tmp_path / "x.po", catalog)
    back = twins.read_catalog(tmp_path / "x.po")
    assert back.get(source, context="id-1").string == "标题 " * 40 + "\n"


@pytest.mark.parametrize("twin_path", EXISTING_TWINS, ids=lambda p: p.stem)
def test_a_committed_twin_has_the_english_code_and_no_untranslated_cell(twin_path):
    twin = json.loads(twin_path.read_text(encoding="utf-8"))
    english = json.loads((NOTEBOOKS / twin_path.name).read_text(encoding="utf-8"))
    english_code = [twins.cell_source(c) for c in english["cells"] if c["cell_type"] == "code"]
    # The same code; only the docstrings and comments are in Chinese.
    assert list(map(twins.code_skeleton, twins.english_code(twin))) == list(
        map(twins.code_skeleton, english_code)
    ), (
        f"{twin_path.name}: the twin's code differs from the English lesson's: run "
        "python -m course twins (make notebooks executes it)"
    )
    po_path = twin_path.with_suffix(".po")
    built, report = twins.build_twin(NOTEBOOKS / twin_path.name, twins.read_catalog(po_path))
    assert twins.same_cells(built, twin), f"{twin_path.name}: run python -m course twins"
    assert report.untranslated == [], (
        f"{po_path.name}: markdown cells without a translation, by id: {report.untranslated}; "
        "python -m course twins --update-po adds them, then translate them there"
    )
    assert report.problems == [], f"{po_path.name}: {report.problems}"


EXERCISE = (
    "def area(w, h):\n"
    '    """Width times height,\n    in pixels."""\n'
    "    return w * h  # the rectangle's\n"
    "\n\n"
    "check.area(area)"
)


def exercise_lesson(folder: Path, source: str = EXERCISE) -> Path:
    english = lesson(folder)
    notebook = json.loads(english.read_text(encoding="utf-8"))
    cell = {"cell_type": "code", "id": "e", "metadata": {"tags": ["solution"]}, "source": source}
    notebook["cells"].append({**cell, "outputs": [], "execution_count": None})
    english.write_text(json.dumps(notebook), encoding="utf-8")
    return english


TRANSLATED = {
    "a": "# 课\n\n`f` 的点 $B(t)$。",
    "c": "见[课程地图](00_index.ipynb)。",
    "e:docstring": "宽乘以高，\n单位是像素。",
    "e:comment": "矩形的",
}


def test_update_po_adds_each_docstring_and_comment_of_the_code(tmp_path):
    english = exercise_lesson(tmp_path)
    assert twins.update_catalog(english, tmp_path / "zh-CN" / "01_x.po") == (4, 0)
    catalog = twins.read_catalog(tmp_path / "zh-CN" / "01_x.po")
    assert [(m.context, m.id) for m in catalog if m.id][2:] == [
        ("e:docstring", "Width times height,\nin pixels."),  # its lines without their indent
        ("e:comment", "the rectangle's"),
    ]


def test_a_docstring_is_translated_and_the_code_around_it_is_unchanged(tmp_path, capsys):
    english = exercise_lesson(tmp_path)
    po_path = tmp_path / "zh-CN" / "01_x.po"
    twins.update_catalog(english, po_path)
    translate(po_path, TRANSLATED)
    assert main(["twins", "--notebooks", str(tmp_path), "--check"]) == 0
    assert "01_x: 2/2 markdown cells translated, 2/2 docstrings and comments" in (
        capsys.readouterr().out
    )
    assert main(["twins", "--notebooks", str(tmp_path)]) == 0
    twin = json.loads((tmp_path / "zh-CN" / "01_x.ipynb").read_text(encoding="utf-8"))
    assert twins.english_code(twin)[2] == (
        'def area(w, h):\n    """宽乘以高，\n    单位是像素。"""\n    return w * h  # 矩形的\n\n\n'
        "check.area(area)"
    )
    assert twins.code_skeleton(twins.english_code(twin)[2]) == twins.code_skeleton(EXERCISE)


def test_a_changed_docstring_becomes_untranslated(tmp_path, capsys):
    english = exercise_lesson(tmp_path)
    po_path = tmp_path / "zh-CN" / "01_x.po"
    twins.update_catalog(english, po_path)
    translate(po_path, TRANSLATED)
    english = exercise_lesson(tmp_path, EXERCISE.replace("Width times", "Width by"))
    assert main(["twins", "--notebooks", str(tmp_path), "--check"]) == 1
    assert "untranslated: e:docstring" in capsys.readouterr().out
    assert twins.update_catalog(english, po_path) == (1, 1)
    twin, report = twins.build_twin(english, twins.read_catalog(po_path))
    assert report.untranslated == ["e:docstring"]
    code = twins.english_code(twin)[2]  # the docstring English until translated, the comment not
    assert '"""Width by height,\n    in pixels."""' in code and "# 矩形的" in code


def test_a_translation_that_would_break_the_code_is_reported_and_not_used(tmp_path, capsys):
    english = exercise_lesson(tmp_path)
    po_path = tmp_path / "zh-CN" / "01_x.po"
    twins.update_catalog(english, po_path)
    translate(po_path, TRANSLATED | {"e:docstring": '宽乘以高"""', "e:comment": "矩形\n的"})
    assert main(["twins", "--notebooks", str(tmp_path), "--check"]) == 1
    out = capsys.readouterr().out
    assert "e:docstring: the translation changes the code around it" in out
    assert "e:comment: a comment's translation must be one line" in out
    twin, _ = twins.build_twin(english, twins.read_catalog(po_path))
    assert twins.english_code(twin)[2] == EXERCISE


def test_the_editions_markers_and_tool_comments_are_not_words_to_translate():
    source = "def f():\n    ### BEGIN SOLUTION\n    return 1  # noqa: E501\n    ### END SOLUTION"
    assert twins.code_texts("x", source) == []
    assert twins.code_texts("x", "%timeit f()  # magic") == []


def test_the_handout_keys_anchor_may_be_the_translated_headings_and_formulas_may_wrap():
    from course.classroom.twins import translation_problems

    english = "See [the handouts](00_index.ipynb#The-handouts): $4(1 - \\rho) \\approx\n0.00094$."
    chinese = "见[讲义](00_index.ipynb#讲义)：$4(1 - \\rho) \\approx\n0.00094$。"
    assert translation_problems("c", english, chinese) == []
    wrong_anchor = chinese.replace("#讲义", "#The-handouts")
    assert translation_problems("c", english, wrong_anchor) != []
    assert translation_problems("c", english, chinese.replace("0.00094", "0.0009")) != []


def test_a_fenced_blocks_comments_are_translated_and_its_code_kept():
    # Lesson 03's pseudocode said "# the line is nearer the next row" in the Chinese twin.
    from course.classroom.twins import translation_problems

    english = (
        "Then:\n\n```\nif D > 0:            # the line is nearer the next row\n    y = y + 1\n```"
    )
    chinese = "于是：\n\n```\nif D > 0:    # 直线离下一行更近\n    y = y + 1\n```"
    assert translation_problems("c", english, chinese) == []
    assert translation_problems("c", english, chinese.replace("y + 1", "y + 2")) != []
    assert translation_problems("c", english, chinese.replace("D > 0", "D >= 0")) != []


def chinese_share(markdown: str) -> float:
    """Chinese characters as a share of all letters, outside code, formulas and link targets."""
    prose = re.sub(r"```.*?```|`[^`]*`|\$\$.*?\$\$|\$[^$]*\$|<[^>]+>", " ", markdown, flags=re.S)
    prose = re.sub(r"\]\([^)]*\)", "]", prose)
    chinese = len(re.findall(r"[\u4e00-\u9fff]", prose))
    latin = len(re.findall(r"[A-Za-z]", prose))
    return chinese / (chinese + latin)


def test_the_share_counts_chinese_against_latin_letters_outside_code_and_formulas():
    assert chinese_share("中文 `code` $x + y$ [链接](00_index.ipynb)") == 1.0
    assert chinese_share("四个字 GAMES") == pytest.approx(3 / 8)


@pytest.mark.parametrize("twin_path", EXISTING_TWINS, ids=lambda path: path.stem)
def test_a_chinese_lesson_reads_in_chinese_at_least_90_percent(twin_path):
    notebook = json.loads(twin_path.read_text(encoding="utf-8"))
    markdown = "\n".join(
        "".join(cell["source"]) for cell in notebook["cells"] if cell["cell_type"] == "markdown"
    )
    assert chinese_share(markdown) >= 0.9, twin_path.stem


def test_a_translation_may_mark_more_as_code_or_math_but_loses_nothing():
    from course.classroom.twins import translation_problems

    english = "Move P0 with `addColor` to $t = 1$; see [the handout](handout.md)."
    chinese = "用 `addColor` 把 $P_0$ 移到 $t = 1$，顶点 $A$ 同理；见[讲义](handout.md)。"
    assert translation_problems("c", english, chinese) == []
    assert translation_problems("c", english, chinese.replace("`addColor`", "addColor")) != []
    assert translation_problems("c", english, chinese + "[另见](other.md)") != []
