"""Lesson 08's figures: the stored record of the lab's sweeps is what the solvers compute."""

import itertools
import json
import os
from functools import partial
from pathlib import Path

import numpy as np
import pytest
from chinese import check_chinese_figure
from drawn_figures import figures_drawn

from course import images, poisson
from course.i18n import language
from course.lessons.l08_poisson import convergence, figures

# How far two machines may differ on the lab's record, in intensity units (the image is in
# [0, 1]). Jacobi's iterate carries the rounding of every sweep, damped by rho per sweep:
# at most about eps * max|u| / (1 - rho) = 2.2e-16 * 2 / 2.4e-4 = 2e-12 (rho = 0.99976).
# The exact solution the errors are measured against is off by at most about
# cond(A) * eps * max|u| = 8.5e3 * 2.2e-16 * 2 = 4e-12 for the five-point Laplacian on the
# 109 x 278 unknowns. So 1e-11 covers any CPU, BLAS and thread count (the stored record
# and a fresh run on another machine differ by 2e-15), and is 300 times below the smallest value
# stored (SOR's last error, 2.96e-9): a change in a solver shows. Relative tolerances alone
# fail there: the residuals near 1e-10 differ by 3e-6 of themselves from one CPU to the next.
ATOL = 1e-11


def test_the_stored_lab_sweeps_are_what_the_solvers_compute_now():
    stored, fresh = convergence.lab_sweeps(), convergence.compute_lab_sweeps()
    assert stored["region"] == fresh["region"] == [111, 280]
    for method in ("jacobi", "gauss_seidel", "sor"):
        assert stored[method]["sweeps"] == fresh[method]["sweeps"]
        for key in ("residuals", "errors"):
            np.testing.assert_allclose(
                stored[method][key], fresh[method][key], rtol=1e-9, atol=ATOL
            )
    lab, now = stored["lab_result"], fresh["lab_result"]
    # A mean of errors in grey levels: ATOL * 255 at most.
    assert lab["mean_error"] == pytest.approx(now["mean_error"], rel=1e-9, abs=255 * ATOL)
    # A share of pixels: one whose error lies within rounding of one grey level could
    # count on either side, so allow one pixel of the region (109 x 278 unknowns).
    one_pixel = 1 / (109 * 278)
    assert lab["share_above_one_grey_level"] == pytest.approx(
        now["share_above_one_grey_level"], abs=one_pixel
    )


def test_the_stored_record_shows_what_the_lesson_says():
    record = convergence.lab_sweeps()
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
        convergence.write_lab_sweeps(path)


def test_write_lab_sweeps_refuses_a_folder(tmp_path):
    with pytest.raises(ValueError, match="is a folder"):
        convergence.write_lab_sweeps(str(tmp_path))


@pytest.fixture
def solves(monkeypatch):
    """The record's seconds of solving, replaced by a count of the calls that got that far."""
    calls = []
    monkeypatch.setattr(convergence, "compute_lab_sweeps", lambda: calls.append(1) or {"a": 1})
    return calls


@pytest.mark.parametrize("kind", [str, Path])
def test_write_lab_sweeps_refuses_every_bad_path_before_solving(tmp_path, solves, kind):
    (tmp_path / "notes.txt").write_text("mine")
    for path, said in [
        (tmp_path / "notes.txt" / "sweeps.json", r"notes\.txt, a parent of .*, is a file"),
        (tmp_path / "notes.txt" / "deeper" / "sweeps.json", "is a file, not a folder"),
        (tmp_path, "is a folder"),
        (f"{tmp_path}/sweeps\0.json", "without NUL"),
        (tmp_path / ("s" * 300 + ".json"), "of at most 255 bytes"),
        (f"{tmp_path}/new/..", "not '..'"),
    ]:
        with pytest.raises(ValueError, match=f"^path.*{said}"):
            convergence.write_lab_sweeps(kind(path))
    assert solves == [] and (tmp_path / "notes.txt").read_text() == "mine"
    assert [p.name for p in tmp_path.iterdir()] == ["notes.txt"]


def test_write_lab_sweeps_says_a_folder_it_cannot_write_before_solving(
    tmp_path, solves, monkeypatch
):
    """As root every folder can be written: the refusal the file system gives is simulated."""
    real_open = os.open

    def refusing_open(path, *args, **kwargs):
        if str(path).endswith(".writing"):
            raise PermissionError(13, "Permission denied", str(path))
        return real_open(path, *args, **kwargs)

    monkeypatch.setattr(os, "open", refusing_open)
    with pytest.raises(ValueError, match=r"path: cannot write into .* \(Permission denied\)"):
        convergence.write_lab_sweeps(str(tmp_path / "sweeps.json"))
    assert solves == []


@pytest.mark.parametrize("kind", [str, Path])
def test_write_lab_sweeps_takes_a_str_as_a_path_and_replaces_the_file_whole(tmp_path, solves, kind):
    path = tmp_path / "new" / "sweeps.json"
    convergence.write_lab_sweeps(kind(path))
    convergence.write_lab_sweeps(kind(path))  # again: replaced
    assert json.loads(path.read_text()) == {"a": 1} and solves == [1, 1]
    assert [p.name for p in path.parent.iterdir()] == ["sweeps.json"]  # no temporary left


def test_the_tiny_clone_in_chinese_has_chinese_words_and_every_glyph(monkeypatch, caplog):
    check_chinese_figure(figures.tiny_clone_figure, (None, None, 10), monkeypatch, caplog)


def test_a_printed_line_follows_the_language():
    with language("zh-CN"):
        chinese = convergence.strip_and_square()
    assert chinese == (
        "3 × 3 正方形：0.7071；3 × 30 长条：0.8510；3 × 300 长条：0.8535；3 × ∞：0.8536"
    )


def test_the_tiny_clone_draws_g_on_a_scale_centred_on_0_that_tells_every_value_apart(monkeypatch):
    # Issue 21: drawn as 0.5 + g, every g below -0.5 clipped to black. On the ring
    # g = b - f = sky - 0.9, so its columns run 0.2 - 0.9 = -0.7 up to 0.6 - 0.9 = -0.3.
    with figures_drawn(monkeypatch) as drawn:
        figures.tiny_clone_figure(zoom=10)
    (figure,) = drawn
    (g_image,) = [
        image for axes in figure.axes for image in axes.images if image.cmap.name == "PRGn"
    ]
    g = np.asarray(g_image.get_array())
    np.testing.assert_allclose(g[0], [-0.7, -0.6, -0.5, -0.4, -0.3], atol=1e-9)
    norm = g_image.norm
    assert norm.vmin == -norm.vmax and norm.vmax >= np.abs(g).max()
    colours = {tuple(g_image.to_rgba(value)) for value in g[0]}
    assert len(colours) == 5  # five columns, five colours: none clipped together
    assert any(axes.get_ylabel() == "g" for axes in figure.axes)  # the colour bar


def test_the_lab_s_8000_sweeps_are_called_the_lab_skeleton_s(monkeypatch):
    with figures_drawn(monkeypatch) as drawn:
        still = convergence.convergence_figure()
    assert "after the lab skeleton's 8000 sweeps" in still.caption
    texts = [text.get_text() for text in drawn[0].axes[0].texts]
    assert "the lab skeleton's 8000" in texts


def _boundary(background, foreground, offset):
    return poisson.correction_boundary(background, foreground, offset)


def _jacobi(g, tolerance, in_place=False):
    """A student's sweep, pixel by pixel: Jacobi reads last sweep's values, Gauss-Seidel its own."""
    g = np.array(g, dtype=float)
    height, width = g.shape
    inside = [(y, x) for y in range(1, height - 1) for x in range(1, width - 1)]
    for sweeps in itertools.count():
        source = g if in_place else g.copy()
        worst = 0.0
        for y, x in inside:
            mean = (source[y - 1, x] + source[y + 1, x] + source[y, x - 1] + source[y, x + 1]) / 4
            worst = max(worst, abs(4 * mean - 4 * source[y, x]))
            if not in_place:
                g[y, x] = mean
        if worst < tolerance:
            return source if not in_place else g, sweeps
        if in_place:
            for y, x in inside:
                g[y, x] = (g[y - 1, x] + g[y + 1, x] + g[y, x - 1] + g[y, x + 1]) / 4


def test_the_tiny_clone_draws_the_student_s_functions_only_when_they_do_what_the_checks_ask():
    ok = str(figures.tiny_clone_figure(_boundary, _jacobi, zoom=10))
    assert ok.startswith("your boundary_ring and jacobi_solve: 28 sweeps")
    gauss_seidel = partial(_jacobi, in_place=True)
    ring = poisson.correction_boundary(
        figures.TINY_BACKGROUND, figures.TINY_FOREGROUND, figures.TINY_OFFSET
    )
    assert gauss_seidel(ring, 1e-6)[1] < 28
    for boundary, jacobi in ((_boundary, gauss_seidel), (None, None), (_boundary, None)):
        shown = str(figures.tiny_clone_figure(boundary, jacobi, zoom=10))
        assert shown.startswith("the library's (yours do not pass their checks yet): 28 sweeps")


def test_the_tiny_clone_states_the_tolerance_its_count_of_sweeps_stops_below():
    shown = str(figures.tiny_clone_figure(zoom=10))
    ring = poisson.correction_boundary(
        figures.TINY_BACKGROUND, figures.TINY_FOREGROUND, figures.TINY_OFFSET
    )
    assert figures.TINY_TOLERANCE == 1e-6
    sweeps = _jacobi(ring, figures.TINY_TOLERANCE)[1]
    assert f": {sweeps} sweeps to a residual below 1e-6;" in shown
    assert sweeps == 28 and _jacobi(ring, 1e-4)[1] != sweeps  # the tolerance decides the count
