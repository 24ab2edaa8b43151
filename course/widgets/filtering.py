"""Lesson 07 app: repeated 3 x 3 blurs under the four border rules, side by side.

:class:`RepeatedBlurApp` blurs an image n times (the slider) with each border
rule of :mod:`course.filters` and shows the whole image above a zoomed crop
of its top-right corner, where the rules differ: zero padding darkens a frame
that grows with every pass; the other three keep the edge's brightness.
"""

from __future__ import annotations

from typing import Any

import ipywidgets as widgets
import numpy as np

from course import filters
from course._validate import as_image, as_int
from course.widgets.base import SliderApp
from course.widgets.picture import GRAY_PIXELS, bare_axes

__all__ = ["RepeatedBlurApp", "border_ring_mean"]


def border_ring_mean(image: Any, thickness: int = 1) -> float:
    """Mean of the outermost ``thickness`` pixels all around the image.

    Examples
    --------
    >>> image = np.ones((4, 5))
    >>> image[1:-1, 1:-1] = 0
    >>> border_ring_mean(image)
    1.0
    """
    array = as_image(image, "image")
    thickness = as_int(thickness, "thickness", minimum=1)
    ring = np.ones(array.shape[:2], dtype=bool)
    ring[thickness:-thickness, thickness:-thickness] = False
    return float(array[ring].mean())


def blurred(image: np.ndarray, border: str) -> np.ndarray:
    """One 3 x 3 box blur with the given border rule (``blur`` for the handout's)."""
    if border == "handout":
        return filters.blur(image)
    return filters.convolve(image, filters.BOX, border)


class RepeatedBlurApp(SliderApp):
    """Blur n times with each border rule; the corner crop shows the frame.

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3), values in [0, 1]
    repeats : int
        Initial number of blurs.
    corner : int
        Side of the zoomed top-right crop.
    """

    def __init__(self, image: Any, repeats: int = 5, corner: int = 32) -> None:
        self.image = as_image(image, "image")
        self.corner = as_int(corner, "corner", minimum=2)
        self.original_ring = border_ring_mean(self.image)
        controls = {"repeats": widgets.IntSlider(value=repeats, min=0, max=30, description="blurs")}
        super().__init__(controls, shape=(560, 1000))
        self.done = 0
        self.results = dict.fromkeys(filters.BORDERS, self.image)
        self.wholes, self.crops, self.titles = {}, {}, {}
        grid = self.figure.add_gridspec(2, 4, left=0.01, right=0.99, top=0.9, bottom=0.01)
        style = GRAY_PIXELS if self.image.ndim == 2 else {"interpolation": "nearest"}
        for column, border in enumerate(filters.BORDERS):
            top = bare_axes(self.figure.add_subplot(grid[0, column]))
            self.wholes[border] = top.imshow(
                self.image, **{**style, "interpolation": "antialiased"}
            )
            self.titles[border] = top.set_title(border, fontsize=9)
            bottom = bare_axes(self.figure.add_subplot(grid[1, column]))
            self.crops[border] = bottom.imshow(self.corner_of(self.image), **style)
        self.update()

    def corner_of(self, image: np.ndarray) -> np.ndarray:
        """The zoomed top-right corner."""
        return image[: self.corner, -self.corner :]

    def blurred(self, repeats: int) -> dict[str, np.ndarray]:
        """The image blurred ``repeats`` times under each rule (kept for the next step)."""
        if repeats < self.done:
            self.done, self.results = 0, dict.fromkeys(filters.BORDERS, self.image)
        while self.done < repeats:
            self.results = {
                border: blurred(result, border) for border, result in self.results.items()
            }
            self.done += 1
        return self.results

    def update(self) -> None:
        repeats = int(self.value("repeats"))
        for border, result in self.blurred(repeats).items():
            self.wholes[border].set_data(result)
            self.crops[border].set_data(self.corner_of(result))
            ratio = border_ring_mean(result) / self.original_ring
            self.titles[border].set_text(
                f"{border!r}, {repeats} blurs\nedge pixels at {ratio:.2f} x the original"
            )
