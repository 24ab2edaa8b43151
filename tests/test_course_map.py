"""course.classroom.course_map: the course map's table, and the README's copy of it."""

import re
from pathlib import Path

from conftest import write_notebook

from course.classroom.cli import main
from course.classroom.course_map import (
    EXERCISE_GUIDE,
    HANDOUTS,
    README_MARKERS,
    course_map,
    handout_key,
    lesson_card,
    readme_lessons,
    update_readme,
)
from course.classroom.notebooks import NOTEBOOKS, notebooks
from course.classroom.registry import lessons
from course.i18n import language

README = Path(__file__).resolve().parent.parent / "README.md"


def test_one_row_per_lesson_with_its_registry_entry_or_its_summary(tmp_path):
    write_notebook(tmp_path / "01_de_casteljau.ipynb", "# Lesson 01 · de Casteljau")
    write_notebook(tmp_path / "42_unregistered.ipynb", "# Later\n\nIt does | this.")
    table = course_map(tmp_path, guide=False).splitlines()
    assert table[0] == "| lesson | after it you can | handout task it answers | time |"
    assert len(table) == 2 + 2
    entry = lessons()["01"]
    assert entry.outcomes and entry.minutes
    assert table[2] == (
        f"| [Lesson 01 · de Casteljau](01_de_casteljau.ipynb) | {'; '.join(entry.outcomes)} "
        f"| {entry.handout} | {entry.minutes} min |"
    )
    # A notebook without a module still has its row: its summary, and what to add.
    assert table[3] == (
        "| [Later](42_unregistered.ipynb) | It does \\| this. "
        "| (no module course/lessons/l42_unregistered.py) |  |"
    )


def test_every_lesson_says_what_a_student_can_do_after_it_how_long_and_shows_one_panel():
    for number, lesson in lessons().items():
        assert 2 <= len(lesson.outcomes) <= 3, number
        assert 20 <= lesson.minutes <= 120, number
        assert lesson.preview is not None and lesson.preview.name.startswith(f"{number}_")


def test_the_readme_lesson_table_is_the_course_map(capsys):
    """The README's table is generated: ``make notebooks`` runs ``python -m course map``."""
    expected = course_map(link_prefix="notebooks/", guide=False)
    assert main(["map", "--link-prefix", "notebooks/"]) == 0
    assert capsys.readouterr().out == expected + "\n"
    start, end = README_MARKERS
    section = README.read_text(encoding="utf-8").split(start)[1].split(end)[0].strip()
    assert section == readme_lessons(link_prefix="notebooks/"), (
        "README.md's lesson table is out of date: run `make notebooks`, or "
        "`python -m course map --readme README.md`"
    )
    links = re.findall(r"\]\((notebooks/[^)]+)\)", section)
    assert links == [f"notebooks/{book.path.name}" for book in notebooks()]
    assert all((README.parent / link).is_file() for link in links)


def test_update_readme_rewrites_only_between_its_markers(tmp_path, capsys):
    books = tmp_path / "lessons"
    books.mkdir()
    write_notebook(books / "01_de_casteljau.ipynb", "# Lesson 01 · de Casteljau")
    readme = tmp_path / "README.md"
    start, end = README_MARKERS
    readme.write_text(f"# Course\n\n{start}\nold table\n{end}\n\nMore.\n")
    assert main(["map", "--readme", str(readme), "--notebooks", str(books)]) == 0
    assert "lesson table rewritten" in capsys.readouterr().out
    text = readme.read_text()
    assert text.startswith(f"# Course\n\n{start}\n| lesson |") and text.endswith(
        f"{end}\n\nMore.\n"
    )
    assert "](lessons/01_de_casteljau.ipynb)" in text and "old table" not in text
    assert update_readme(readme, books) is False
    readme.write_text("no markers\n")
    assert main(["map", "--readme", str(readme), "--notebooks", str(books)]) == 2
    assert "expected one line" in capsys.readouterr().err


def test_the_handout_key_names_each_handout_once_by_role_and_own_title_and_no_file_name():
    key = handout_key().splitlines()
    assert len(key) == 2 + len(HANDOUTS)
    roles = [handout.role for handout in HANDOUTS]
    assert len(set(roles)) == len(roles)
    for handout, row in zip(HANDOUTS, key[2:], strict=True):
        assert row.startswith(f"| {handout.role} | {handout.title} |")
    # A student never meets the handouts' file names ("seed 000").
    assert "seed" not in handout_key()
    for lesson in lessons().values():
        assert "seed" not in lesson.handout, lesson.handout
    # Each lesson a handout names exists.
    numbers = set(lessons())
    for handout in HANDOUTS:
        assert set(handout.lessons.split(", ")) <= numbers, handout.role


def test_every_lesson_links_to_the_handout_key_in_the_course_map():
    map_text = (Path(__file__).resolve().parent.parent / "notebooks" / "00_index.ipynb").read_text(
        encoding="utf-8"
    )
    assert "handout_key()" in map_text and "## The handouts" in map_text
    for book in notebooks():
        if book.number == "00":
            continue
        assert "00_index.ipynb#The-handouts" in book.path.read_text(encoding="utf-8"), book.path


def test_the_course_map_notebook_shows_how_an_exercise_works_above_the_table(tmp_path):
    write_notebook(tmp_path / "01_de_casteljau.ipynb", "# Lesson 01 · de Casteljau")
    shown = course_map(tmp_path)
    assert shown.startswith(EXERCISE_GUIDE) and shown.endswith(course_map(tmp_path, guide=False))
    # What a student must read there: the stub to replace, run, PASS or FAIL, where to work.
    for words in ('raise NotImplementedError("your code here")', "run the cell", "**PASS**",
                  "**FAIL**", "student/", "make lab", "never"):  # fmt: skip
        assert words in EXERCISE_GUIDE, words


CHINESE = re.compile("[\u4e00-\u9fff]")


def test_the_course_map_in_chinese_shows_chinese_lessons_handouts_and_guide():
    with language("zh-CN"):
        shown = course_map(NOTEBOOKS / "zh-CN")
        key = handout_key()
        outcome = lessons()["08"].outcomes[0]
        title = HANDOUTS[0].title
    assert shown.startswith("### 练习怎么做")
    assert "| 课 | 学完你能够 | 对应的讲义任务 | 时长 |" in shown
    assert "[第 01 课 · " in shown and "60 分钟" in shown
    assert "通过反复做线性插值，手算贝塞尔曲线上的一个点" in shown
    # Each lesson's row: its title, what it teaches and its handout task, in Chinese.
    rows = [line for line in shown.splitlines() if line.startswith("| [")]
    assert len(rows) == len(lessons())
    assert all(len(CHINESE.findall(row)) > 20 for row in rows)
    assert outcome == "通过求解泊松方程，把一幅图像无缝地贴进另一幅"
    assert key.startswith("| 课程里的称呼 |") and "| GAMES101 作业报告 |" in key
    # The handouts' own titles stay as the student holds them: a Chinese one as it is, an
    # English one glossing its Chinese translation (issue 36).
    assert "| HW4:绘制贝塞尔曲线 + 线性插值反走样 |" in key
    assert "| 实验 01 报告（Lab01 Report） |" in key
    assert title.startswith("作业 4 的题目：GAMES101 作业报告在“题目”下引用")


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


def test_a_lesson_card_says_what_comes_after_it_in_the_language():
    outcomes = ("blur", "find edges")
    english = lesson_card("Lesson 07 · Filtering", "07_filtering.ipynb", outcomes)
    assert english == (
        "### [Lesson 07 · Filtering](07_filtering.ipynb)\n\nAfter it you can:\n* blur\n* find edges"
    )
    with language("zh-CN"):
        chinese = lesson_card("第 07 课 · 滤波", "07_filtering.ipynb", outcomes)
    assert chinese.splitlines()[2] == "学完这一课，你能够："
