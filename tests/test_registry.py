"""course.classroom.registry: lesson chapters discovered, matched to notebooks, none listed.

A new lesson is new files only: a chapter ``course/lessons/lNN_topic/`` and a notebook.
The last test proves it with a throwaway lesson made in a temporary folder.
"""

import io
import re
import sys
import textwrap

import pytest
from conftest import write_notebook
from PIL import Image

import course.lessons
from course.classroom.course_map import course_map
from course.classroom.gallery import gallery_pictures, write_gallery
from course.classroom.notebooks import notebooks
from course.classroom.registry import lesson_modules, lessons


def test_the_repository_notebooks_and_the_lesson_modules_agree():
    found = {book.number: book for book in notebooks()}
    modules = lesson_modules()
    assert list(modules) == list(found), "every lesson notebook has its module, and only those"
    entries = lessons()
    for number, book in found.items():
        assert modules[number] == f"course.lessons.l{number}_{book.topic}.lesson"
        assert re.match(rf"Lesson {number} · ", book.title), book.title
        lesson = entries[number]
        assert lesson.handout and lesson.teaches and lesson.pictures, number
        assert all(picture.name.startswith(f"{number}_") for picture in lesson.pictures)
    every_name = [picture.name for lesson in entries.values() for picture in lesson.pictures]
    assert len(set(every_name)) == len(every_name)


def test_the_course_s_slider_lessons_are_registered():
    # Slider moves checked against the library for lessons 01, 03, 05 and 06 at least.
    with_sliders = {number for number, lesson in lessons().items() if lesson.sliders}
    assert {"01", "03", "05", "06"} <= with_sliders


THROWAWAY = '''
"""Lesson 09, polygon clipping: a throwaway lesson made by a test."""

from matplotlib.figure import Figure

from course.classroom.pictures import figure_picture
from course.classroom.registry import Lesson, Picture


def clipped_square() -> bytes:
    figure = Figure(figsize=(1, 1), dpi=20)
    figure.add_subplot().fill([0, 1, 1, 0], [0, 0, 1, 1])
    return figure_picture(figure)


LESSON = Lesson(
    handout="Lab 2, Task 1: Sutherland-Hodgman",
    teaches="clipping a polygon against a window, edge by edge",
    pictures=(Picture("09_clipped_square", "a square, clipped", clipped_square),),
)
'''


@pytest.fixture
def throwaway_lesson(tmp_path, monkeypatch):
    """A lesson chapter and its notebook, written to a temporary folder, nowhere else."""
    modules = tmp_path / "modules"
    chapter = modules / "l09_polygon_clipping"
    chapter.mkdir(parents=True)
    (chapter / "__init__.py").write_text('"""Lesson 09 · Polygon clipping."""\n')
    (chapter / "lesson.py").write_text(textwrap.dedent(THROWAWAY))
    books = tmp_path / "notebooks"
    books.mkdir()
    write_notebook(books / "01_de_casteljau.ipynb", "# Lesson 01 · de Casteljau's algorithm")
    write_notebook(books / "09_polygon_clipping.ipynb", "# Lesson 09 · Polygon clipping\n\nIt.")
    # Where the course looks for lesson modules, plus the temporary folder.
    monkeypatch.setattr(course.lessons, "__path__", [*course.lessons.__path__, str(modules)])
    yield books
    sys.modules.pop("course.lessons.l09_polygon_clipping", None)
    sys.modules.pop("course.lessons.l09_polygon_clipping.lesson", None)


def test_a_new_lesson_is_new_files_only(throwaway_lesson, tmp_path):
    assert lesson_modules()["09"] == "course.lessons.l09_polygon_clipping.lesson"
    assert lessons()["09"].teaches == "clipping a polygon against a window, edge by edge"
    table = course_map(throwaway_lesson).splitlines()
    assert table[-1] == (
        "| [Lesson 09 · Polygon clipping](09_polygon_clipping.ipynb) | clipping a polygon "
        "against a window, edge by edge | Lab 2, Task 1: Sutherland-Hodgman |  |"
    )
    pictures = gallery_pictures(throwaway_lesson)
    assert [picture.name for picture in pictures][-1] == "09_clipped_square"
    written = write_gallery(tmp_path / "gallery", pictures=pictures[-1:], stream=io.StringIO())
    assert [path.name for path in written] == ["09_clipped_square.png"]
    assert Image.open(written[0]).format == "PNG"


def test_a_chapter_without_its_entry_is_refused_by_name(tmp_path, monkeypatch):
    (tmp_path / "l10_empty").mkdir()
    (tmp_path / "l10_empty" / "__init__.py").write_text("")
    (tmp_path / "l10_empty" / "lesson.py").write_text('"""No LESSON here."""\n')
    monkeypatch.setattr(course.lessons, "__path__", [*course.lessons.__path__, str(tmp_path)])
    try:
        with pytest.raises(
            TypeError, match=r"course\.lessons\.l10_empty\.lesson: expected .*LESSON"
        ):
            lessons()
    finally:
        sys.modules.pop("course.lessons.l10_empty", None)
        sys.modules.pop("course.lessons.l10_empty.lesson", None)


def test_a_lesson_module_that_is_not_a_chapter_is_refused_by_name(tmp_path, monkeypatch):
    (tmp_path / "l11_flat.py").write_text("")
    monkeypatch.setattr(course.lessons, "__path__", [*course.lessons.__path__, str(tmp_path)])
    with pytest.raises(TypeError, match="l11_flat: a lesson is a chapter, a folder l11_flat/"):
        lesson_modules()


def test_two_chapters_for_one_lesson_are_refused(tmp_path, monkeypatch):
    (tmp_path / "l01_again").mkdir()
    (tmp_path / "l01_again" / "__init__.py").write_text("")
    monkeypatch.setattr(course.lessons, "__path__", [*course.lessons.__path__, str(tmp_path)])
    with pytest.raises(ValueError, match="lesson 01: two chapters claim it"):
        lesson_modules()
