"""course.classroom.gallery and ``python -m course gallery``: pictures written, none clobbered."""

import io

import numpy as np
import pytest
from PIL import Image

from course.classroom.cli import main
from course.classroom.gallery import ProgressBar, gallery_pictures, write_gallery
from course.classroom.notebooks import notebooks
from course.classroom.registry import Picture, lessons

LESSONS = lessons()


def tiny_png(value: int) -> bytes:
    buffer = io.BytesIO()
    Image.fromarray(np.full((2, 3), value, dtype=np.uint8)).save(buffer, format="png")
    return buffer.getvalue()


TINY = [Picture("a", "dark", lambda: tiny_png(0)), Picture("b", "light", lambda: tiny_png(255))]


def test_writes_every_registered_picture_of_the_lessons_present(tmp_path):
    stream = io.StringIO()
    out = tmp_path / "new" / "gallery"
    written = write_gallery(out, stream=stream)
    expected = [
        f"{picture.name}.png" for book in notebooks() for picture in LESSONS[book.number].pictures
    ]
    assert [path.name for path in written] == expected
    assert sorted(path.name for path in out.iterdir()) == sorted(expected)
    assert len(expected) >= len(LESSONS)
    # The progress bar ends full, with the last file, and a newline.
    # (padded with spaces over a longer previous label).
    last = stream.getvalue().split("\r")[-1]
    assert last.endswith("\n") and last.rstrip().endswith(
        f"{len(expected)}/{len(expected)} {expected[-1]}"
    )
    # Lesson 01's picture at t = 0.25 shows B(0.25) where de_casteljau puts it.
    (spec,) = LESSONS["01"].sliders
    app = spec.build()
    app.controls["t"].value = 0.25
    assert_landmarks(out / "01_de_casteljau_degree3_t0.25.png", spec.landmarks(app))
    # The slider apps' pictures show what the library computes, landmark by landmark.
    for number, name in (
        ("03", "03_triangles_top_left"),
        ("05", "05_seed000_three_splats_position0.10"),
        ("06", "06_gray_level_0.30"),
        ("08", "08_jacobi_1000_sweeps"),
    ):
        (spec,) = LESSONS[number].sliders
        app = spec.build()
        app.refresh()
        assert_landmarks(out / f"{name}.png", spec.landmarks(app))
    # A dragging app's picture, as the gallery draws it before any drag.
    spec = LESSONS["08"].drags[0]
    app = spec.build()
    app.refresh()
    assert_landmarks(out / "08_drag_the_plane.png", spec.landmarks(app))
    # A still is its figure's own size: six columns of 144-pixel windows and their gaps.
    assert Image.open(out / "06_dithering_table.png").size[0] == 14 + 6 * (144 + 14)


def assert_landmarks(path, landmarks):
    image = np.asarray(Image.open(path).convert("RGB")).astype(int)
    assert landmarks
    for mark in landmarks:
        shown = image[mark.row, mark.column]
        assert np.abs(shown - np.array(mark.color)).max() <= mark.tolerance, (path.name, mark)


def test_refuses_a_non_empty_folder_and_writes_nothing(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(FileExistsError, match=r"not empty.*--force"):
        write_gallery(tmp_path, pictures=TINY, stream=io.StringIO())
    assert [path.name for path in tmp_path.iterdir()] == ["notes.txt"]
    (tmp_path / "file").write_text("")
    with pytest.raises(NotADirectoryError, match="expected a folder"):
        write_gallery(tmp_path / "file", pictures=TINY, stream=io.StringIO())


def test_force_adds_and_replaces_its_own_files_and_deletes_nothing(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    (tmp_path / "a.png").write_bytes(b"old")
    write_gallery(tmp_path, force=True, pictures=TINY, stream=io.StringIO())
    assert sorted(path.name for path in tmp_path.iterdir()) == ["a.png", "b.png", "notes.txt"]
    assert (tmp_path / "notes.txt").read_text() == "mine"
    assert np.asarray(Image.open(tmp_path / "a.png")).max() == 0
    assert np.asarray(Image.open(tmp_path / "b.png")).min() == 255


def test_duplicate_names_are_refused_before_writing(tmp_path):
    with pytest.raises(ValueError, match="distinct names"):
        write_gallery(tmp_path / "g", pictures=[TINY[0], TINY[0]], stream=io.StringIO())
    assert not (tmp_path / "g").exists()


def test_progress_bar_redraws_one_line_over_a_longer_label():
    stream = io.StringIO()
    bar = ProgressBar(2, stream, length=4)
    bar.advance("a-long-name.png")
    bar.advance("b.png")
    bar.close()
    first, second = stream.getvalue().split("\r")[1:]
    assert first == "[##--] 1/2 a-long-name.png"
    assert second == "[####] 2/2 b.png".ljust(len(first)) + "\n"


def test_command_line_refuses_then_forces(tmp_path, capsys, monkeypatch):
    # The command's own work, on two tiny pictures (the test above renders the real ones).
    monkeypatch.setattr("course.classroom.gallery.gallery_pictures", lambda folder: TINY)
    (tmp_path / "keep.txt").write_text("x")
    assert main(["gallery", "--out", str(tmp_path)]) == 2
    assert "is not empty" in capsys.readouterr().err
    assert main(["gallery", "--out", str(tmp_path), "--force"]) == 0
    assert "wrote 2 files" in capsys.readouterr().err
    assert {path.name for path in tmp_path.iterdir()} == {"keep.txt", "a.png", "b.png"}


def test_every_registered_picture_is_a_png_named_for_its_lesson():
    pictures = gallery_pictures()
    assert len(pictures) >= 2 * len(LESSONS)
    assert all(
        picture.caption and picture.name[:3] in {f"{n}_" for n in LESSONS} for picture in pictures
    )


def test_only_renders_the_named_pictures_and_names_an_unknown_one(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr("course.classroom.gallery.gallery_pictures", lambda folder: TINY)
    assert main(["gallery", "--out", str(tmp_path), "--only", "b"]) == 0
    assert [path.name for path in tmp_path.iterdir()] == ["b.png"]
    assert main(["gallery", "--out", str(tmp_path / "x"), "--only", "c"]) == 2
    assert "no picture named 'c'; the pictures are: a, b" in capsys.readouterr().err
    assert not (tmp_path / "x").exists()


def test_force_writes_nothing_through_a_picture_named_link_that_leads_out(tmp_path, capsys):
    outside = tmp_path / "outside.png"
    outside.write_bytes(b"mine")
    out = tmp_path / "gallery"
    out.mkdir()
    (out / "b.png").symlink_to(outside)
    with pytest.raises(ValueError, match=r"b\.png leads outside .*gallery, to .*outside\.png"):
        write_gallery(out, force=True, pictures=TINY, stream=io.StringIO())
    assert outside.read_bytes() == b"mine" and [p.name for p in out.iterdir()] == ["b.png"]
    # Inside the folder, a link of a picture's name is replaced by the picture, not written
    # through: the file it led to is left as it was.
    (out / "b.png").unlink()
    (out / "mine.png").write_bytes(b"mine too")
    (out / "b.png").symlink_to("mine.png")
    write_gallery(out, force=True, pictures=TINY, stream=io.StringIO())
    assert not (out / "b.png").is_symlink() and (out / "mine.png").read_bytes() == b"mine too"
    assert np.asarray(Image.open(out / "b.png")).min() == 255
    assert sorted(p.name for p in out.iterdir()) == ["a.png", "b.png", "mine.png"]


def test_the_command_line_names_the_link_in_one_line(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr("course.classroom.gallery.gallery_pictures", lambda folder: TINY)
    (tmp_path / "outside").mkdir()
    out = tmp_path / "gallery"
    out.mkdir()
    (out / "a.png").symlink_to(tmp_path / "outside" / "a.png")  # a link to nothing yet
    assert main(["gallery", "--out", str(out), "--force"]) == 2
    error = capsys.readouterr().err
    assert len(error.strip().splitlines()) == 1 and "a.png leads outside" in error
    assert list((tmp_path / "outside").iterdir()) == []
