"""course.widgets.base: a slider change redraws the picture; the text repr is stable."""

import base64

import ipywidgets as widgets
import numpy as np

from course.widgets.base import SliderApp


class LineApp(SliderApp):
    """A minimal app: a horizontal line at height y."""

    def __init__(self) -> None:
        super().__init__({"y": widgets.FloatSlider(value=0.5, min=0, max=1)}, shape=(100, 200))
        axes = self.figure.add_axes((0, 0, 1, 1))
        axes.set_xlim(0, 1)
        axes.set_ylim(0, 1)
        axes.set_axis_off()
        (self.line,) = axes.plot([0, 1], [0.5, 0.5], color="black", linewidth=4)

    def update(self) -> None:
        y = self.value("y")
        self.line.set_ydata([y, y])


def dark_rows(app: LineApp) -> np.ndarray:
    rgba = app.view.pixels()
    return np.flatnonzero((rgba[..., :3] < 100).all(axis=2).any(axis=1))


def test_moving_a_slider_redraws_the_picture_where_the_value_says():
    app = LineApp()
    app.refresh()
    before = app.view.image.value
    rows = dark_rows(app)
    assert abs(rows.mean() - 50) < 2
    app.controls["y"].value = 0.9
    assert app.renders == 2
    assert app.view.image.value != before
    assert abs(dark_rows(app).mean() - 10) < 2


def test_repr_is_stable_text_plus_a_still_picture():
    app = LineApp()
    bundle = app._repr_mimebundle_()
    assert bundle["text/plain"] == "LineApp(y=0.5)"
    assert base64.b64decode(bundle["image/png"]).startswith(b"\x89PNG")
    assert "application/vnd.jupyter.widget-view+json" in bundle
