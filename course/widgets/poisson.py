"""Lesson 08's slider app: an iterative Poisson solve, sweep by sweep.

The region starts as the pasted foreground (the lab's ``g = 0``); each sweep
lets the boundary's values seep further in. Beside the picture, the error
against the exact solution, in grey levels, on a fixed colour scale, so one
sees how slowly Jacobi's error leaves the middle of the region.
"""

from __future__ import annotations

from typing import Any

import ipywidgets as widgets
import numpy as np
from matplotlib.figure import Figure

from course import images, poisson
from course._validate import as_image, as_int
from course.widgets.base import SliderApp

__all__ = ["PoissonIterationApp", "show_images"]

# Sweeps the slider stops at, roughly three per decade up to the lab's 8000.
SWEEP_STOPS = (0, 1, 3, 10, 30, 100, 300, 1000, 3000, 8000)
MARGIN = 12  # background pixels shown around the region


class PoissonIterationApp(SliderApp):
    """Pick a method and a number of sweeps; see the iterate and its error.

    Iterates are computed on demand and kept, so moving back is instant and
    moving forward only runs the sweeps not yet done.

    Parameters
    ----------
    background, foreground, offset, mask
        As for :func:`course.poisson.seamless_clone`; by default the lab's
        scene, :func:`course.images.plane` into :func:`course.images.lake`
        at (500, 300).
    stops : sequence of int
        The sweep counts the slider offers, increasing, starting at 0.
    """

    def __init__(
        self,
        background: Any = None,
        foreground: Any = None,
        offset: Any = (500, 300),
        mask: Any = None,
        stops: tuple[int, ...] = SWEEP_STOPS,
    ) -> None:
        background = images.lake() if background is None else background
        foreground = images.plane() if foreground is None else foreground
        self.problem = poisson.clone_problem(background, foreground, offset, mask)
        self.background = np.asarray(background, dtype=float)
        self.exact = poisson.solve(self.problem)
        self.stops = tuple(int(stop) for stop in stops)
        self._iterates: dict[str, dict[int, np.ndarray]] = {}
        self._runs: dict[str, tuple[Any, int]] = {}
        controls = {
            "method": widgets.Dropdown(
                options=[("Jacobi", "jacobi"), ("Gauss-Seidel", "gauss_seidel"), ("SOR", "sor")],
                value="jacobi",
                description="method",
            ),
            "sweeps": widgets.SelectionSlider(
                options=self.stops, value=self.stops[0], description="sweeps"
            ),
        }
        super().__init__(controls, shape=(330, 900))
        x, y = self.problem.corner
        height, width = self.problem.region.shape
        self.window = (
            slice(max(y - MARGIN, 0), y + height + MARGIN),
            slice(max(x - MARGIN, 0), x + width + MARGIN),
        )
        self.initial_error = self._error(self.problem.values)
        picture_axes = self.figure.add_axes((0.01, 0.08, 0.48, 0.8))
        error_axes = self.figure.add_axes((0.51, 0.08, 0.48, 0.8))
        for axes in (picture_axes, error_axes):
            axes.set_axis_off()
        start = self.composite(self.problem.values)
        self.picture = picture_axes.imshow(start, interpolation="nearest")
        self.error_image = error_axes.imshow(
            self.error_map(self.problem.values),
            cmap="magma",
            vmin=0,
            vmax=max(self.initial_error, 1e-9),
            interpolation="nearest",
        )
        self.figure.colorbar(self.error_image, ax=error_axes, shrink=0.8, label="grey levels")
        picture_axes.set_title("the result after the sweeps", fontsize=10)
        error_axes.set_title("|iterate - exact solution|, largest channel", fontsize=10)
        self.caption = self.figure.text(0.5, 0.96, "", ha="center", va="top", fontsize=11)

    def iterate(self, method: str, sweeps: int) -> np.ndarray:
        """The problem's window after ``sweeps`` sweeps of ``method`` (kept for next time)."""
        kept = self._iterates.setdefault(method, {0: self.problem.values})
        if sweeps not in kept:
            run, done = self._runs.get(method, (None, 0))
            if run is None or done > sweeps:
                run, done = poisson.iterates(self.problem, method), 0
            while done < sweeps:
                latest = next(run)
                done += 1
                if done in self.stops or done == sweeps:
                    kept[done] = latest.copy()
            self._runs[method] = (run, done)
        return kept[sweeps]

    def composite(self, solution: np.ndarray) -> np.ndarray:
        """The background with the region set to ``solution``, cut around the region."""
        return np.clip(self.problem.paste(self.background, solution)[self.window], 0.0, 1.0)

    def error_map(self, solution: np.ndarray) -> np.ndarray:
        """``|solution - exact|`` in grey levels, largest channel, 0 outside the region."""
        error = np.abs(solution - self.exact) * 255
        if error.ndim == 3:
            error = error.max(axis=2)
        full = np.zeros(self.background.shape[:2])
        x, y = self.problem.corner
        height, width = self.problem.region.shape
        full[y : y + height, x : x + width] = np.where(self.problem.region, error, 0.0)
        return full[self.window]

    def update(self) -> None:
        method, sweeps = self.value("method"), self.value("sweeps")
        solution = self.iterate(method, sweeps)
        self.picture.set_data(self.composite(solution))
        self.error_image.set_data(self.error_map(solution))
        residual = self.problem.residual(solution)
        names = {"jacobi": "Jacobi", "gauss_seidel": "Gauss-Seidel", "sor": "SOR"}
        self.caption.set_text(
            f"{names[method]}, {sweeps} sweeps: residual {residual:.2g}, error up to "
            f"{self._error(solution):.1f} grey levels (from {self.initial_error:.1f})"
        )

    def _error(self, solution: np.ndarray) -> float:
        return float(np.abs(solution - self.exact)[self.problem.region].max() * 255)


def show_images(
    pictures: dict[str, Any],
    window: tuple[slice, slice] | None = None,
    columns: int | None = None,
    figure_width: int = 1000,
) -> Figure:
    """Images side by side with their titles; ``window`` crops every one alike.

    The figure is ``figure_width`` pixels wide, the grid ``columns`` images across.

    Gray images are shown on a fixed 0-1 grey scale, so equal values look
    equal across panels.

    Examples
    --------
    >>> figure = show_images({"a": np.zeros((4, 6)), "b": np.ones((4, 6, 3))}, columns=1)
    >>> len(figure.axes), [axes.get_title() for axes in figure.axes]
    (2, ['a', 'b'])
    """
    arrays = {name: as_image(image, f"pictures[{name!r}]") for name, image in pictures.items()}
    if window is not None:
        arrays = {name: image[window] for name, image in arrays.items()}
    columns = as_int(columns or len(arrays), "columns", minimum=1)
    rows = -(-len(arrays) // columns)
    height, width = next(iter(arrays.values())).shape[:2]
    panel = figure_width / 100 / columns
    figure = Figure(
        figsize=(figure_width / 100, rows * (panel * height / width + 0.35)),
        dpi=100,
        layout="constrained",
    )
    for index, (name, image) in enumerate(arrays.items()):
        axes = figure.add_subplot(rows, columns, index + 1)
        axes.imshow(image, cmap="gray", vmin=0, vmax=1, interpolation="antialiased")
        axes.set_title(name, fontsize=10)
        axes.set_axis_off()
    return figure
