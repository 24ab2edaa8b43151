"""Flattening behind :func:`course.curves.flattening.flatten`: pure array code on validated input.

Nothing here checks its input: ``control`` is a finite float ``(N, d)`` array,
``tolerance`` a float > 0 and ``max_step`` a float > 0 or ``inf``, as
:func:`course.curves.flattening.flatten` makes sure before it calls :func:`flatten_curve`.

How the parameters are chosen, by degree:

* 2: Levien's analytic subdivision [1]_. The quadratic is an affine image of
  a piece of the parabola y = x^2; there, a chord over a short x interval
  ``dx`` around ``x`` is ``dx^2 / (4 sqrt(1 + 4 x^2))`` away from the curve,
  so the number of segments a tolerance needs is close to the integral of
  ``(1 + 4 x^2)^(-1/4)`` over ``2 sqrt(tolerance)`` (in the parabola's
  units), and that integral and its inverse have accurate closed-form
  approximations. The count is the integral over the curve, rounded up,
  and the vertices sit where it crosses equal fractions.
* 3: as kurbo does [2]_: the cubic is cut at equal steps of t into
  quadratics within a tenth of the tolerance of it, the quadratics'
  integrals are added up and the vertices placed where the sum crosses equal
  fractions, with the other nine tenths of the tolerance. (The midpoint
  quadratic of a cubic differs from it, at the same t, by ``(P3 - 3 P2 + 3
  P1 - P0) t (1 - t) (1 - 2 t) / 2``, at most ``sqrt(3) / 36`` of that
  third difference, which falls with the cube of the step.) The vertices
  are points of the cubic itself, at the same t.
* 1: the chord; 0: the point; 4 and more: bisection at t = 1/2 until every
  control point of a piece is within the tolerance of its chord (the piece
  lies in their convex hull).

Levien's count and spacing come from approximations, so for degrees 1 to 3
each segment's distance to the curve is then computed: the piece over the
segment is a cubic C0..C3 in its own parameter, and when C1 and C2 project
inside the chord its distance is the largest value of a cubic polynomial,
at a root of its derivative (exact in the plane, an upper bound in other
dimensions); when they do not, the convex hull of C0..C3 bounds it
(:func:`cubic_chord_errors`). The count is lowered while
the same spacing with fewer segments still passes (the estimate rounds up
and leaves most segments a little inside the tolerance), and segments
beyond the tolerance or longer than ``max_step`` are split at equal steps
of t and checked again.

References
----------
.. [1] R. Levien, "Flattening quadratic Béziers", 2019,
   https://raphlinus.github.io/graphics/curves/2019/12/23/flatten-quadbez.html
.. [2] kurbo, ``flatten`` (src/bezpath.rs), ``QuadBez::estimate_subdiv``
   (src/quadbez.rs) and ``CubicBez::to_quads`` (src/cubicbez.rs),
   https://github.com/linebender/kurbo
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable

import numpy as np

from course.curves._bezier_fast import de_casteljau_chunked

# kurbo's TO_QUAD_TOL: the share of the tolerance spent on replacing a cubic by
# quadratics. A smaller share means more quadratics but a count closer to the
# cubic's own; a tenth costs about 5% more segments than a perfect fit.
_QUAD_SHARE = 0.1
# sqrt(3) / 36: the largest distance from a cubic to its midpoint quadratic,
# at the same t, per unit of the third difference P3 - 3 P2 + 3 P1 - P0.
_MIDPOINT_QUADRATIC_ERROR = math.sqrt(3) / 36
# Each round cuts every failing segment into two or more; after this many they
# are below float64 resolution of t and further splitting cannot help.
_MAX_ROUNDS = 60
# Each bisection halves the parameter interval; the same limit for degree >= 4.
_MAX_SUBDIVISIONS = 52
# Fewer segments of Levien's spacing are tried when the square law of the
# errors of short segments, relaxed by these factors, lets them pass: it
# overstates how fast errors grow when a curve has few segments (two instead
# of four on a hairpin quadratic measured 0.7 of its prediction, one instead
# of two on glyph curves 0.9). Up to _FEW_SEGMENTS every smaller count is
# tried, beyond it one Newton step on the count at a time.
_FEWER_ALLOWANCE = 1.25
_FEW_ALLOWANCE = 2.0
_FEW_SEGMENTS = 4
# Levien's constants for the integral and its inverse (kurbo's D and B).
_INTEGRAL_D = 0.67
_INVERSE_B = 0.39


def flatten_curve(
    control: np.ndarray, tolerance: float, max_step: float
) -> tuple[np.ndarray, np.ndarray]:
    """(vertices (K, d), parameters (K,)) of a polyline within ``tolerance``."""
    count = len(control)
    if count == 1:
        return control.copy(), np.zeros(1)
    if count > 4:
        return flatten_by_bisection(control, tolerance, max_step)
    curve = Measured(control)
    t, points, errors = levien_parameters(curve, tolerance)
    return refine(curve, t, points, errors, tolerance, max_step)


class Measured:
    """A curve of degree 1 to 3 and its hodograph, to measure polylines against."""

    def __init__(self, control: np.ndarray) -> None:
        self.control = control
        self.hodograph = (len(control) - 1) * np.diff(control, axis=0)

    def measure(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The vertices B(t) and each segment's distance to the curve (a bound, see
        :func:`cubic_chord_errors`)."""
        points = de_casteljau_chunked(self.control, t)
        speeds = de_casteljau_chunked(self.hodograph, t)
        return points, cubic_chord_errors(points, speeds, np.diff(t))


def chord_errors(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Each segment's distance to the curve, degrees 1 to 3 (:func:`cubic_chord_errors`)."""
    return Measured(control).measure(t)[1]


def levien_parameters(
    curve: Measured, tolerance: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Levien's vertices (t, B(t), segment errors), as few as his placement allows.

    His count rounds an approximate integral up, and his placement leaves
    most segments a little inside the tolerance. The errors of short
    segments grow with the square of their width, so when the largest exact
    error is a fraction ``r`` of the tolerance, the same placement with
    ``ceil(count * sqrt(r))`` segments (at least one fewer) is tried and
    kept if it passes, and so on until one fails; a count of 4 or less
    tries each smaller count instead, smallest first.
    """
    control = curve.control
    if len(control) == 2:
        t = np.array([0.0, 1.0])
        return (t, *curve.measure(t))
    plan = quadratic_plan if len(control) == 3 else cubic_plan
    count, place = plan(control, tolerance)
    t = place(count)
    points, errors = curve.measure(t)
    ratio = float(errors.max()) / tolerance
    if ratio > 1.0:
        # Beyond the tolerance somewhere (kurbo's cubics, near an inflection):
        # fewer would not pass; refine() splits those few segments.
        return t, points, errors
    if count <= _FEW_SEGMENTS:
        # Too few for the square law: an odd count can leave one segment
        # across a tight bend that an even count cuts at its tip.
        for fewer in range(1, count):
            if ratio * (count / fewer) ** 2 <= _FEW_ALLOWANCE:
                candidate = place(fewer)
                candidate_points, candidate_errors = curve.measure(candidate)
                if candidate_errors.max() <= tolerance:
                    return candidate, candidate_points, candidate_errors
        return t, points, errors
    while count > 1:
        fewer = min(count - 1, math.ceil(count * math.sqrt(ratio)))
        if ratio * (count / fewer) ** 2 > _FEWER_ALLOWANCE:
            break
        candidate = place(fewer)
        candidate_points, candidate_errors = curve.measure(candidate)
        candidate_ratio = float(candidate_errors.max()) / tolerance
        if candidate_ratio > 1.0:
            break
        count, t, points, errors = fewer, candidate, candidate_points, candidate_errors
        ratio = candidate_ratio
    return t, points, errors


# --- Levien's subdivision of a quadratic -------------------------------------


def parabola_integral(x: np.ndarray) -> np.ndarray:
    """Levien's approximation of the integral of ``(1 + 4 x^2)^(-1/4)`` from 0 to x."""
    return x / (1.0 - _INTEGRAL_D + np.sqrt(np.sqrt(_INTEGRAL_D**4 + 0.25 * x * x)))


def parabola_inverse_integral(a: np.ndarray) -> np.ndarray:
    """Levien's approximation of the inverse of :func:`parabola_integral`."""
    return a * (1.0 - _INVERSE_B + np.sqrt(_INVERSE_B**2 + 0.25 * a * a))


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise dot products of (K, d) arrays, one coordinate at a time.

    ``np.sum(a * b, axis=1)`` reduces over a short axis and is several times
    slower for the few coordinates of a point.
    """
    total = a[:, 0] * b[:, 0]
    for axis in range(1, a.shape[1]):
        total += a[:, axis] * b[:, axis]
    return total


def _norm(a: np.ndarray) -> np.ndarray:
    """Row-wise lengths of a (K, d) array."""
    return np.sqrt(_dot(a, a))


def _cross_norm(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """|a x b| row by row in any dimension: the area of the parallelogram."""
    if a.shape[1] == 2:
        return np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    total = np.zeros(len(a))
    for first, second in itertools.combinations(range(a.shape[1]), 2):
        total += (a[:, first] * b[:, second] - a[:, second] * b[:, first]) ** 2
    return np.sqrt(total)


def parabola_subdivision(
    start: np.ndarray, middle: np.ndarray, end: np.ndarray, sqrt_tolerance: float
) -> tuple[np.ndarray, ...]:
    """Levien's ``estimate_subdiv`` for K quadratics at once, each row one curve.

    Returns ``(value, a0, a2, u0, u_scale)``: ``value / (2 sqrt(tolerance))``
    is the number of segments the quadratic needs, and the other four map a
    fraction of that number to the curve's t (:func:`subdivision_parameters`).
    A straight quadratic (no area) gets value 0.
    """
    d01 = middle - start
    d12 = end - middle
    dd = d01 - d12
    cross = _cross_norm(end - start, dd)
    dd_norm = _norm(dd)
    curved = cross > 0
    safe_cross = np.where(curved, cross, 1.0)
    # The curve is the parabola y = x^2 from x0 to x2, rotated and scaled;
    # the scale (its size over the unit parabola's) is cross^2 / |dd|^3.
    x0 = np.where(curved, _dot(d01, dd) / safe_cross, 0.0)
    x2 = np.where(curved, _dot(d12, dd) / safe_cross, 0.0)
    scale = np.where(curved, cross**2 / np.where(curved, dd_norm, 1.0) ** 3, 0.0)
    a0, a2 = parabola_integral(x0), parabola_integral(x2)
    spread = np.abs(a2 - a0)
    sqrt_scale = np.sqrt(scale)
    # The parabola's vertex (its curvature maximum) inside the curve: near it
    # the density is capped by the tolerance, as if the integral began at x_min.
    with np.errstate(divide="ignore", invalid="ignore"):
        x_min = sqrt_tolerance / sqrt_scale
        cusp_value = sqrt_tolerance * spread / parabola_integral(x_min)
    same_side = np.signbit(x0) == np.signbit(x2)
    value = np.where(same_side, spread * sqrt_scale, cusp_value)
    value = np.where(curved & np.isfinite(value), value, 0.0)
    u0, u2 = parabola_inverse_integral(a0), parabola_inverse_integral(a2)
    span = u2 - u0
    u_scale = np.where(span != 0, 1.0 / np.where(span != 0, span, 1.0), 0.0)
    return value, a0, a2, u0, u_scale


def subdivision_parameters(
    a0: np.ndarray, a2: np.ndarray, u0: np.ndarray, u_scale: np.ndarray, fraction: np.ndarray
) -> np.ndarray:
    """Levien's ``determine_subdiv_t``: the t where the integral reaches ``fraction``."""
    u = parabola_inverse_integral(a0 + (a2 - a0) * fraction)
    return (u - u0) * u_scale


def segment_count(value: float, sqrt_tolerance: float) -> int:
    """Levien's count for an integral ``value``: ``ceil(value / (2 sqrt(tolerance)))``, >= 1."""
    return max(1, math.ceil(0.5 * value / sqrt_tolerance))


Placement = Callable[[int], np.ndarray]


def quadratic_plan(control: np.ndarray, tolerance: float) -> tuple[int, Placement]:
    """Levien's count for a quadratic, and his vertices' t for any count."""
    sqrt_tolerance = math.sqrt(tolerance)
    value, a0, a2, u0, u_scale = parabola_subdivision(
        control[:1], control[1:2], control[2:], sqrt_tolerance
    )

    def place(count: int) -> np.ndarray:
        fraction = np.arange(1, count) / count
        return _with_ends(subdivision_parameters(a0, a2, u0, u_scale, fraction))

    return segment_count(float(value[0]), sqrt_tolerance), place


def cubic_plan(control: np.ndarray, tolerance: float) -> tuple[int, Placement]:
    """kurbo's count for a cubic through quadratics, and the vertices' t for any count."""
    third = control[3] - 3.0 * control[2] + 3.0 * control[1] - control[0]
    error = _MIDPOINT_QUADRATIC_ERROR * float(np.sqrt(np.sum(third**2)))
    # The midpoint quadratic's error falls with the cube of the step in t.
    pieces = max(1, math.ceil((error / (_QUAD_SHARE * tolerance)) ** (1 / 3)))
    edges = np.arange(pieces + 1) / pieces
    points = de_casteljau_chunked(control, edges)
    speeds = de_casteljau_chunked(3.0 * np.diff(control, axis=0), edges)
    starts, ends = points[:-1], points[1:]
    # The piece's cubic controls are start + h/3 B'(a) and end - h/3 B'(b);
    # the midpoint quadratic's middle is (3 (C1 + C2) - C0 - C3) / 4.
    middles = 0.5 * (starts + ends) + (0.25 / pieces) * (speeds[:-1] - speeds[1:])
    sqrt_tolerance = math.sqrt((1.0 - _QUAD_SHARE) * tolerance)
    value, a0, a2, u0, u_scale = parabola_subdivision(starts, middles, ends, sqrt_tolerance)
    total = float(value.sum())
    running = np.concatenate([[0.0], np.cumsum(value)])

    def place(count: int) -> np.ndarray:
        # Vertex i where the running sum of the quadratics' integrals reaches i / count.
        targets = np.arange(1, count) * (total / count)
        which = np.clip(np.searchsorted(running, targets, side="right") - 1, 0, pieces - 1)
        own = value[which]
        fraction = (targets - running[which]) / np.where(own > 0, own, 1.0)
        local = subdivision_parameters(a0[which], a2[which], u0[which], u_scale[which], fraction)
        # The quadratic over [i / pieces, (i + 1) / pieces] shares the cubic's t there.
        return _with_ends((which + local) / pieces)

    return segment_count(total, sqrt_tolerance), place


def _with_ends(interior: np.ndarray) -> np.ndarray:
    """0, the distinct values strictly inside (0, 1) in order, 1."""
    inside = np.unique(interior)
    inside = inside[(inside > 0.0) & (inside < 1.0)]
    return np.concatenate([[0.0], inside, [1.0]])


# --- the check every segment passes --------------------------------------------


def cubic_chord_errors(points: np.ndarray, speeds: np.ndarray, widths: np.ndarray) -> np.ndarray:
    """Distance from each piece of a curve of degree <= 3 to its chord.

    ``points`` and ``speeds`` (K + 1, d) are B and B' at the vertices and
    ``widths`` (K,) the t steps: piece i is the cubic C0 = B(a), C1 = B(a) +
    h B'(a) / 3, C2 = B(b) - h B'(b) / 3, C3 = B(b) (exact up to degree 3).
    When C1 and C2 project inside the chord, so does the whole piece, and
    its distance to the chord is the largest |f(s)| of ``f(s) = 3 s (1 - s)
    ((1 - s) d1 + s d2)``, d1 and d2 the distances of C1 and C2 from the
    chord's line (signed in the plane, so that this is exact; unsigned in
    other dimensions, an upper bound). Otherwise the farther of C1 and C2
    from the segment bounds it: the piece lies in their convex hull.
    """
    third = widths[:, None] / 3.0
    chord = points[1:] - points[:-1]
    first = third * speeds[:-1]  # C1 - C0
    second = chord - third * speeds[1:]  # C2 - C0
    length2 = _dot(chord, chord)
    safe_length2 = np.where(length2 > 0, length2, 1.0)
    along1 = _dot(first, chord) / safe_length2
    along2 = _dot(second, chord) / safe_length2
    if chord.shape[1] == 2:
        length = np.sqrt(safe_length2)
        d1 = (chord[:, 0] * first[:, 1] - chord[:, 1] * first[:, 0]) / length
        d2 = (chord[:, 0] * second[:, 1] - chord[:, 1] * second[:, 0]) / length
    else:
        d1 = _norm(first - along1[:, None] * chord)
        d2 = _norm(second - along2[:, None] * chord)
    errors = _largest_bump(d1, d2)
    beside = (length2 > 0) & (np.minimum(along1, along2) >= 0) & (np.maximum(along1, along2) <= 1)
    if not beside.all():
        where = np.flatnonzero(~beside)
        errors[where] = np.maximum(
            _distance_to_segment(first[where], chord[where], along1[where]),
            _distance_to_segment(second[where], chord[where], along2[where]),
        )
    return errors


def _distance_to_segment(offset: np.ndarray, chord: np.ndarray, along: np.ndarray) -> np.ndarray:
    """Distance of start + offset to the segment start -> start + chord."""
    return _norm(offset - np.fmax(np.fmin(along, 1.0), 0.0)[:, None] * chord)


def _largest_bump(d1: np.ndarray, d2: np.ndarray) -> np.ndarray:
    """max over s in [0, 1] of |3 s (1 - s) ((1 - s) d1 + s d2)|, elementwise."""
    # Where the derivative vanishes: a s^2 + b s + c = 0 with a = 3 (d2 - d1),
    # b = 2 (2 d1 - d2), c = -d1, whose discriminant 4 (d1^2 - d1 d2 + d2^2)
    # is never negative. The stable pair of roots: q / a and c / q.
    a = 3.0 * (d2 - d1)
    b = 2.0 * (2.0 * d1 - d2)
    root = 2.0 * np.sqrt(d1 * d1 - d1 * d2 + d2 * d2)
    q = -0.5 * (b + np.copysign(root, b))
    with np.errstate(divide="ignore", invalid="ignore"):
        first, second = q / a, -d1 / q
    largest = np.zeros_like(d1)
    for s in (first, second):
        # Roots outside [0, 1], infinite or NaN (d1 = d2) land on an end, where
        # f is 0: fmin and fmax pass NaN over.
        s = np.fmax(np.fmin(s, 1.0), 0.0)
        np.maximum(largest, np.abs(3.0 * s * (1.0 - s) * (d1 + s * (d2 - d1))), out=largest)
    return largest


def refine(
    curve: Measured,
    t: np.ndarray,
    points: np.ndarray,
    errors: np.ndarray,
    tolerance: float,
    max_step: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Split the segments beyond the tolerance or ``max_step`` until none is: (B(t), t)."""
    for _ in range(_MAX_ROUNDS):
        # The error of a short piece grows with the square of its width.
        pieces = np.where(
            errors > tolerance, np.maximum(2.0, np.ceil(np.sqrt(errors / tolerance))), 1.0
        )
        if max_step < np.inf:
            lengths = _norm(np.diff(points, axis=0))
            pieces = np.maximum(pieces, np.ceil(lengths / max_step))
        if np.all(pieces == 1):
            break
        refined = _split_evenly(t, pieces.astype(np.int64))
        if len(refined) == len(t):  # every split is below float resolution of t
            break
        t = refined
        points, errors = curve.measure(t)
    return points, t


def _split_evenly(t: np.ndarray, pieces: np.ndarray) -> np.ndarray:
    """Segment i of ``t`` cut into ``pieces[i]`` equal steps; distinct values only."""
    starts = np.repeat(t[:-1], pieces)
    steps = np.repeat(np.diff(t) / pieces, pieces)
    index = np.arange(pieces.sum()) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    return np.unique(np.concatenate([starts + index * steps, t[-1:]]))


# --- bisection, for degree 4 and more ------------------------------------------


def flatten_by_bisection(
    control: np.ndarray, tolerance: float, max_step: float
) -> tuple[np.ndarray, np.ndarray]:
    """Split at t = 1/2 until every control point of a piece is within tolerance of its chord.

    The piece lies in the convex hull of its control points, so then the
    whole piece is within the tolerance of the chord.
    """
    # All pieces at one depth are tested and split together, as arrays:
    # pieces (K, N, d) with parameter intervals [start, start + width).
    pieces = control[None]
    starts = np.zeros(1)
    width = 1.0
    done_pieces, done_starts, done_widths = [], [], []
    for depth in range(_MAX_SUBDIVISIONS + 1):
        flat = _is_flat(pieces, tolerance, max_step) | (depth == _MAX_SUBDIVISIONS)
        done_pieces.append(pieces[flat])
        done_starts.append(starts[flat])
        done_widths.append(np.full(int(flat.sum()), width))
        pieces, starts = pieces[~flat], starts[~flat]
        if len(pieces) == 0:
            break
        left, right = _split_half(pieces)
        width /= 2
        pieces = np.concatenate([left, right])
        starts = np.concatenate([starts, starts + width])
    all_pieces = np.concatenate(done_pieces)
    all_starts = np.concatenate(done_starts)
    order = np.argsort(all_starts)
    all_pieces = all_pieces[order]
    vertices = np.vstack([all_pieces[:, 0], all_pieces[-1:, -1]])
    ends = np.concatenate(done_widths)[order] + all_starts[order]
    parameters = np.concatenate([all_starts[order], ends[-1:]])
    return vertices, parameters


def _is_flat(pieces: np.ndarray, tolerance: float, max_step: float) -> np.ndarray:
    """Which pieces have every control point within tolerance of their chord."""
    start, end = pieces[:, :1], pieces[:, -1:]
    chord = end - start
    length2 = np.sum(chord**2, axis=-1)
    offsets = pieces - start
    safe = np.where(length2 > 0, length2, 1.0)
    u = np.clip(np.sum(offsets * chord, axis=-1) / safe, 0.0, 1.0)
    u = np.where(length2 > 0, u, 0.0)
    distance2 = np.sum((offsets - u[..., None] * chord) ** 2, axis=-1)
    flat = distance2.max(axis=1) <= tolerance**2
    return flat & (length2[:, 0] <= max_step**2)


def _split_half(pieces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Split (K, N, d) pieces at t = 1/2: de Casteljau along axis 1."""
    count = pieces.shape[1]
    left = np.empty_like(pieces)
    right = np.empty_like(pieces)
    level = pieces
    for k in range(count):
        left[:, k] = level[:, 0]
        right[:, count - 1 - k] = level[:, -1]
        level = 0.5 * (level[:, :-1] + level[:, 1:])
    return left, right
