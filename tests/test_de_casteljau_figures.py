"""Lesson 01's still pictures: the numbers their captions print, checked independently."""

import re

import numpy as np
from drawn_figures import figures_drawn

from course.curves.handout_loops import HANDOUT_LOOPS, yellow_check
from course.i18n import language
from course.images import SEED_000_CUBIC
from course.lessons.l01_de_casteljau import figures, pixel_views


def last_t(step, dtype):
    """The last t a C++ ``for (t = 0; t <= 1; t += step)`` loop of ``dtype`` takes."""
    t, step, last = dtype(0), dtype(step), None
    while t <= dtype(1):
        last, t = t, dtype(t + step)
    return float(last)


def test_the_end_of_curve_caption_gives_each_loop_s_last_t_and_whether_b1_s_pixel_is_painted():
    caption = figures.end_of_curve_figure(SEED_000_CUBIC).caption
    assert "B(1) = (690, 690) in pixel (690, 690)" in caption
    games101, vs2022 = re.findall(r"last t ([\d.]+)", caption)
    assert float(games101) == float(f"{last_t(0.001, np.float32):.7g}")
    assert float(vs2022) == float(f"{last_t(0.001, np.float64):.7g}") == 0.999
    # Rounding the float loop's last point reaches B(1)'s pixel; truncating 0.999's does not.
    assert "the GAMES101 report paints it" in caption and "the VS2022 report does not" in caption


def test_the_yellow_check_caption_counts_the_pixels_each_curve_paints_alone():
    for seed in ("000", "002"):
        check = yellow_check(SEED_000_CUBIC, HANDOUT_LOOPS[seed])
        red = check.image[..., 0] > 0
        green = check.image[..., 1] > 0
        caption = figures.yellow_check_figure(SEED_000_CUBIC, seed).caption
        assert (
            f"{np.count_nonzero(red & green) / np.count_nonzero(red | green):.1%} yellow" in caption
        )
        assert f"{np.count_nonzero(red & ~green)} pixels only red" in caption
        assert f"{np.count_nonzero(green & ~red)} only green" in caption


def test_the_captions_name_the_handouts_by_their_chinese_roles_in_chinese():
    # Issue 36: the loops' role names and the "; " joiner were English in the Chinese captions.
    with language("zh-CN"):
        end = figures.end_of_curve_figure(SEED_000_CUBIC).caption
        report = figures.yellow_check_figure(SEED_000_CUBIC, "002").caption
        assert HANDOUT_LOOPS["003"].label == "VS2022 作业报告"
    assert "GAMES101 作业报告" in end and "VS2022 作业报告" in end
    assert "; " not in end and "report" not in end, end
    assert report.startswith("任意阶作业报告"), report
    assert HANDOUT_LOOPS["003"].label == "the VS2022 report"


def test_the_yellow_check_overview_shows_both_yellow_and_not_yellow_stretches(monkeypatch):
    # Issue 21: with 831 of 1375 pixels odd, marking each odd pixel drew one solid band.
    check = yellow_check(np.asarray(SEED_000_CUBIC, float), HANDOUT_LOOPS["000"])
    painted = np.count_nonzero(check.image.sum(axis=2) > 0)
    odd = len(check.red_only) + len(check.green_only)
    with figures_drawn(monkeypatch) as drawn:
        figures.yellow_check_figure(SEED_000_CUBIC, "000")
    (overview,) = [axes for axes in drawn[0].axes if "not yellow" in axes.get_title()]
    assert overview.get_title() == f"{odd} of {painted} pixels not yellow"
    (pieces,) = [c for c in overview.collections if c.get_array() is not None]
    shares = np.asarray(pieces.get_array())
    assert shares.min() < 0.25 and shares.max() > 0.75  # some stretches odd, some yellow


def test_the_share_along_the_curve_is_each_stretch_s_own():
    curve = np.column_stack([np.linspace(0, 400, 401), np.full(401, 5.0)])
    yellow = np.array([[x, 5] for x in range(0, 200)])
    odd = np.array([[x, 5] for x in range(200, 400)])
    shares = pixel_views.yellow_along(curve, yellow, odd)
    assert shares.shape == (50,)
    assert (shares[:24] == 1).all() and (shares[26:] == 0).all()


def test_b1_s_dashed_outline_is_drawn_over_its_pixel_and_the_cross(monkeypatch):
    with figures_drawn(monkeypatch) as drawn:
        figures.end_of_curve_figure(SEED_000_CUBIC)
    (figure,) = drawn
    assert figure.bbox.width >= 2 * 10 * 28  # two 10-pixel windows, 28 screen px a pixel
    panels = [axes for axes in figure.axes if axes.images]
    assert len(panels) == 2
    for axes in panels:
        outline = [p for p in axes.patches if tuple(p.get_xy()) == (690, 690)]
        assert any(p.get_linestyle() != "-" for p in outline)  # the dashes
        (cross,) = [line for line in axes.lines if line.get_marker() == "x"]
        np.testing.assert_allclose(np.ravel(cross.get_xydata()), [690, 690])
        below = [*axes.images, *axes.collections, cross]  # the pixels, the grid, B(1)
        assert min(p.get_zorder() for p in outline) > max(a.get_zorder() for a in below)
