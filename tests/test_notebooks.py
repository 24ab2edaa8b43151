"""course.classroom.notebooks: the lesson notebooks found on disk, in order, titled."""

import pytest
from conftest import write_notebook

from course.classroom.notebooks import NOTEBOOKS, notebooks


def test_every_lesson_notebook_is_found_in_order_and_titled_by_its_first_heading(tmp_path):
    write_notebook(tmp_path / "00_index.ipynb", "# Map")
    write_notebook(
        tmp_path / "09_later.ipynb", "intro without heading", "# Third\n\nIt does | this."
    )
    write_notebook(
        tmp_path / "01_first.ipynb", "# First lesson\n\nFirst line\nof one paragraph.\n\nMore."
    )
    write_notebook(tmp_path / "scratch.ipynb", "# Not a lesson")
    write_notebook(tmp_path / "1_short.ipynb", "# Not a lesson either")
    found = notebooks(tmp_path)
    assert [(book.number, book.topic, book.title) for book in found] == [
        ("01", "first", "First lesson"),
        ("09", "later", "Third"),
    ]
    assert found[0].summary == "First line of one paragraph."
    assert found[1].path == tmp_path / "09_later.ipynb"
    assert [book.number for book in notebooks(tmp_path, index=True)] == ["00", "01", "09"]


def test_a_notebook_without_a_heading_is_refused_by_name(tmp_path):
    write_notebook(tmp_path / "04_bad.ipynb", "no heading here")
    with pytest.raises(ValueError, match=r"04_bad\.ipynb"):
        notebooks(tmp_path)
    with pytest.raises(ValueError, match="expected a folder"):
        notebooks(tmp_path / "missing")


def test_the_repository_s_lessons_are_numbered_from_01_without_gaps():
    numbers = [book.number for book in notebooks(NOTEBOOKS, index=True)]
    assert numbers == [f"{n:02d}" for n in range(len(numbers))]
