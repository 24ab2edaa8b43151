"""Real curves for the flattening benchmark, and how a polyline is measured against them.

Curves: the quadratic segments of DejaVu Sans glyphs (matplotlib's bundled
TrueType font, through ``matplotlib.textpath.TextPath``) and the cubic
segments of the SVG icons bundled with matplotlib
(``mpl-data/images/*.svg``, read with a small path-data parser), each icon
scaled to a few hundred pixels.

Measures: the distance of each piece of the curve, sampled densely in t, to
its chord; the fewest segments of a uniform t step within a tolerance; and
Levien's segment count (the anchor of the best achievable count), written
out here from kurbo's ``estimate_subdiv`` and ``flatten`` one curve at a
time, independently of :mod:`course.curves._flatten`.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import matplotlib
import numpy as np
from matplotlib.font_manager import FontProperties
from matplotlib.textpath import TextPath

from course.curves.bezier import de_casteljau

GLYPH_TEXT = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789&@%$§?"
GLYPH_SIZE = 200.0
ICON_SIZE = 400.0
SAMPLES_PER_PIECE = 256


# --- curves --------------------------------------------------------------------


def glyph_quadratics(text: str = GLYPH_TEXT, size: float = GLYPH_SIZE) -> list[np.ndarray]:
    """The quadratic segments (3, 2) of each glyph of ``text`` in DejaVu Sans."""
    font = FontProperties(family="DejaVu Sans")
    curves = []
    for character in text:
        path = TextPath((0.0, 0.0), character, size=size, prop=font)
        for segment, _ in path.iter_bezier(simplify=False):
            if len(segment.control_points) == 3:
                curves.append(np.array(segment.control_points, dtype=float))
    return curves


def icon_cubics(size: float = ICON_SIZE) -> list[np.ndarray]:
    """The distinct cubic segments (4, 2) of matplotlib's SVG icons, each icon ``size`` px."""
    folder = Path(matplotlib.get_data_path()) / "images"
    seen, curves = set(), []
    for svg in sorted(folder.glob("*.svg")):
        icon = [
            segment
            for data in re.findall(r'\sd="([^"]*)"', svg.read_text())
            for segment in parse_path(data)
        ]
        corners = np.concatenate(icon) if icon else np.zeros((1, 2))
        extent = float(np.ptp(corners, axis=0).max()) or 1.0
        origin = corners.min(axis=0)
        for segment in icon:
            if len(segment) != 4:
                continue
            scaled = (segment - origin) * (size / extent)
            key = tuple(np.round(scaled, 6).ravel())
            if key not in seen:  # the "-symbolic" icons repeat the others
                seen.add(key)
                curves.append(scaled)
    return curves


_TOKEN = re.compile(r"[MmLlHhVvCcSsQqTtZz]|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
_ARGUMENTS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "Z": 0}


def parse_path(data: str) -> list[np.ndarray]:
    """Segments of SVG path data (M L H V C S Q T Z, absolute and relative).

    Lines come out as (2, 2) arrays, quadratics (3, 2), cubics (4, 2). Arcs
    (A) are not supported and raise ValueError.
    """
    tokens = _TOKEN.findall(data)
    if re.search(r"[Aa]", data):
        raise ValueError("arcs (A) are not supported")
    segments: list[np.ndarray] = []
    current = start = np.zeros(2)
    previous_command, reflected = "", None
    index, command = 0, ""
    while index < len(tokens):
        if tokens[index].isalpha():
            command = tokens[index]
            index += 1
        elif command in ("M", "m"):  # coordinates after a moveto are linetos
            command = "L" if command == "M" else "l"
        upper = command.upper()
        count = _ARGUMENTS[upper]
        values = [float(value) for value in tokens[index : index + count]]
        index += count
        origin = current if command.islower() else np.zeros(2)
        relative = command.islower()

        def point(x: float, y: float, origin: np.ndarray = origin) -> np.ndarray:
            return np.array([x, y]) + origin

        if upper == "M":
            current = start = point(*values)
        elif upper == "Z":
            if not np.array_equal(current, start):
                segments.append(np.array([current, start]))
            current = start
        elif upper in ("L", "H", "V"):
            if upper == "H":
                end = np.array([values[0] + (current[0] if relative else 0.0), current[1]])
            elif upper == "V":
                end = np.array([current[0], values[0] + (current[1] if relative else 0.0)])
            else:
                end = point(*values)
            segments.append(np.array([current, end]))
            current = end
        elif upper in ("C", "S"):
            if upper == "C":
                first, second, end = point(*values[:2]), point(*values[2:4]), point(*values[4:])
            else:
                smooth = previous_command in ("C", "S") and reflected is not None
                first = 2 * current - reflected if smooth else current
                second, end = point(*values[:2]), point(*values[2:])
            segments.append(np.array([current, first, second, end]))
            reflected, current = second, end
        else:  # Q, T
            if upper == "Q":
                middle, end = point(*values[:2]), point(*values[2:])
            else:
                smooth = previous_command in ("Q", "T") and reflected is not None
                middle = 2 * current - reflected if smooth else current
                end = point(*values)
            segments.append(np.array([current, middle, end]))
            reflected, current = middle, end
        previous_command = upper
    return segments


# --- measures --------------------------------------------------------------------


def piece_errors(
    points: np.ndarray,
    t: np.ndarray,
    vertices: np.ndarray | None = None,
    samples: int = SAMPLES_PER_PIECE,
) -> np.ndarray:
    """For each segment of a polyline: the largest distance from ``samples``
    points of the curve, evenly spaced over the segment's t interval, to the
    segment. The vertices are B(t) unless given."""
    fraction = np.linspace(0.0, 1.0, samples)
    dense_t = (t[:-1, None] + np.diff(t)[:, None] * fraction).ravel()
    dense = de_casteljau(points, dense_t).reshape(len(t) - 1, samples, -1)
    ends = de_casteljau(points, t) if vertices is None else vertices
    start, chord = ends[:-1, None], np.diff(ends, axis=0)[:, None]
    length2 = np.maximum(np.sum(chord**2, axis=2), 1e-300)
    along = np.clip(np.sum((dense - start) * chord, axis=2) / length2, 0.0, 1.0)
    return np.sqrt(np.sum((dense - start - along[..., None] * chord) ** 2, axis=2)).max(axis=1)


def uniform_error(points: np.ndarray, count: int) -> float:
    return float(piece_errors(points, np.linspace(0.0, 1.0, count + 1)).max())


def fewest_uniform_segments(points: np.ndarray, tolerance: float) -> int:
    """The smallest n whose uniform polyline B(k / n) is within ``tolerance``.

    The error falls as n grows, so n is found by doubling and then bisection.
    """
    high = 1
    while uniform_error(points, high) > tolerance:
        high *= 2
    low = high // 2  # fails, or 0
    while high - low > 1:
        middle = (low + high) // 2
        if uniform_error(points, middle) > tolerance:
            low = middle
        else:
            high = middle
    return high


def _parabola_integral(x: float) -> float:
    return x / (1 - 0.67 + math.sqrt(math.sqrt(0.67**4 + 0.25 * x * x)))


def levien_value(p0: np.ndarray, p1: np.ndarray, p2: np.ndarray, sqrt_tol: float) -> float:
    """kurbo's ``QuadBez::estimate_subdiv(sqrt_tol).val``, one quadratic."""
    d01, d12 = p1 - p0, p2 - p1
    dd = d01 - d12
    chord = p2 - p0
    cross = chord[0] * dd[1] - chord[1] * dd[0]
    if cross == 0:
        return 0.0
    x0 = float(np.dot(d01, dd)) / cross
    x2 = float(np.dot(d12, dd)) / cross
    scale = abs(cross / (math.hypot(*dd) * (x2 - x0)))
    a0, a2 = _parabola_integral(x0), _parabola_integral(x2)
    if not math.isfinite(scale):
        return 0.0
    da = abs(a2 - a0)
    sqrt_scale = math.sqrt(scale)
    if math.copysign(1, x0) == math.copysign(1, x2):
        return da * sqrt_scale
    x_min = sqrt_tol / sqrt_scale
    return sqrt_tol * da / _parabola_integral(x_min)


def levien_segments(points: np.ndarray, tolerance: float) -> int:
    """Levien's count (kurbo's ``flatten``) for a quadratic or a cubic.

    A cubic goes through kurbo's ``to_quads(tolerance / 10)``: n equal steps
    of t with ``sqrt(3) / 36 |P3 - 3 P2 + 3 P1 - P0| / n^3`` within a tenth of
    the tolerance, each replaced by its midpoint quadratic; the quadratics'
    values are added and the other nine tenths of the tolerance used.
    """
    if len(points) == 3:
        sqrt_tol = math.sqrt(tolerance)
        return max(1, math.ceil(0.5 * levien_value(*points, sqrt_tol) / sqrt_tol))
    p0, p1, p2, p3 = points
    third = float(np.hypot(*(p3 - 3 * p2 + 3 * p1 - p0)))
    quads = max(1, math.ceil((third / (432**0.5 * 0.1 * tolerance)) ** (1 / 3)))
    sqrt_tol = math.sqrt(0.9 * tolerance)
    total = 0.0
    for i in range(quads):
        a, b = i / quads, (i + 1) / quads
        start, end = de_casteljau(points, a), de_casteljau(points, b)
        speeds = de_casteljau(3 * np.diff(points, axis=0), [a, b])
        c1 = start + (b - a) / 3 * speeds[0]
        c2 = end - (b - a) / 3 * speeds[1]
        middle = (3 * (c1 + c2) - start - end) / 4
        total += levien_value(start, middle, end, sqrt_tol)
    return max(1, math.ceil(0.5 * total / sqrt_tol))
