"""Drawing a checked path: what :func:`course.antialias.render` and Agg's anchor run.

Nothing here checks the arguments its callers check (``UNCHECKED = True``): ``path`` is
:class:`course.curves.paths.Curves`, ``canvas`` a shape ``(H, W)``, ``method`` one of
:data:`course.antialias.RENDER_METHODS`, ``width`` a float > 0 within
:data:`course.limits.MAX_STROKE_WIDTH`, ``step`` None or a float > 0, ``weighting`` one of
:data:`course.antialias.WEIGHTINGS`, as :func:`course.antialias.render` makes sure before
it calls :func:`render_path`. What sampling a curve costs depends on the curve and the
step: it is checked here, as the curve is sampled (:func:`evaluate`). The measures of
:mod:`course.antialias.curve_quality` draw their variants here, each checked once.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import RendererAgg
from matplotlib.path import Path
from matplotlib.transforms import Affine2D

from course import limits
from course._validate import as_points, describe
from course.antialias._splats import arc_length_weights, splat_points
from course.antialias.near_pixels import first_of_runs, pixels_near
from course.antialias.splats import PIXELS_PER_SAMPLE
from course.antialias.stroke import stroke_coverage
from course.curves._bezier_fast import bernstein_horner, de_casteljau_chunked
from course.curves._frozen import made
from course.curves._uniform import uniform_polyline, uniform_steps
from course.curves.drawable_paths import matplotlib_path
from course.curves.paths import Curves
from course.i18n import _
from course.limits import require_bounded_evaluation, require_step_samples
from course.raster._paint import painted_canvas
from course.raster.canvas import painted

__all__ = [
    "AGG",
    "ARC_LENGTH",
    "ARC_LENGTH_SPACING",
    "DEFAULT_STEP",
    "SPLAT_REACH",
    "STROKE_TOLERANCE",
    "agg_coverage",
    "agg_stroke",
    "checked_line",
    "checked_samples",
    "default_arc_length_step",
    "evaluate",
    "one_curve_path",
    "painted_white",
    "render_path",
    "stroke_linear_coverage",
    "variant_coverage",
    "with_gaps",
]

UNCHECKED = True  # kernels for checked callers; see the module docstring

# The handouts' loop: for (t = 0; t <= 1; t += 0.001).
DEFAULT_STEP = 0.001
# Largest distance between samples the arc-length fix picks by itself, in pixels.
ARC_LENGTH_SPACING = 0.5
# Largest distance from the flattened curve to the true one in the stroke methods.
STROKE_TOLERANCE = 0.01
# Names of the variants beside the methods' own names (course.antialias.curve_quality's).
AGG = "Agg (matplotlib)"
ARC_LENGTH = " + arc length"
# Farther than any splat paints from its sample, in pixels (bilinear: 1.5, rounded up).
SPLAT_REACH = 3.0


def one_curve_path(control: np.ndarray) -> Curves:
    """A checked curve as the one curve of a path, as course.curves.paths.as_path makes it."""
    return made(Curves, points=control, sizes=np.array([len(control)]))


def variant_coverage(
    name: str, path: Curves, canvas: tuple[int, int], width: float, evaluated: dict | None = None
) -> np.ndarray:
    """:func:`course.antialias.curve_quality.render_variant` of checked arguments;
    ``evaluated`` keeps the splats' samples for the next variant of the same path
    (:func:`render_path`)."""
    if name == AGG:
        return agg_coverage(path, canvas, width)
    if name.endswith(ARC_LENGTH):
        method, weighting = name[: -len(ARC_LENGTH)], "arc_length"
    else:
        method, weighting = name, "count"
    return render_path(path, canvas, method, width, None, weighting, evaluated)


def render_path(
    path: Curves,
    canvas: tuple[int, int],
    method: str,
    width: float,
    step: float | None,
    weighting: str,
    evaluated: dict | None = None,
) -> np.ndarray:
    """:func:`course.antialias.render` of checked arguments: the path drawn on a new canvas.

    ``evaluated``, when given, keeps each curve's samples by its step, for
    the next call on the same path (the samples are read, never modified).
    """
    if method == "stroke_area":
        # The fast path: the exact coverage straight into a new canvas.
        line, gaps = uniform_polyline(path, STROKE_TOLERANCE)
        return stroke_coverage(line, gaps, 0.5 * width, canvas)
    if method == "stroke_linear":
        line, gaps = checked_line(*uniform_polyline(path, STROKE_TOLERANCE))
        pixels, weights = stroke_linear_coverage(line, gaps, width, canvas, (0, 0))
        # Each pixel comes once: "max" writes it without a saturating sum.
        return painted_white(canvas, pixels, weights, mode="max")
    # The handouts' loop, curve after curve; every splat adds, with saturation.
    controls = path.split() if len(path.sizes) > 1 else [path.points]
    steps = [
        step
        if step is not None
        else (DEFAULT_STEP if weighting == "count" else default_arc_length_step(control))
        for control in controls
    ]
    _require_few_samples(steps, step is not None)
    all_pixels, all_weights = [], []
    for index, (control, own_step) in enumerate(zip(controls, steps, strict=True)):
        if np.floor(1 / own_step * (1 + 1e-12)) + 2 > limits.MAX_STEP_SAMPLES:
            require_step_samples(own_step, "step")  # one curve's samples, refused as before
        samples = None if evaluated is None else evaluated.get((index, own_step))
        if samples is None:
            samples = checked_samples(evaluate(control, uniform_steps(own_step, "exact")))
            if evaluated is not None:
                evaluated[index, own_step] = samples
        lengths = arc_length_weights(samples) if weighting == "arc_length" else None
        # A window of a long curve (render_window) is touched by a few of its thousand.
        touching = _touching(samples, canvas)
        if touching is not None:
            samples = samples[touching]
            lengths = None if lengths is None else lengths[touching]
        pixels, weights = splat_points(samples, method)
        if lengths is not None:
            spread = np.repeat(lengths * width, PIXELS_PER_SAMPLE[method])
            weights = np.minimum(weights * spread, 1)
        all_pixels.append(pixels)
        all_weights.append(weights)
    if len(all_pixels) > 1:
        all_pixels, all_weights = [np.concatenate(all_pixels)], [np.concatenate(all_weights)]
    return painted_white(canvas, all_pixels[0], all_weights[0])


def _touching(samples: np.ndarray, canvas: tuple[int, int]) -> np.ndarray | None:
    """Which samples' splats can reach the canvas (None when all can).

    Every splat paints within :data:`SPLAT_REACH` pixels of its sample: the
    others add nothing, as the canvas drops their pixels, and the order of
    the rest is kept, so the sums are the same.
    """
    height, width = canvas
    x, y = samples[:, 0], samples[:, 1]
    touching = (
        (x >= -SPLAT_REACH) & (x <= width + SPLAT_REACH) & (y >= -SPLAT_REACH)
        & (y <= height + SPLAT_REACH)
    )  # fmt: skip
    return None if touching.all() else touching


def stroke_linear_coverage(
    line: np.ndarray,
    gaps: np.ndarray,
    width: float,
    canvas: tuple[int, int],
    origin: tuple[int, int],
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`course.antialias.stroke_linear` of checked arguments, on a canvas (H, W) whose
    corner is ``origin``."""
    reach = 0.5 * width + 0.5
    near = pixels_near(line, canvas, reach, origin, gaps=gaps)
    # Pairs are sorted by pixel, nearest segment first.
    first = first_of_runs(near.flat)
    pixels = np.stack([near.x[first], near.y[first]], axis=1)
    weights = np.clip(reach - near.distance[first], 0.0, 1.0)
    keep = weights > 0
    return pixels[keep], weights[keep]


def with_gaps(line: np.ndarray, gaps: Any) -> tuple[np.ndarray, np.ndarray]:
    """A checked (K, 2) polyline (a point doubled, to keep its caps) and its gaps, checked."""
    if len(line) == 1:
        line = np.vstack([line, line])
    if gaps is None:
        return line, np.zeros(len(line) - 1, dtype=bool)
    mask = np.asarray(gaps)
    if mask.dtype != bool or mask.shape != (len(line) - 1,):
        raise ValueError(
            _(
                "gaps must be a bool array of shape ({line_count},), one per segment; got {gaps}"
            ).format(line_count=len(line) - 1, gaps=describe(gaps))
        )
    return line, mask


def checked_line(line: np.ndarray, gaps: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A path's polyline as :func:`course.antialias.stroke_linear` takes it, checked where it
    can fail.

    The polyline's points lie on the path's curves; they can stray past the coordinates'
    bound by a rounding, or outnumber a polyline's points by the path's joins.
    """
    if len(line) > limits.MAX_SAMPLES or np.abs(line).max() > limits.MAX_COORDINATE:
        as_points(line, "polyline", bound=limits.MAX_COORDINATE)  # refused, as before
    return with_gaps(line, gaps)


def checked_samples(samples: np.ndarray) -> np.ndarray:
    """A curve's samples as the splats take them, checked where they can fail: a rounding
    can put a point of the curve past the coordinates' bound."""
    if len(samples) > limits.MAX_SAMPLES or np.abs(samples).max() > limits.MAX_COORDINATE:
        as_points(samples, "samples", bound=limits.MAX_COORDINATE)  # refused, as before
    return samples


def painted_white(
    canvas: tuple[int, int], pixels: np.ndarray, weights: np.ndarray, mode: str = "add"
) -> np.ndarray:
    """A new canvas with the pixels painted white at their weights, made here."""
    if weights.size and not (
        np.all(np.isfinite(weights)) and weights.min() >= 0 and weights.max() <= 1
    ):
        return painted(canvas, pixels, 1.0, weights, mode=mode)  # refused, as before
    return painted_canvas(canvas, pixels, np.array(1.0), weights, mode)


def _require_few_samples(steps: list[float], given: bool) -> None:
    """ValueError before sampling when the curves' t steps add up to too many samples."""
    total = sum(np.floor(1 / step * (1 + 1e-12)) + 1 for step in steps)
    if total > limits.MAX_STEP_SAMPLES:
        cause = "step" if given else "points (a long curve takes a fine default step)"
        raise ValueError(
            _(
                "{cause}: the splat methods would take about {total:.3g} samples over "
                "{steps_count} curves, more than the {most} allowed; use a larger "
                "step, fewer or shorter curves, or a stroke method"
            ).format(
                cause=cause,
                total=total,
                steps_count=len(steps),
                most=limits.MAX_STEP_SAMPLES,
            )
        )


def evaluate(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Points of the curve: the Bernstein form up to cubics, de Casteljau beyond.

    The kernels of :func:`course.curves.bezier.bezier_bernstein` (its Horner form, with
    its binomials) and :func:`course.curves.bezier.de_casteljau`, on a checked curve.
    """
    require_bounded_evaluation(len(control), len(t))
    if len(control) > 4:
        return de_casteljau_chunked(control, t)
    degree = len(control) - 1
    binomials = np.array([float(math.comb(degree, k)) for k in range(degree + 1)])
    return bernstein_horner(control, binomials, t)


def default_arc_length_step(control: np.ndarray) -> float:
    """:func:`course.antialias.arc_length_step` of a checked curve."""
    if len(control) < 2:
        return DEFAULT_STEP
    speed = (len(control) - 1) * np.hypot(*np.diff(control, axis=0).T).max()
    return float(min(DEFAULT_STEP, ARC_LENGTH_SPACING / speed)) if speed > 0 else DEFAULT_STEP


def agg_coverage(path: Curves, canvas: tuple[int, int], width: float) -> np.ndarray:
    """:func:`course.antialias.agg.agg_render` of checked arguments: (H, W) coverage."""
    height, canvas_width = canvas
    drawable = matplotlib_path(path)
    if len(drawable.vertices) > limits.MAX_SAMPLES:
        as_points(drawable.vertices, "path.vertices")  # more vertices than a path may hold
    renderer = agg_stroke(drawable, height, canvas_width, width)
    return np.asarray(renderer.buffer_rgba())[..., 3] / 255.0


def agg_stroke(path: Path, height: int, canvas_width: int, width: float) -> RendererAgg:
    """:func:`course.antialias.agg.agg_draw` of checked arguments: vertices within the
    coordinates, (N, 2)."""
    renderer = RendererAgg(canvas_width, height, 72)
    context = renderer.new_gc()
    context.set_linewidth(width)
    context.set_capstyle("round")
    context.set_joinstyle("round")
    context.set_antialiased(True)
    context.set_snap(False)
    context.set_foreground((1.0, 1.0, 1.0, 1.0))
    flip = Affine2D().scale(1.0, -1.0).translate(0.0, height)
    renderer.draw_path(context, path, flip)
    context.restore()
    return renderer
