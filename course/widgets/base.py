"""What every slider app shares: a matplotlib figure shown as an image widget.

The picture is an ``ipywidgets.Image`` holding a PNG that a matplotlib
``Figure`` renders on the Agg canvas. An app builds its figure and artists
once; a slider change calls ``update``, which only changes artist data, and
then the figure is rendered again. No pyplot, no figure rebuilt per step, no
frontend backend: it passes nbval, runs in JupyterLab and Voila, and the
update can be driven from plain Python in a test by setting slider values.
"""

from __future__ import annotations

import base64
import io
from typing import Any

import ipywidgets as widgets
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from PIL import Image as PILImage

__all__ = ["GRAY_PIXELS", "FigureView", "SliderApp", "bare_axes"]

#: imshow settings for a gray image in [0, 1], pixels drawn as flat squares.
GRAY_PIXELS = {"cmap": "gray", "vmin": 0.0, "vmax": 1.0, "interpolation": "nearest"}


def bare_axes(axes: Any) -> Any:
    """The axes without ticks, for a picture: returned, so it can wrap ``add_subplot``."""
    axes.set_xticks([])
    axes.set_yticks([])
    return axes


class FigureView:
    """A matplotlib ``Figure`` of ``shape = (H, W)`` pixels, rendered into an image widget."""

    def __init__(self, shape: tuple[int, int] = (500, 500), dpi: int = 100) -> None:
        rows, columns = shape
        self.figure = Figure(figsize=(columns / dpi, rows / dpi), dpi=dpi)
        self.canvas = FigureCanvasAgg(self.figure)
        self.image = widgets.Image(format="png", width=columns, height=rows)
        self._background = None

    def pixels(self) -> np.ndarray:
        """Draw the figure and return its RGBA pixels, (height, width, 4) uint8."""
        self.canvas.draw()
        return np.asarray(self.canvas.buffer_rgba()).copy()

    def render(self) -> bytes:
        """Draw the whole figure into the image widget and return the PNG bytes."""
        self.canvas.draw()
        return self.publish()

    def render_moving(self, artists: list) -> bytes:
        """Redraw only ``artists`` (made ``set_animated(True)``) over a cached background.

        Blitting: the first call draws everything else once and keeps it;
        later calls restore it and draw just the moving artists. Call
        :meth:`invalidate` when something in the background changes.
        """
        if self._background is None:
            self.canvas.draw()  # skips animated artists
            self._background = self.canvas.copy_from_bbox(self.figure.bbox)
        else:
            self.canvas.restore_region(self._background)
        for artist in artists:
            self.figure.draw_artist(artist)
        return self.publish()

    def invalidate(self) -> None:
        """Forget the cached background; the next :meth:`render_moving` redraws it."""
        self._background = None

    def publish(self) -> bytes:
        """Encode the canvas as it stands into the image widget; return the PNG bytes."""
        buffer = io.BytesIO()
        # Fast PNG: level-1 compression, the picture is redrawn on every step.
        PILImage.fromarray(np.asarray(self.canvas.buffer_rgba())).save(
            buffer, format="png", compress_level=1
        )
        self.image.value = buffer.getvalue()
        return buffer.getvalue()


class SliderApp:
    """Controls beside a figure; any control's change redraws the figure.

    Subclasses build their artists in ``__init__`` (after calling this one
    with their controls) and implement ``update``, which reads the controls'
    values and changes artist data. ``controls`` maps names to widgets, so a
    test can do ``app.controls["t"].value = 0.3`` and inspect the result.
    """

    def __init__(
        self,
        controls: dict[str, widgets.ValueWidget],
        shape: tuple[int, int] = (500, 500),
        dpi: int = 100,
    ) -> None:
        self.controls = controls
        self.view = FigureView(shape, dpi)
        self.figure = self.view.figure
        self.renders = 0
        for control in controls.values():
            control.observe(self._on_change, names="value")
        # Controls beside the picture when the window is wide enough, below it
        # when not: they never shrink, so their labels are never cut off.
        panel = widgets.VBox(list(controls.values()), layout=widgets.Layout(flex="0 0 auto"))
        self.widget = widgets.HBox(
            [self.view.image, panel],
            layout=widgets.Layout(align_items="flex-start", flex_flow="row wrap"),
        )

    def value(self, name: str) -> Any:
        """The current value of control ``name``."""
        return self.controls[name].value

    def update(self) -> None:  # pragma: no cover - every app overrides it
        raise NotImplementedError

    def refresh(self) -> bytes:
        """Update the artists from the controls and render the picture."""
        self.update()
        self.renders += 1
        return self.view.render()

    def _on_change(self, change: dict) -> None:
        self.refresh()

    def describe(self) -> str:
        """A stable one-line summary: the app's name and its controls' values."""
        values = ", ".join(
            f"{name}={_format(control.value)}" for name, control in self.controls.items()
        )
        return f"{type(self).__name__}({values})"

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        # JupyterLab shows the live widget. The text is what nbval compares, so
        # it must not hold PNG bytes; the PNG is the still picture that static
        # viewers (GitHub, nbviewer, a notebook opened without a kernel) show.
        if self.renders == 0:
            self.refresh()
        bundle = self.widget._repr_mimebundle_(**kwargs)
        bundle["text/plain"] = self.describe()
        bundle["image/png"] = base64.b64encode(bytes(self.view.image.value)).decode("ascii")
        return bundle


def _format(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, tuple):
        return "(" + ", ".join(_format(v) for v in value) + ")"
    return repr(value)
