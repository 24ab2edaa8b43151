"""course.classroom.link: the nbgitpuller link, and a pulled lesson keeping a student's work."""

import json
import shutil
import subprocess
from urllib.parse import parse_qs, urlsplit

import pytest

from course.classroom.cli import main
from course.classroom.edition_folder import write_student_edition
from course.classroom.link import lessons_folder, nbgitpuller_link, pull_path
from course.classroom.notebooks import NOTEBOOKS


def test_the_link_asks_the_hub_to_pull_the_edition_and_open_its_map():
    link = nbgitpuller_link(
        "https://hub.example.edu/prefix/", "https://git.example.edu/cg/student-edition.git"
    )
    parts = urlsplit(link)
    assert (parts.scheme, parts.netloc) == ("https", "hub.example.edu")
    assert parts.path == "/prefix/hub/user-redirect/git-pull"
    assert parse_qs(parts.query) == {
        "repo": ["https://git.example.edu/cg/student-edition.git"],
        "branch": ["main"],
        "targetpath": ["student-edition"],
        "urlpath": ["lab/tree/student-edition/00_index.ipynb"],
    }
    chosen = parse_qs(
        urlsplit(
            nbgitpuller_link(
                "http://127.0.0.1:8000",
                "https://git.example.edu/cg/x",
                branch="spring-2027",
                notebook="01_de_casteljau.ipynb",
                folder="graphics/lessons",
            )
        ).query
    )
    assert chosen["targetpath"] == ["graphics/lessons"]
    assert chosen["branch"] == ["spring-2027"]
    assert chosen["urlpath"] == ["lab/tree/graphics/lessons/01_de_casteljau.ipynb"]


@pytest.mark.parametrize(
    "repository",
    [
        "https://github.com/ORG/cg-student",
        "https://github.com/ORG/cg-student.git",  # what a Clone button gives
        "https://github.com/ORG/cg-student/",
    ],
)
def test_the_folder_pulled_into_is_the_one_the_link_opens(repository):
    # nbgitpuller clones into targetpath when the link names it (else into the address's last
    # part, ".git" and all): the link always names it, so the page it opens is in that folder.
    query = parse_qs(urlsplit(nbgitpuller_link("https://h.edu", repository)).query)
    assert query["targetpath"] == ["cg-student"]
    assert query["urlpath"] == ["lab/tree/cg-student/00_index.ipynb"]
    assert lessons_folder(repository) == "cg-student"
    # The hub's start page is the same pull, on the student's own server (hub/ config).
    assert nbgitpuller_link("https://h.edu", repository).endswith(
        "/user-redirect/" + pull_path(repository)
    )


@pytest.mark.parametrize(
    ("arguments", "error", "message"),
    [
        (("hub.example.edu", "https://g.edu/r"), ValueError, "hub must be an http"),
        (("https://h.edu?x=1", "https://g.edu/r"), ValueError, "no query or fragment"),
        (("https://h.edu", "git@g.edu:r.git"), ValueError, "repository must be an http"),
        (("https://h.edu", "https://g.edu/"), ValueError, "repository must end in"),
        (("https://h.edu", "https://g.edu/.git"), ValueError, "repository must end in"),
        (("https://h.edu", "https://g.edu/r", "a b"), ValueError, "branch must be a relative"),
        (("https://h.edu", "https://g.edu/r", "main", "../x"), ValueError, "notebook must be"),
        (("https://h.edu", "https://g.edu/r", "main", "a", "/abs"), ValueError, "folder must be"),
        ((None, "https://g.edu/r"), TypeError, "hub must be an http.*got NoneType"),
        (("https://h.edu", "https://g.edu/r", 3), TypeError, "branch must be a string; got int"),
    ],
)
def test_bad_link_arguments_are_named(arguments, error, message):
    with pytest.raises(error, match=message):
        nbgitpuller_link(*arguments)


def test_the_command_prints_the_link_or_says_what_is_wrong(capsys):
    assert main(["link", "--hub", "https://h.edu", "--repo", "https://g.edu/cg/lessons"]) == 0
    assert capsys.readouterr().out.strip() == nbgitpuller_link(
        "https://h.edu", "https://g.edu/cg/lessons"
    )
    assert main(["link", "--hub", "h.edu", "--repo", "https://g.edu/cg/lessons"]) == 2
    assert "python -m course link: hub must be an http(s) address" in capsys.readouterr().err


def git(folder, *arguments):
    subprocess.run(
        ["git", "-c", "user.name=Teacher", "-c", "user.email=t@example.edu", *arguments],
        cwd=folder,
        check=True,
        capture_output=True,
    )


def publish(lessons, edition):
    """The teacher's step: the student edition rewritten from the lessons, committed."""
    write_student_edition(edition, lessons, force=True)
    git(edition, "add", "-A")
    git(edition, "commit", "-q", "-m", "lessons")


def pull(edition, folder):
    from nbgitpuller.pull import GitPuller  # the hub's own merge, as the link runs it

    for _ in GitPuller(str(edition), str(folder), branch="main").pull():
        pass


def cell_sources(path):
    return ["".join(cell["source"]) for cell in json.loads(path.read_text())["cells"]]


def test_pulling_an_updated_lesson_keeps_the_student_s_edited_exercise(tmp_path):
    lessons, edition, student = tmp_path / "lessons", tmp_path / "edition", tmp_path / "student"
    lessons.mkdir()
    for name in ("00_index.ipynb", "01_de_casteljau.ipynb"):
        shutil.copy(NOTEBOOKS / name, lessons / name)
    edition.mkdir()
    git(edition, "init", "-q", "-b", "main")
    publish(lessons, edition)
    pull(edition, student)  # the first click: a clone
    lesson = student / "01_de_casteljau.ipynb"
    notebook = json.loads(lesson.read_text())
    exercise = next(
        cell for cell in notebook["cells"] if "exercise" in cell["metadata"].get("tags", [])
    )
    stubbed = "".join(exercise["source"])
    assert 'raise NotImplementedError("your code here")' in stubbed
    answer = stubbed.replace(
        'raise NotImplementedError("your code here")', "return 'my own answer'  # a student's"
    )
    exercise["source"] = answer.splitlines(keepends=True)
    lesson.write_text(json.dumps(notebook, indent=1, ensure_ascii=False) + "\n")

    # The teacher adds lesson 02 and rewords lesson 01's first cell, far from the exercise.
    shutil.copy(NOTEBOOKS / "02_bernstein.ipynb", lessons / "02_bernstein.ipynb")
    teacher = json.loads((lessons / "01_de_casteljau.ipynb").read_text())
    first = "".join(teacher["cells"][0]["source"]) + "\n\nA sentence the teacher added."
    teacher["cells"][0]["source"] = first.splitlines(keepends=True)
    (lessons / "01_de_casteljau.ipynb").write_text(json.dumps(teacher, indent=1) + "\n")
    publish(lessons, edition)
    pull(edition, student)  # the next click: a merge

    sources = cell_sources(lesson)  # still a notebook: the merge left valid JSON
    assert answer in sources  # the student's work, whole
    assert sources[0].endswith("A sentence the teacher added.")  # and the teacher's change
    assert (student / "02_bernstein.ipynb").is_file()
    assert cell_sources(student / "02_bernstein.ipynb") == cell_sources(
        edition / "02_bernstein.ipynb"
    )
