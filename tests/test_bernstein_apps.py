"""Lesson 02's app: the basis and its values at t are what course.curves.bezier computes."""

import io

import numpy as np
from PIL import Image

from course.curves.bezier import bernstein_basis
from course.lessons.l02_bernstein.apps import BernsteinBasisApp


def picture(app):
    return np.asarray(Image.open(io.BytesIO(app.view.image.value)).convert("RGB")).astype(int)


def test_bernstein_app_draws_the_basis_and_its_values_at_t():
    app = BernsteinBasisApp(degree=3, t=0.3)
    app.refresh()
    before = app.view.image.value
    app.controls["degree"].value = 6
    assert app.view.image.value != before
    samples = app.basis_lines[0].get_xdata()
    expected = bernstein_basis(6, samples)
    for i in range(7):
        np.testing.assert_allclose(app.basis_lines[i].get_ydata(), expected[:, i])
    assert all(len(line.get_xdata()) == 0 for line in app.basis_lines[7:])
    np.testing.assert_allclose(app.sum_line.get_ydata(), 1.0, rtol=1e-14)
    app.controls["t"].value = 0.75
    np.testing.assert_allclose(app.markers.get_ydata(), bernstein_basis(6, 0.75)[0])
    heights = [bar.get_height() for bar in app.bars]
    np.testing.assert_allclose(heights[:7], bernstein_basis(6, 0.75)[0])
    assert heights[7:] == [0.0] * (len(heights) - 7)
    assert "weights sum to 1.000000000000" in app.title.get_text()


def test_every_basis_curve_is_named_in_its_colour_at_its_peak_and_every_bar_is_ticked():
    app = BernsteinBasisApp(degree=3, t=0.3)
    app.refresh()
    named = [label for label in app.curve_labels if label.get_text()]
    assert [label.get_text() for label in named] == [f"$B_{{{i},3}}$" for i in range(4)]
    for i, label in enumerate(named):
        x, y = label.get_position()
        assert 0 < x < 1
        peak = bernstein_basis(3, i / 3)[0, i]
        assert abs(y - (peak + 0.01)) < 1e-12
        assert np.allclose(label.get_color(), app.basis_lines[i].get_color())
    assert list(app.bars_axes.get_xticks()) == [0, 1, 2, 3]
    legend = [text.get_text() for text in app.axes.get_legend().get_texts()]
    assert legend == ["sum of the weights", "the weights at t"]
    # At degree 20 the ends and every fifth curve are named, and the bars ticked every fifth.
    app.controls["degree"].value = 20
    app.refresh()
    named = [label.get_text() for label in app.curve_labels if label.get_text()]
    assert named == [f"$B_{{{i},20}}$" for i in (0, 5, 10, 15, 20)]
    assert list(app.bars_axes.get_xticks()) == [0, 5, 10, 15, 20]
