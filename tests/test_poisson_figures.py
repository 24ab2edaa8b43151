"""Lesson 08's figures: the stored record of the lab's sweeps is what the solvers compute."""

import numpy as np
import pytest

from course import images, poisson
from course.widgets import poisson_figures as figures


def test_the_stored_lab_sweeps_are_what_the_solvers_compute_now():
    stored, fresh = figures.lab_sweeps(), figures.compute_lab_sweeps()
    assert stored["region"] == fresh["region"] == [111, 280]
    for method in ("jacobi", "gauss_seidel", "sor"):
        assert stored[method]["sweeps"] == fresh[method]["sweeps"]
        for key in ("residuals", "errors"):
            np.testing.assert_allclose(stored[method][key], fresh[method][key], rtol=1e-9)
    for key, value in fresh["lab_result"].items():
        assert stored["lab_result"][key] == pytest.approx(value, rel=1e-9)


def test_the_stored_record_shows_what_the_lesson_says():
    record = figures.lab_sweeps()
    final = {method: record[method]["errors"][-1] * 255 for method in ("jacobi", "gauss_seidel")}
    # Gauss-Seidel (the lab's in-place loop) is ahead of Jacobi, and neither is within a grey level.
    assert 1 < final["gauss_seidel"] < final["jacobi"]
    assert record["sor"]["errors"][-1] * 255 < 1e-3


def test_the_headline_clone_hides_the_seam_the_paste_shows():
    lake, plane = figures.day_scene()
    problem = poisson.clone_problem(lake, plane, figures.DAY_OFFSET)
    pasted = problem.seam(poisson.naive_paste(lake, plane, figures.DAY_OFFSET))
    cloned = problem.seam(poisson.seamless_clone(lake, plane, figures.DAY_OFFSET))
    # The clone's step across the border is below the sky's own texture; the paste's is 15x it.
    assert cloned < problem.seam(lake) < pasted / 15


def test_the_day_plane_is_blue_and_an_unknown_sky_is_refused_by_name():
    day = images.plane(sky="day")
    assert day.shape == (111, 280, 3)
    assert (day[2:8, 2:8, 2] > day[2:8, 2:8, 0]).all()
    with pytest.raises(ValueError, match="sky"):
        images.plane(sky="night")


@pytest.mark.parametrize("path", [3, None, b"x.json"])
def test_write_lab_sweeps_checks_its_path_before_solving(path):
    with pytest.raises(TypeError, match="path must be a file path"):
        figures.write_lab_sweeps(path)


def test_write_lab_sweeps_refuses_a_folder(tmp_path):
    with pytest.raises(ValueError, match="is a folder"):
        figures.write_lab_sweeps(str(tmp_path))
