"""Lesson 08's still pictures: a clone that works, its correction, a clone that cannot keep
the colours, masks and mixed gradients, inpainting, and the tiny clone solved by hand.

Each function returns a :class:`~course.widgets.picture.Still` whose caption
states the numbers it shows; photographs are drawn pixel for pixel
(:func:`~course.widgets.picture.pixel_figure`). How far the lab's sweeps get, and
the sweeps app's questions, are in :mod:`.convergence`, which draws on the scenes here.
"""

from __future__ import annotations

import functools
from typing import Any

import matplotlib
import numpy as np
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from course import images, limits, poisson
from course._validate import as_int
from course.i18n import _
from course.widgets.picture import Still, bare_axes, pixel_axes, pixel_figure

__all__ = [
    "DAY_OFFSET",
    "LAB_OFFSET",
    "colour_figure",
    "correction_figure",
    "day_scene",
    "headline_figure",
    "inpainting_figure",
    "lab_scene",
    "mask_and_mixed_figure",
    "tiny_clone_figure",
]

#: Where the day plane sits in the lake's sky (x, y): the headline clone.
DAY_OFFSET = (420, 50)
#: The lab's offset: the evening plane over the water.
LAB_OFFSET = (500, 300)
_MARGIN = 30
BLUE, VERMILLION, GREEN = "#0072B2", "#D55E00", "#009E73"
#: g has both signs: purple below 0, white at 0, green above (no orange, the inside's mark).
G_COLOURS = "PRGn"


def _read_only(*arrays: np.ndarray) -> tuple[np.ndarray, ...]:
    for array in arrays:
        array.flags.writeable = False  # cached: shared by every caller
    return arrays


@functools.cache
def day_scene() -> tuple[np.ndarray, np.ndarray]:
    """The lake and the plane photographed against a pale day sky (read-only)."""
    return _read_only(images.lake(), images.plane(sky="day"))


@functools.cache
def lab_scene() -> tuple[np.ndarray, np.ndarray]:
    """The lake and the lab's plane in its orange evening sky (read-only)."""
    return _read_only(images.lake(), images.plane())


def _around(offset: tuple[int, int], shape: tuple[int, int], image: np.ndarray) -> tuple:
    """The window of ``image`` around a pasted ``shape`` at ``offset``, with its extent."""
    x, y = offset
    top, left = max(y - _MARGIN, 0), max(x - _MARGIN, 0)
    bottom = min(y + shape[0] + _MARGIN, image.shape[0])
    right = min(x + shape[1] + _MARGIN, image.shape[1])
    return (slice(top, bottom), slice(left, right)), (left, right, bottom, top)


def _grey(value: float) -> str:
    return f"{value * 255:.1f}"


def headline_figure() -> Still:
    """The day plane pasted into the lake's sky: copied pixels, and the seamless clone.

    Examples
    --------
    >>> headline_figure()  # doctest: +NORMALIZE_WHITESPACE
    the step across the region's border: 54.7 grey levels pasted, 2.7 cloned
    (the sky's own steps there: 3.5)
    """
    lake, plane = day_scene()
    naive = poisson.naive_paste(lake, plane, DAY_OFFSET)
    cloned = poisson.seamless_clone(lake, plane, DAY_OFFSET)
    window, extent = _around(DAY_OFFSET, plane.shape[:2], lake)
    figure, _panels = pixel_figure(
        [
            (naive[window], extent, _("pasted: the pixels copied")),
            (cloned[window], extent, _("seamless clone")),
        ],
        1,
    )
    problem = poisson.clone_problem(lake, plane, DAY_OFFSET)
    caption = _(
        "the step across the region's border: {pasted} grey levels "
        "pasted, {cloned} cloned (the sky's own steps there: {sky})"
    ).format(
        pasted=_grey(problem.seam(naive)),
        cloned=_grey(problem.seam(cloned)),
        sky=_grey(problem.seam(lake)),
    )
    return Still.of(figure, caption)


def correction_figure() -> Still:
    """The headline's correction g = u - f: smooth, from the ring's mismatch inwards.

    Examples
    --------
    >>> correction_figure()  # doctest: +NORMALIZE_WHITESPACE
    g's mean over the region (R, G, B): -0.22, -0.19, -0.11;
    from -0.59 to 0.19 on the ring
    """
    lake, plane = day_scene()
    ring = poisson.correction_boundary(lake, plane, DAY_OFFSET)
    problem = poisson.clone_problem(lake, plane, DAY_OFFSET)
    membrane = poisson.PoissonProblem(ring, problem.region, np.zeros_like(ring), problem.corner)
    g = poisson.solve(membrane)
    extent = (0, plane.shape[1], plane.shape[0], 0)
    figure, _panels = pixel_figure(
        [
            (plane, extent, _("the plane, f")),
            (np.clip((g + 1) / 2, 0, 1), extent, _("g, shown as (g + 1) / 2")),
            (np.clip(plane + g, 0, 1), extent, "f + g"),
        ],
        1,
    )
    edge = ~problem.region
    means = _(", ").join(f"{value:.2f}" for value in g[problem.region].mean(axis=0))
    caption = _(
        "g's mean over the region (R, G, B): {means}; from {low:.2f} to {high:.2f} on the ring"
    ).format(means=means, low=ring[edge].min(), high=ring[edge].max())
    return Still.of(figure, caption)


def colour_figure() -> Still:
    """The lab's scene: the evening plane over the water, pasted and cloned.

    Examples
    --------
    >>> colour_figure()  # doctest: +NORMALIZE_WHITESPACE
    cloned, the plane's white shifts by -0.77, -0.35, +0.05 (R, G, B) on average;
    5.5% of the region's values fall outside [0, 1] and are clipped
    """
    lake, plane = lab_scene()
    naive = poisson.naive_paste(lake, plane, LAB_OFFSET)
    cloned = poisson.seamless_clone(lake, plane, LAB_OFFSET)
    window, extent = _around(LAB_OFFSET, plane.shape[:2], lake)
    problem = poisson.clone_problem(lake, plane, LAB_OFFSET)
    exact = poisson.solve(problem)
    shift = (exact - plane)[problem.region].mean(axis=0)
    outside = ((exact < 0) | (exact > 1))[problem.region].mean()
    shifts = _(", ").join(f"{value:+.2f}" for value in shift)
    figure, _panels = pixel_figure(
        [
            (naive[window], extent, _("pasted")),
            (
                cloned[window],
                extent,
                _(
                    "clone: R, G, B moved by {shifts};\n"
                    "{outside:.1%} of values outside [0, 1], clipped"
                ).format(shifts=shifts, outside=outside),
            ),
        ],
        1,
        title_height=44,
    )
    caption = _(
        "cloned, the plane's white shifts by {shifts} (R, G, B) on average; "
        "{outside:.1%} of the region's values fall outside [0, 1] and are clipped"
    ).format(shifts=shifts, outside=outside)
    return Still.of(figure, caption)


def mask_and_mixed_figure() -> Still:
    """The headline clone three ways: the rectangle, a mask around the plane, mixed gradients.

    Examples
    --------
    >>> mask_and_mixed_figure()  # doctest: +NORMALIZE_WHITESPACE
    mean step between neighbours inside the rectangle: the sky 3.49 grey levels,
    rectangle 3.94, mask 4.63, mixed 5.37
    """
    lake, plane = day_scene()
    shown = {
        _("rectangle"): poisson.seamless_clone(lake, plane, DAY_OFFSET),
        _("mask"): poisson.seamless_clone(lake, plane, DAY_OFFSET, images.plane_mask()),
        _("mixed"): poisson.seamless_clone(lake, plane, DAY_OFFSET, guidance="mixed"),
    }
    window, extent = _around(DAY_OFFSET, plane.shape[:2], lake)
    figure, _panels = pixel_figure(
        [(image[window], extent, name) for name, image in shown.items()], 1
    )
    problem = poisson.clone_problem(lake, plane, DAY_OFFSET)
    steps = _(", ").join(
        _("{name} {step:.2f}").format(name=name, step=problem.texture(image) * 255)
        for name, image in shown.items()
    )
    caption = _(
        "mean step between neighbours inside the rectangle: the sky {sky:.2f} grey levels, {steps}"
    ).format(sky=problem.texture(lake) * 255, steps=steps)
    return Still.of(figure, caption)


def inpainting_figure() -> Still:
    """Seven scratches across the photograph, filled by Laplace's equation.

    Examples
    --------
    >>> inpainting_figure()  # doctest: +NORMALIZE_WHITESPACE
    8214 scratched pixels: mean error 154 grey levels scratched, 9.1 inpainted
    (95% within 36)
    """
    original = images.photograph()
    scratched, scratches = images.scratched_photograph()
    filled = poisson.inpaint(scratched, scratches)
    window = (slice(120, 420), slice(60, 460))
    extent = (60, 460, 420, 120)
    figure, _panels = pixel_figure(
        [(scratched[window], extent, _("scratched")), (filled[window], extent, _("inpainted"))],
        1,
    )
    error = np.abs(filled - original)[scratches] * 255
    before = np.abs(scratched - original)[scratches].mean() * 255
    caption = _(
        "{count} scratched pixels: mean error {before:.0f} grey levels scratched, "
        "{after:.1f} inpainted (95% within {percentile:.0f})"
    ).format(
        count=scratches.sum(),
        before=before,
        after=error.mean(),
        percentile=np.percentile(error, 95),
    )
    return Still.of(figure, caption)


#: Lesson 08's tiny clone: a 6 x 7 sky brightening to the right, and a 4 x 5 patch of a white
#: plane with one dark window, pasted at (1, 1). Its inside is 2 x 3: six unknowns.
TINY_BACKGROUND = np.tile(np.round(np.linspace(0.1, 0.7, 7), 2), (6, 1))
TINY_FOREGROUND = np.array(
    [
        [0.9, 0.9, 0.9, 0.9, 0.9],
        [0.9, 1.0, 0.6, 1.0, 0.9],
        [0.9, 1.0, 1.0, 1.0, 0.9],
        [0.9, 0.9, 0.9, 0.9, 0.9],
    ]
)
TINY_OFFSET = (1, 1)
#: The residual the tiny clone's sweeps stop below; its caption states it with the count.
TINY_TOLERANCE = 1e-6


def _tiny_correction(boundary: Any, jacobi: Any) -> tuple[np.ndarray, int, str]:
    """g for the tiny clone from the student's two functions, or the library's if they fail.

    Theirs are drawn only when they give the library's g in the library's number of
    Jacobi sweeps: a Gauss-Seidel sweep reaches the same g sooner, and fails Exercise 2.
    """
    ring = poisson.correction_boundary(TINY_BACKGROUND, TINY_FOREGROUND, TINY_OFFSET)
    expected, sweeps = _jacobi_reference(ring, TINY_TOLERANCE)
    try:
        given_ring = np.asarray(
            boundary(TINY_BACKGROUND.copy(), TINY_FOREGROUND.copy(), TINY_OFFSET), dtype=float
        )
        given, count = jacobi(given_ring, TINY_TOLERANCE)
        given = np.asarray(given, dtype=float)
        same = given.shape == expected.shape and np.allclose(given, expected, atol=1e-5)
        if same and int(count) == sweeps:
            return given, sweeps, _("your boundary_ring and jacobi_solve")
    except Exception:  # the student's code is not written yet, or fails: show the library's
        pass
    return expected, sweeps, _("the library's (yours do not pass their checks yet)")


def _jacobi_reference(g: np.ndarray, tolerance: float) -> tuple[np.ndarray, int]:
    """Jacobi sweeps on g's inside until the residual is below ``tolerance``."""
    g = np.array(g, dtype=float)
    sweeps = 0
    while True:
        around = g[:-2, 1:-1] + g[2:, 1:-1] + g[1:-1, :-2] + g[1:-1, 2:]
        if np.abs(around - 4 * g[1:-1, 1:-1]).max() < tolerance:
            return g, sweeps
        g[1:-1, 1:-1] = around / 4
        sweeps += 1


def tiny_clone_figure(boundary: Any = None, jacobi: Any = None, zoom: int = 50) -> Still:
    """A clone small enough to check by hand, solved by the student's own two functions.

    ``boundary`` and ``jacobi`` are the lesson's exercises; if either is
    missing or its answer is wrong (a Gauss-Seidel sweep included), the
    library's is drawn and the title says so. Every pixel's value is written.

    Examples
    --------
    >>> tiny_clone_figure()  # doctest: +NORMALIZE_WHITESPACE
    the library's (yours do not pass their checks yet): 28 sweeps to a residual below 1e-6;
    the dark window stays 0.4 darker than the pixel below it (0.100 against 0.500); the
    clone's ring equals the sky's
    """
    zoom = as_int(zoom, "zoom", minimum=8, maximum=limits.MAX_ZOOM)
    g, sweeps, who = _tiny_correction(boundary, jacobi)
    height, width = TINY_FOREGROUND.shape
    x, y = TINY_OFFSET
    sky = TINY_BACKGROUND[y : y + height, x : x + width]
    clone = TINY_FOREGROUND + g
    panels = (
        (_("the sky b, under the patch"), sky),
        (_("the plane f"), TINY_FOREGROUND),
        (_("g: b - f on the ring,\nJacobi inside ({sweeps} sweeps)").format(sweeps=sweeps), g),
        (_("the clone f + g"), clone),
    )
    side, gap, title, scale_room = width * zoom, 22, 44, 64
    # g's colours are symmetric about 0, so a value and its negative are equally strong.
    reach = float(np.abs(g).max()) or 1.0
    g_norm = Normalize(-reach, reach)
    figure = Figure(
        figsize=(
            (gap + len(panels) * (side + gap) + scale_room) / 100,
            (height * zoom + title + 40) / 100,
        )
    )
    left = gap
    for name, values in panels:
        axes = bare_axes(pixel_axes(figure, left, 8, side, height * zoom))
        if values is g:
            colours = matplotlib.colormaps[G_COLOURS](g_norm(values))
            axes.imshow(
                values,
                cmap=G_COLOURS,
                norm=g_norm,
                interpolation="nearest",
                extent=(0, width, height, 0),
            )
            scale = pixel_axes(figure, left + side + 8, 8, 12, height * zoom)
            figure.colorbar(ScalarMappable(g_norm, G_COLOURS), cax=scale).set_label("g")
            scale.tick_params(labelsize=8)
            left += scale_room
        else:
            shown = np.clip(values, 0.0, 1.0)
            colours = matplotlib.colormaps["gray"](shown)
            axes.imshow(
                shown,
                cmap="gray",
                vmin=0,
                vmax=1,
                interpolation="nearest",
                extent=(0, width, height, 0),
            )
        lightness = colours[..., :3] @ (0.299, 0.587, 0.114)
        axes.add_patch(
            Rectangle((1, 1), width - 2, height - 2, fill=False, edgecolor=VERMILLION, lw=2)
        )
        for (row, column), value in np.ndenumerate(values):
            axes.text(
                column + 0.5,
                row + 0.5,
                f"{value:.3f}".rstrip("0").rstrip("."),
                ha="center",
                va="center",
                fontsize=8,
                color="white" if lightness[row, column] < 0.5 else "black",
            )
        axes.set_title(name, fontsize=9)
        left += side + gap
    figure.text(
        0.5,
        0.98,
        _(
            "solved by {who}; orange: the inside, the six unknowns; "
            "g in purple below 0 and green above, its scale beside it"
        ).format(who=who),
        ha="center",
        va="top",
        fontsize=9,
    )
    dark = clone[1, 2]
    below = clone[2, 2]
    caption = (
        _(
            "{who}: {sweeps} sweeps to a residual below {tolerance}; the dark window stays "
            "{gap:.1f} darker than the pixel below it ({dark:.3f} against {below:.3f}); the "
            "clone's ring equals the sky's"
        )
        if np.allclose(clone[0], sky[0])
        else _(
            "{who}: {sweeps} sweeps to a residual below {tolerance}; the dark window stays "
            "{gap:.1f} darker than the pixel below it ({dark:.3f} against {below:.3f}); the "
            "clone's ring differs from the sky's"
        )
    ).format(
        who=who,
        sweeps=sweeps,
        tolerance=f"{TINY_TOLERANCE:.0e}".replace("e-0", "e-"),  # 1e-6
        gap=TINY_FOREGROUND[2, 2] - TINY_FOREGROUND[1, 2],
        dark=dark,
        below=below,
    )
    return Still.of(figure, caption)
