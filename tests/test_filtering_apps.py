"""Lesson 07's apps: any kernel, and repeated blurs under each border rule, as course.filters
computes them."""

import numpy as np
import pytest
from scipy import ndimage

from course import filters
from course.lessons.l07_filtering.apps import (
    KERNELS,
    KernelApp,
    RepeatedBlurApp,
    format_kernel,
    parse_kernel,
    right_column_mean,
)


def test_repeated_blur_app_applies_each_border_rule_n_times():
    image = np.random.default_rng(0).random((20, 24, 3))
    app = RepeatedBlurApp(image, repeats=0, corner=6)
    before = app.refresh()
    assert np.array_equal(app.wholes["zero"].get_array(), image)
    app.controls["repeats"].value = 3
    assert app.view.image.value != before
    handout = filters.blur(filters.blur(filters.blur(image)))
    assert np.allclose(app.wholes["handout"].get_array(), handout, atol=1e-15)
    zero = image
    for _ in range(3):
        zero = filters.convolve(zero, filters.BOX, "zero")
    assert np.allclose(app.wholes["zero"].get_array(), zero, atol=1e-15)
    assert np.allclose(app.crops["zero"].get_array(), zero[:6, -6:], atol=1e-15)
    # Back to fewer blurs: recomputed from the original.
    app.controls["repeats"].value = 1
    assert np.allclose(
        app.wholes["replicate"].get_array(), filters.convolve(image, filters.BOX, "replicate")
    )
    assert app.describe() == "RepeatedBlurApp(repeats=1)"


def test_repeated_blur_app_measures_the_dark_frame_of_zero_padding():
    app = RepeatedBlurApp(np.full((16, 16), 0.5), repeats=4)
    assert "at 1.00 x" in app.titles["handout"].get_text()
    assert "at 1.00 x" in app.titles["reflect"].get_text()
    ratio = right_column_mean(app.wholes["zero"].get_array()) / 0.5
    assert ratio < 0.8 and f"right column at {ratio:.2f} x" in app.titles["zero"].get_text()


def test_kernel_app_applies_the_lab_dot_product_under_the_chosen_border():
    rng = np.random.default_rng(3)
    image = rng.random((30, 24))
    app = KernelApp(image, window=(5, 20))
    app.refresh()
    np.testing.assert_allclose(app.result, filters.convolve(image, filters.BOX, "replicate"))
    app.controls["border"].value = "handout"
    np.testing.assert_allclose(app.result, filters.blur(image), atol=1e-12)
    app.controls["preset"].value = "Sobel x"
    assert app.value("kernel") == KERNELS["Sobel x"]
    # The lab's dot product: a rising edge gives a positive Gx, not the convolution's negative.
    step = np.zeros((5, 6))
    step[:, 3:] = 1.0
    edge_app = KernelApp(step, kernel="Sobel x", window=(0, 0))
    edge_app.refresh()
    assert edge_app.result[2, 3] == 4.0
    # The zoomed window is the filtered image's 16 x 16 there, clamped into the image.
    np.testing.assert_array_equal(app.panels["corner"].values, app.result[5:21, 8:24])


def test_kernel_app_preset_and_typed_kernel_follow_each_other():
    app = KernelApp(np.full((20, 20), 0.5))
    app.refresh()
    app.controls["preset"].value = "Gaussian"
    assert app.value("kernel") == KERNELS["Gaussian"]
    np.testing.assert_allclose(app.kernel, np.array([[1, 2, 1], [2, 4, 2], [1, 2, 1]]) / 16)
    app.controls["kernel"].value = "0 0 0; 0 2 0; 0 0 0"
    assert app.value("preset") == "typed"
    np.testing.assert_allclose(app.result, 1.0)
    app.controls["preset"].value = "identity"
    np.testing.assert_allclose(app.result, 0.5)


def test_kernel_app_keeps_the_last_kernel_when_the_text_is_wrong_and_says_why():
    app = KernelApp(np.full((20, 20), 0.5))
    app.refresh()
    app.controls["kernel"].value = "1 2; 3 4"
    assert "expected 3 rows of 3 numbers" in app.status.value
    np.testing.assert_allclose(app.kernel, filters.BOX)
    app.controls["kernel"].value = "1/0 0 0; 0 0 0; 0 0 0"
    assert "every entry must be a number" in app.status.value


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("0,5 1; 0 0 0; 0 0 0", "mixes commas and spaces"),  # read as 0 5 1 before
        ("0x10 0 0; 0 0 0; 0 0 0", "got '0x10'"),
        ("1_0 0 0; 0 0 0; 0 0 0", "got '1_0'"),  # read as 10 before
        ("inf 0 0; 0 0 0; 0 0 0", "got 'inf'"),
    ],
)
def test_kernel_text_that_could_be_read_two_ways_is_refused(text, reason):
    with pytest.raises(ValueError, match=reason):
        parse_kernel(text)
    assert parse_kernel("1,2,1; 2, 4, 2\n1 2 1").tolist() == [[1, 2, 1], [2, 4, 2], [1, 2, 1]]
    app = KernelApp(np.full((20, 20), 0.5))
    app.refresh()
    app.controls["kernel"].value = text
    assert reason in app.status.value
    np.testing.assert_allclose(app.kernel, filters.BOX)


def test_kernel_app_shows_signed_results_around_zero_and_warns_on_the_handout_rule():
    app = KernelApp(np.random.default_rng(0).random((20, 20)), kernel="Sobel y")
    app.refresh()
    panel = app.panels["filtered"]
    assert panel.vmin == -panel.vmax and panel.vmax == np.abs(app.result).max()
    app.controls["border"].value = "handout"
    assert "read as zero padding" in app.status.value
    np.testing.assert_allclose(
        app.result, filters.convolve(app.image, filters.SOBEL_Y[::-1, ::-1], "zero")
    )
    # Every pixel of the filtered panel is pasted at the app's whole zoom.
    pasted = app.pixel_images[panel.axes]
    assert pasted.shape == (20 * KernelApp.ZOOM, 20 * KernelApp.ZOOM, 3)


def test_parse_kernel_reads_fractions_commas_and_lines():
    np.testing.assert_allclose(
        parse_kernel("1, 2, 3\n4 5 6; 7 8 -9/2"), [[1, 2, 3], [4, 5, 6], [7, 8, -4.5]]
    )
    with pytest.raises(ValueError, match="kernel: expected 3 rows"):
        parse_kernel("")
    with pytest.raises(ValueError, match="kernel: every entry"):
        parse_kernel("a b c; 1 2 3; 4 5 6")
    assert format_kernel(parse_kernel(KERNELS["sharpen"])) == KERNELS["sharpen"]


def test_kernel_app_rejects_a_colour_image_by_name():
    with pytest.raises(ValueError, match="image: expected a gray"):
        KernelApp(np.zeros((10, 10, 3)))


def test_the_blur_app_titles_give_the_dark_frame_depth_as_lesson_07_measures_it():
    # Lesson 07: the columns in from the right edge below 95% of the same column under
    # 'replicate'. A flat image stays flat under 'replicate'; scipy's "constant" mode is
    # zero padding.
    flat = np.full((24, 24), 0.5)
    app = RepeatedBlurApp(flat, repeats=0, corner=8)
    for repeats in (0, 5, 10):
        app.controls["repeats"].value = repeats
        zero = flat.copy()
        for _ in range(repeats):
            zero = ndimage.uniform_filter(zero, 3, mode="constant")
        dark = zero.mean(axis=0)[::-1] < 0.95 * 0.5
        depth = len(dark) if dark.all() else int(np.argmin(dark))
        assert app.titles["zero"].get_text().endswith(f"\ndark frame: {depth} px deep")
        assert app.titles["reflect"].get_text().endswith("\ndark frame: 0 px deep")
        assert app.titles["replicate"].get_text().endswith("\nthe frames' reference")
    assert depth >= 2  # 10 blurs darken more than the outermost column


def test_the_border_caption_and_the_app_titles_measure_the_same_rightmost_column():
    from course import images
    from course.lessons.l07_filtering import figures
    from course.lessons.l07_filtering.apps import blurred

    face = images.face()
    results = dict.fromkeys(filters.BORDERS, face)
    for _blur in range(20):
        results = {border: blurred(result, border) for border, result in results.items()}
    caption = figures.border_figure(passes=20).caption
    app = RepeatedBlurApp(face, repeats=20)
    assert "the face's right column" in caption
    for border, result in results.items():
        ratio = result[:, -1].mean() / face[:, -1].mean()  # the column the figure plots at 0 px
        assert f"{ratio:.2f} ({border})" in caption
        assert f"right column at {ratio:.2f} x the original" in app.titles[border].get_text()


def test_the_presets_weights_are_printed_as_the_app_reads_them(capsys):
    from course.lessons.l07_filtering import lesson

    lesson.print_kernel_presets()
    header, *rows = capsys.readouterr().out.splitlines()
    assert header.split("   ")[0].strip() == "box" and "Gaussian" in header and "sharpen" in header
    starts = [header.index(name) for name in KERNELS]
    for name, start, end in zip(KERNELS, starts, [*starts[1:], None], strict=True):
        printed = "; ".join(" ".join(row[start:end].split()) for row in rows)
        np.testing.assert_array_equal(parse_kernel(printed), parse_kernel(KERNELS[name]))
