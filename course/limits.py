"""The course's limits: every bound on an input's size, coordinates or counts, in one place.

A public function rejects input beyond these bounds with a ValueError naming
the parameter, before it allocates or loops, so that no call runs unbounded
and no far-away value wraps around to a pixel on the canvas. The validators of
:mod:`course._validate` apply them to each argument; the ``require_*`` checks at the end
bound the work a call asks for (vertices, samples, interpolations), which several
arguments decide together, before any of it is done.

Examples
--------
>>> MAX_PIXELS
8388608
"""

from __future__ import annotations

import numpy as np

from course.i18n import _

__all__ = [
    "LARGEST",
    "MAX_BAYER_SIZE",
    "MAX_CALLS",
    "MAX_COORDINATE",
    "MAX_COUNT",
    "MAX_DEGREE",
    "MAX_EVALUATION_WORK",
    "MAX_FIGURE_PIXELS",
    "MAX_FIGURE_POINTS",
    "MAX_HANDOUT_POINTS",
    "MAX_ITERATIONS",
    "MAX_MASK_SIZE",
    "MAX_OVERLAP_PAIRS",
    "MAX_PARAMETER",
    "MAX_PIXELS",
    "MAX_RATE",
    "MAX_SAMPLES",
    "MAX_SIDE",
    "MAX_STEP_SAMPLES",
    "MAX_STROKED_TEXT",
    "MAX_STROKE_WIDTH",
    "MAX_SUPERSAMPLES",
    "MAX_TEXT_LENGTH",
    "MAX_TYPED_TEXT",
    "MAX_ZOOM",
    "SMALLEST",
    "require_bounded_evaluation",
    "require_bounded_flattening",
    "require_step_samples",
]

MAX_PIXELS = 2**23
"""Pixels in one image, canvas or sample grid (H * W, times rate**2 when supersampled)."""

MAX_SIDE = 2**16
"""Largest side of an image, canvas or resampled row, in pixels."""

MAX_ZOOM = 128
"""Screen pixels per image pixel, on each side, in a figure's pixel view."""

MAX_STROKE_WIDTH = 1000.0
"""Widest stroke, in pixels: every pixel within half of it of the curve is visited."""

MAX_SUPERSAMPLES = 2**28
"""Most samples one supersampling call may take (output pixels times rate**2)."""

MAX_RATE = 256
"""Largest supersampling rate (samples per pixel side)."""

MAX_FIGURE_PIXELS = 4000 * 4000
"""Most pixels of an app's or figure's picture."""

MAX_FIGURE_POINTS = 100
"""Most control points of a curve a lesson's figure draws and labels one by one."""

MAX_SAMPLES = 2**25
"""Points, samples or polyline vertices one call may generate."""

MAX_STEP_SAMPLES = 2**20
"""Most samples a fixed t step may give (t = 0, step, 2 step, ... <= 1), over all of a
path's curves: a step of at least about 1e-6 for one curve. The handouts step by 0.001
and 0.0001; a million samples already take seconds to splat and count."""

MAX_COORDINATE = 2.0**20
"""Largest |x| or |y| of an image-space point (a million pixels off any canvas)."""

MAX_PARAMETER = 1e3
"""Largest |t| of a curve parameter: extrapolating further overflows any but tiny degrees."""

MAX_DEGREE = 2000
"""Largest degree (or binomial row n): exact Pascal rows beyond it take seconds."""

MAX_EVALUATION_WORK = 2**27
"""Most interpolations one evaluation of a curve may take: samples times (degree + 1)**2.
A cubic may be sampled at 8 million parameters, a degree-1000 curve at 134."""

MAX_COUNT = 10**7
"""Largest integer count or size of any other kind (sizes, rates, samples, margins)."""

MAX_ITERATIONS = 100_000
"""Largest number of iterations (sweeps) of an iterative solver."""

MAX_MASK_SIZE = 128
"""Largest side of a void-and-cluster mask: its cost grows as size**4 (128 takes a second)."""

MAX_OVERLAP_PAIRS = 2**21
"""Most pairs of a polyline's segments within a stroke's width of each other that the exact
stroke examines (a line of text has a few thousand; a path running over itself hundreds of
times, millions)."""

MAX_HANDOUT_POINTS = 500
"""Most control points the handouts' point-by-point Python loops are given: N (N - 1) / 2
interpolations, 125,000 at most, a fraction of a second."""

MAX_BAYER_SIZE = 2**11
"""Largest side of a Bayer matrix: its size**2 entries stay within MAX_PIXELS / 2 (4 M
thresholds, far more levels than any image has)."""

MAX_TEXT_LENGTH = 1000
"""Most characters of a line of text turned into curves."""

MAX_TYPED_TEXT = 4000
"""Most characters an app's text box reads (points, a kernel): a hundred points written with
long decimals. Longer text is refused before it is parsed."""

MAX_STROKED_TEXT = 160
"""Largest ``len(text) * size`` (characters times pixels to the em) of a line of text a
figure strokes and compares with the exact coverage, which samples 64 x 64 points in every
pixel along the outlines: 'Bé' at 40 px, the lesson's, is 80."""

MAX_CALLS = 2_000_000
"""Most calls a deliberately exponential handout recursion may make."""

SMALLEST = 1e-15
"""Smallest positive real accepted for a tolerance, step, width or scale."""

LARGEST = 1e12
"""Largest real accepted for a tolerance, step, width or scale."""


# --- the bounds on a call's work, checked before any is done ---------------------------------


def require_bounded_flattening(control: np.ndarray, tolerance: float, max_step: float) -> None:
    """ValueError unless flattening needs at most ``MAX_SAMPLES`` vertices.

    Wang's formula bounds the segments needed for ``tolerance``; the control
    polygon's length over ``max_step`` bounds those needed for ``max_step``.
    """
    degree = len(control) - 1
    with np.errstate(over="ignore", invalid="ignore"):
        needed = 1.0
        if degree >= 2:
            second = np.linalg.norm(np.diff(control, n=2, axis=0), axis=1).max()
            needed = max(needed, np.sqrt(degree * (degree - 1) * second / (8 * tolerance)))
        if degree >= 1 and np.isfinite(max_step):
            length = np.linalg.norm(np.diff(control, axis=0), axis=1).sum()
            needed = max(needed, length / max_step)
    if not needed <= MAX_SAMPLES:
        raise ValueError(
            _(
                "points, tolerance and max_step would need about {needed:.3g} vertices, more than "
                "the {limit} allowed; raise tolerance (or max_step), or bring the control points "
                "closer together"
            ).format(needed=needed, limit=MAX_SAMPLES)
        )
    # Degree 4 and up is evaluated by de Casteljau, (degree + 1)**2 / 2 steps a vertex.
    if degree >= 4 and not needed * (degree + 1) ** 2 <= MAX_EVALUATION_WORK:
        raise ValueError(
            _(
                "points: a curve of {count} control points within this tolerance would need about "
                "{needed:.3g} vertices of {work} interpolations each, more than the {limit} "
                "allowed; split the curve into pieces of low degree, or raise tolerance"
            ).format(
                count=degree + 1,
                needed=needed,
                work=(degree + 1) ** 2,
                limit=MAX_EVALUATION_WORK,
            )
        )


def require_step_samples(step: float, name: str = "step", curves: int = 1) -> None:
    """ValueError unless a t step gives at most ``MAX_STEP_SAMPLES`` samples in all.

    ``curves`` curves are each sampled at t = 0, step, 2 step, ... <= 1.
    """
    count = (np.floor(1 / step * (1 + 1e-12)) + 2) * curves
    if count > MAX_STEP_SAMPLES:
        per_curve = _(" over {curves} curves").format(curves=curves) if curves > 1 else ""
        room = MAX_STEP_SAMPLES / curves - 2
        smallest = _(", a step of at least {step:.3g}").format(step=1 / room) if room >= 1 else ""
        raise ValueError(
            _(
                "{name} must give at most {limit} samples{per_curve}{smallest}; got {step:g}, "
                "which gives about {count:.3g}"
            ).format(
                name=name,
                limit=MAX_STEP_SAMPLES,
                per_curve=per_curve,
                smallest=smallest,
                step=step,
                count=count,
            )
        )


def require_bounded_evaluation(points: int, samples: int, name: str = "points") -> None:
    """ValueError unless ``samples`` evaluations of a curve of ``points`` control points fit
    ``MAX_EVALUATION_WORK`` interpolations (de Casteljau's (N + 1)**2 / 2 per sample)."""
    work = float(samples) * points**2
    if work > MAX_EVALUATION_WORK:
        raise ValueError(
            _(
                "{name}: {samples} samples of a curve of {points} control points would take about "
                "{work:.3g} interpolations, more than the {limit} allowed; split the curve into "
                "pieces of low degree, or raise the tolerance or step"
            ).format(
                name=name,
                samples=samples,
                points=points,
                work=work,
                limit=MAX_EVALUATION_WORK,
            )
        )
