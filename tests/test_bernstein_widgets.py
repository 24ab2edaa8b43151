"""Lesson 02's app: the basis and its values at t are what course.bezier computes."""

import io

import numpy as np
from PIL import Image

from course.bezier import bernstein_basis
from course.widgets.bernstein import BernsteinBasisApp


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
