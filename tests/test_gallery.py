"""course.gallery and ``python -m course gallery``: pictures written, none clobbered unasked."""

import io

import numpy as np
import pytest
from PIL import Image

from course.__main__ import main
from course.gallery import ProgressBar, gallery_pictures, write_gallery
from course.lessons import LESSONS, Picture, notebooks


def tiny_png(value: int) -> bytes:
    buffer = io.BytesIO()
    Image.fromarray(np.full((2, 3), value, dtype=np.uint8)).save(buffer, format="png")
    return buffer.getvalue()


TINY = [Picture("a", "dark", lambda: tiny_png(0)), Picture("b", "light", lambda: tiny_png(255))]


def test_writes_every_registered_picture_of_the_lessons_present(tmp_path):
    stream = io.StringIO()
    out = tmp_path / "new" / "gallery"
    written = write_gallery(out, stream=stream)
    expected = [picture.name + ".png" for book in notebooks() for picture in book.pictures]
    assert [path.name for path in written] == expected
    assert sorted(path.name for path in out.iterdir()) == sorted(expected)
    assert len(expected) >= len(LESSONS)
    # The progress bar ends full, with the last file, and a newline.
    assert stream.getvalue().endswith(f"{len(expected)}/{len(expected)} {expected[-1]}\n")
    # Lesson 01's picture at t = 0.25 shows B(0.25) where de_casteljau puts it.
    app = LESSONS["01"].slider.build()
    app.controls["t"].value = 0.25
    (landmark,) = LESSONS["01"].slider.landmarks(app)
    image = np.asarray(Image.open(out / "01_de_casteljau_degree3_t0.25.png").convert("RGB"))
    assert np.abs(image[landmark.row, landmark.column] - np.array(landmark.color)).max() <= 40


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
    bar = ProgressBar(2, stream, width=4)
    bar.advance("a-long-name.png")
    bar.advance("b.png")
    bar.close()
    first, second = stream.getvalue().split("\r")[1:]
    assert first == "[##--] 1/2 a-long-name.png"
    assert second == "[####] 2/2 b.png".ljust(len(first)) + "\n"


def test_command_line_refuses_then_forces(tmp_path, capsys):
    (tmp_path / "keep.txt").write_text("x")
    assert main(["gallery", "--out", str(tmp_path)]) == 2
    assert "is not empty" in capsys.readouterr().err
    assert main(["gallery", "--out", str(tmp_path), "--force"]) == 0
    names = {path.name for path in tmp_path.iterdir()}
    assert names == {"keep.txt"} | {picture.name + ".png" for picture in gallery_pictures()}
