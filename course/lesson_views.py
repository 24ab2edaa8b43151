"""Each lesson's key pictures and slider landmarks, built as its notebook builds them.

:mod:`course.lessons` registers, per lesson, pictures (for the gallery and
the course map) and a slider the browser tests move. This module makes
them: every picture calls the library's functions or apps with the
notebook's own arguments, and every landmark function computes, with the
library and not from the app's artists, pixels of the app's picture whose
colour is then known for the value the slider shows (lesson 03: the
Bresenham pixels where ``course.raster.line`` puts them, black on white;
lesson 06: every pixel of the flat patch as ``course.dither`` dithers it).
Each is chosen so that the picture one slider stop away fails it
(``tests/test_lessons.py`` checks that after every registered move). A
landmark inside a pixel of a zoomed view sits at the point of that pixel
farthest from any line drawn over it, so the overlay cannot hide it.
"""

from __future__ import annotations

import functools
import itertools
from dataclasses import replace
from typing import Any

import matplotlib
import numpy as np

from course import dither, filters, images, poisson
from course.aa_metrics import variants
from course.bezier import bernstein_basis, de_casteljau
from course.canvas import crop
from course.coverage import curve_polyline, reference, segment_distance
from course.raster import line, line_4connected, wu_line
from course.resample import supersample, supersample_without_offset
from course.showcase import (
    CRIMSON,
    Landmark,
    Picture,
    app_picture,
    figure_picture,
    gray_color,
    landmark_at,
    landmark_in_box,
)
from course.widgets import (
    BernsteinBasisApp,
    DeCasteljauApp,
    GrayLevelApp,
    PoissonIterationApp,
    RepeatedBlurApp,
    StepApp,
    SupersampleApp,
    TriangleApp,
    VoidAndClusterApp,
    ZoomApp,
)
from course.widgets.antialias import SEED_000_POINTS, CurveWalk, zoom_figure
from course.widgets.base import SliderApp
from course.widgets.de_casteljau import DEFAULT_POINTS, parse_points
from course.widgets.dithering import side_by_side
from course.widgets.filtering import blurred
from course.widgets.poisson import MARGIN, show_images

BLACK, WHITE = (0, 0, 0), (255, 255, 255)


def _colormap(name: str, value: float, low: float = 0.0, high: float = 1.0) -> tuple[int, ...]:
    """The RGB colour (0-255) of ``value`` on colormap ``name`` scaled from low to high."""
    rgba = matplotlib.colormaps[name]((value - low) / (high - low), bytes=True)
    return tuple(int(channel) for channel in rgba[:3])


def _rgb(value: Any) -> tuple[int, int, int]:
    """An RGB colour in [0, 1] as imshow shows it: 255 times, truncated to an integer."""
    red, green, blue = (int(channel * 255) for channel in np.clip(value, 0.0, 1.0))
    return (red, green, blue)


def _clear_point(column: int, row: int, segments: np.ndarray) -> tuple[float, float]:
    """The quarter point of pixel (column, row) farthest from ``segments`` (M, 2, 2).

    A pixel drawn as a flat square under a line (the true curve, the ideal
    line) shows its own colour there.
    """
    offsets = np.array([[0.25, 0.25], [0.75, 0.25], [0.25, 0.75], [0.75, 0.75]])
    candidates = np.array([column, row]) + offsets
    distance, _, _ = segment_distance(
        candidates[:, :1], candidates[:, 1:], segments[None, :, 0], segments[None, :, 1]
    )
    x, y = candidates[int(np.argmax(distance.min(axis=1)))]
    return float(x), float(y)


def _segments(polyline: np.ndarray) -> np.ndarray:
    return np.stack([polyline[:-1], polyline[1:]], axis=1)


def _frozen(array: np.ndarray) -> np.ndarray:
    array.flags.writeable = False
    return array


# --- Lesson 01: de Casteljau's algorithm --------------------------------------


def de_casteljau_landmarks(app: SliderApp) -> list[Landmark]:
    """The red dot B(t) where ``de_casteljau`` puts it."""
    points = parse_points(app.value("points"))
    t = float(app.value("t"))
    point = de_casteljau(points, t)
    return [landmark_at(app, app.axes, point, CRIMSON, f"B({t:.2f}) by de_casteljau")]


def de_casteljau_picture(t: float, count: int = 4) -> Picture:
    return Picture(
        f"01_de_casteljau_degree{count - 1}_t{t:.2f}",
        f"de Casteljau's levels for {count} control points at t = {t:.2f}",
        lambda: app_picture(DeCasteljauApp(points=DEFAULT_POINTS[:count], t=t)),
    )


# --- Lesson 02: the Bernstein form -------------------------------------------


def bernstein_landmarks(app: SliderApp) -> list[Landmark]:
    """Each basis function's marker at (t, B_i,n(t)) from ``bernstein_basis``."""
    degree, t = int(app.value("degree")), float(app.value("t"))
    weights = bernstein_basis(degree, t)[0]
    landmarks = []
    for i, weight in enumerate(weights):
        centre = landmark_at(app, app.axes, (t, weight), CRIMSON, f"B_{i},{degree}({t:.2f})")
        # The vertical line at t is crimson too: look 2 px to its right, still
        # inside the marker (radius about 2.8 px), where only the marker is red.
        landmarks.append(replace(centre, column=centre.column + 2))
    return landmarks


def bernstein_app() -> BernsteinBasisApp:
    return BernsteinBasisApp(degree=3, t=0.3)


def bernstein_picture(degree: int, t: float) -> Picture:
    return Picture(
        f"02_bernstein_degree{degree}_t{t:.2f}",
        f"the degree-{degree} Bernstein basis and its weights at t = {t:.2f}",
        lambda: app_picture(BernsteinBasisApp(degree=degree, t=t)),
    )


# --- Lesson 05: anti-aliasing a curve ----------------------------------------

SEED_000_SHAPE = (700, 700)
ZOOM_PICKS = ("bilinear_zero_offset", "bilinear_corners", "bilinear_centres")
# The variants the notebook zooms into, in its order (its "Every variant" cell).
ZOOMED_VARIANTS = (
    "nearest_round",
    "bilinear_zero_offset",
    "bilinear_corners",
    "bilinear_centres",
    "subsample_falloff",
    "normalised_centres",
    "stroke_linear",
    "stroke_area",
    "bilinear_centres + arc length",
    "nearest_truncate + arc length",
    "Agg (matplotlib)",
)


@functools.cache
def seed_000_renderings() -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Every variant of seed 000's test and the exact reference (k = 64), computed once."""
    points = np.array(SEED_000_POINTS)
    renderings = {name: _frozen(image) for name, image in variants(points, SEED_000_SHAPE).items()}
    exact = reference(points, SEED_000_SHAPE, width=1.0, k=64)
    return renderings, _frozen(exact)


def zoom_app() -> ZoomApp:
    """Lesson 05's first app, as its notebook builds it."""
    renderings, exact = seed_000_renderings()
    return ZoomApp(renderings, np.array(SEED_000_POINTS), exact, picks=ZOOM_PICKS)


def zoom_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of each panel: ``crop`` of the variant's rendering around the curve point.

    The window's centre is the point ``position`` of the way along the curve
    (by arc length); each panel must show ``crop(rendering, centre, size)``,
    the rendering as ``aa_metrics.variants`` and ``coverage.reference`` make it.
    """
    renderings, exact = seed_000_renderings()
    points = np.array(SEED_000_POINTS)
    position, size = float(app.value("position")), int(app.value("size"))
    centre = CurveWalk(points).at(position)
    segments = _segments(curve_polyline(points, 1e-3))
    shown = [(app.value(slot), renderings[app.value(slot)]) for slot in ("left", "middle", "right")]
    shown.append(("exact reference", exact))
    landmarks = []
    for panel, (name, image) in zip(app.panels, shown, strict=True):
        window, extent = crop(image, centre, size)
        left, _, _, top = extent
        for row, column in np.ndindex(*window.shape):
            x, y = left + column, top + row
            value = float(window[row, column])
            point = _clear_point(x, y, segments)
            what = f"{name} at position {position:.3f}: pixel ({x}, {y}) = {value:.2f}"
            landmarks.append(
                landmark_in_box(app, panel.axes, extent, point, gray_color(value), what, 16)
            )
    return landmarks


def zoom_every_variant() -> bytes:
    """The notebook's still grid: every variant zoomed where the curve leaves P0."""
    renderings, exact = seed_000_renderings()
    panels = {name: renderings[name] for name in ZOOMED_VARIANTS} | {"exact reference": exact}
    points = np.array(SEED_000_POINTS)
    figure = zoom_figure(panels, points, center=de_casteljau(points, 0.08), size=14, columns=4)
    return figure_picture(figure)


def step_app_picture(weighting: str) -> bytes:
    app = StepApp(np.array(SEED_000_POINTS), SEED_000_SHAPE)
    app.controls["weighting"].value = weighting
    return app_picture(app)


# --- Lesson 03: lines and triangles ------------------------------------------


def line_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of the three panels: ``raster.line``, ``line_4connected``, ``wu_line``.

    Bresenham's and the report's pixels black on white, Wu's weights in
    grays; a pixel the report lights and Bresenham does not is named so.
    """
    p0 = (int(app.value("x0")), int(app.value("y0")))
    p1 = (int(app.value("x1")), int(app.value("y1")))
    ideal = np.array([[np.add(p0, 0.5), np.add(p1, 0.5)]])
    bresenham = {tuple(pixel) for pixel in line(p0, p1).tolist()}
    staircase = {tuple(pixel) for pixel in line_4connected(p0, p1).tolist()}
    wu = {}
    for pixel, weight in zip(*wu_line(np.add(p0, 0.5), np.add(p1, 0.5)), strict=True):
        wu[tuple(pixel.tolist())] = min(wu.get(tuple(pixel.tolist()), 0.0) + weight, 1.0)
    grid = app.panels["bresenham"].get_array().shape[0]
    landmarks = []
    for pixel in itertools.product(range(grid), repeat=2):
        point = _clear_point(*pixel, ideal)
        drawn = pixel in bresenham
        if drawn:
            role = f"line({p0}, {p1}) pixel {pixel}"
        elif pixel in staircase:
            role = f"not a Bresenham pixel, yet in the report's loop: {pixel}"
        else:
            role = f"background {pixel}"
        for panel, color, what in (
            ("bresenham", BLACK if drawn else WHITE, role),
            ("report", BLACK if pixel in staircase else WHITE, f"line_4connected {pixel}"),
            ("wu", _colormap("Greys", wu.get(pixel, 0.0)), f"wu_line {pixel}"),
        ):
            landmarks.append(landmark_at(app, app.panels[panel].axes, point, color, what))
    return landmarks


def triangle_picture(rule: str) -> bytes:
    app = TriangleApp()
    app.controls["rule"].value = rule
    return app_picture(app)


# --- Lesson 04: sampling and supersampling -----------------------------------


@functools.cache
def _zone_plate_lab() -> tuple[np.ndarray, np.ndarray]:
    """The lab's 2500 x 2500 zone plate and its exact 320 x 320 box downsample."""
    plate = images.zone_plate((2500, 2500))
    return _frozen(plate), _frozen(images.zone_plate_box((2500, 2500), (320, 320)))


def supersample_app(rate: int = 1) -> SupersampleApp:
    app = SupersampleApp()
    app.controls["rate"].value = rate
    return app


def supersample_landmarks(app: SliderApp) -> list[Landmark]:
    """Result and difference pixels: ``supersample`` of the zone plate, minus ``zone_plate_box``.

    The landmarks are the 200 pixels where this rate differs most from the
    rates beside it.
    """
    if app.value("image") != "zone plate":
        raise ValueError("supersample_landmarks: the browser test moves the zone plate's rate")
    plate, exact = _zone_plate_lab()
    rate = int(app.value("rate"))
    resample = supersample if app.value("version") == "centred" else supersample_without_offset
    result = resample(plate, (320, 320), rate)
    difference = result - exact
    # Where this rate differs most from both neighbouring rates: the false
    # rings that move. The result is shown pixel for pixel, 1 px per pixel.
    changes = [
        np.abs(result - resample(plate, (320, 320), other))
        for other in (rate - 1, rate + 1)
        if 1 <= other <= 12
    ]
    telling = np.min(changes, axis=0)
    landmarks = []
    for flat_index in np.argsort(telling, axis=None)[::-1][:200]:
        row, column = (int(i) for i in np.unravel_index(flat_index, telling.shape))
        centre = (column + 0.5, row + 0.5)
        value = float(result[row, column])
        what = f"supersample(zone plate, rate {rate}) pixel ({column}, {row})"
        landmarks.append(landmark_at(app, app.result_axes, centre, gray_color(value), what, 3))
        color = _colormap("RdBu_r", float(difference[row, column]), -0.5, 0.5)
        landmarks.append(
            landmark_at(app, app.difference_axes, centre, color, f"{what} - zone_plate_box", 3)
        )
    return landmarks


# --- Lesson 06: dithering ----------------------------------------------------


@functools.cache
def _hopper_gray() -> np.ndarray:
    return _frozen(images.to_gray(images.photograph())[::2, ::2])


@functools.cache
def _blue_noise_32() -> np.ndarray:
    return _frozen(dither.blue_noise_mask(32, np.random.default_rng(0)))


def gray_level_app() -> GrayLevelApp:
    return GrayLevelApp(level=0.3, size=24)


def gray_level_landmarks(app: SliderApp) -> list[Landmark]:
    """The flat patch at the new level as ``dither`` makes it, and the ordered pattern marked.

    For each of ordered 3 x 3, Bayer 8 x 8, blue noise and Floyd-Steinberg,
    every pixel of the library's output for a flat patch (but the outermost,
    under the panel's frame); and the
    red frame around pattern k = the number of sub-pixels ``dither.ordered``
    lights for one pixel at this level.
    """
    level, size = float(app.value("level")), 24
    patch = np.full((size, size), level)
    outputs = {
        "ordered 3x3": dither.ordered(patch),
        "Bayer 8x8": dither.bayer(patch, 8),
        "blue noise": dither.blue_noise(patch, _blue_noise_32()),
        "Floyd-Steinberg": dither.error_diffusion(patch),
    }
    landmarks = []
    for name, output in outputs.items():
        scale = output.shape[0] // size  # ordered dithering shows 3 sub-pixels per pixel
        axes = app.panels[name].axes
        # Not the patch's outer pixels, which the panel's frame covers in part.
        inner = np.zeros(output.shape, dtype=bool)
        inner[scale:-scale, scale:-scale] = True
        for row, column in zip(*np.nonzero(inner), strict=True):
            value = float(output[row, column])
            centre = ((column + 0.5) / scale - 0.5, (row + 0.5) / scale - 0.5)
            what = f"{name} of a flat {level:.3f} patch: pixel ({column}, {row}) = {value:g}"
            landmarks.append(landmark_at(app, axes, centre, gray_color(value), what, 24))
    lit = int(dither.ordered([[level]]).sum())
    # The frame's left side, or its right side for pattern 0 (at the strip's edge).
    side = 4 * lit - 0.6 if lit > 0 else 2.6
    what = f"red frame around pattern k = {lit} (dither.ordered lights {lit} of 9 at {level:.3f})"
    landmarks.append(landmark_at(app, app.highlight.axes, (side, 1.0), (255, 0, 0), what))
    return landmarks


def dithering_table() -> bytes:
    gray = _hopper_gray()
    table = {"original": gray, **dither.all_methods(gray)}
    return figure_picture(side_by_side(table, center=(150, 80), size=32, width=900, columns=6))


def dithering_ramp() -> bytes:
    gradient = images.ramp(256, 32)
    table = {"ramp": gradient, **dither.all_methods(gradient)}
    return figure_picture(side_by_side(table, center=(64, 16), size=24, columns=6))


# --- Lesson 07: filtering ----------------------------------------------------


@functools.cache
def _hopper_rgb() -> np.ndarray:
    return _frozen(images.photograph()[::2, ::2])


def repeated_blur_app() -> RepeatedBlurApp:
    return RepeatedBlurApp(_hopper_rgb(), repeats=8, corner=32)


def repeated_blur_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of each rule's zoomed top-right corner after n blurs by ``filters``."""
    repeats, corner = int(app.value("repeats")), 32
    landmarks = []
    for border in filters.BORDERS:
        result = _hopper_rgb()
        for _ in range(repeats):
            result = blurred(result, border)
        window = result[:corner, -corner:]
        axes = app.crops[border].axes
        for row, column in np.ndindex(corner, corner):
            what = f"{border!r} after {repeats} blurs: corner pixel ({column}, {row})"
            color = _rgb(window[row, column])
            # Tolerance 1: one more blur changes the zero-padded frame by 2 grey levels.
            landmarks.append(landmark_at(app, axes, (column, row), color, what, 1))
    return landmarks


def blur_and_edges() -> bytes:
    rgb = _hopper_rgb()
    gray = images.to_gray(rgb)
    five_blurs = rgb
    for _ in range(5):
        five_blurs = filters.blur(five_blurs)
    pictures = {
        "original": rgb,
        "blur": filters.blur(rgb),
        "blur 5 times": five_blurs,
        "Sobel (gray), clipped": np.clip(filters.sobel(gray), 0, 1),
        "Sobel per channel, clipped": np.clip(filters.sobel(rgb), 0, 1),
    }
    return figure_picture(side_by_side(pictures, center=(150, 80), size=40, width=1000))


# --- Lesson 08: Poisson image editing ----------------------------------------

PLANE_OFFSET = (500, 300)
AROUND_THE_PLANE = (slice(280, 430), slice(470, 800))


@functools.cache
def _lake_and_plane() -> tuple[np.ndarray, np.ndarray]:
    return _frozen(images.lake()), _frozen(images.plane())


def poisson_app() -> PoissonIterationApp:
    """Lesson 08's app as the notebook shows it: 1000 sweeps of Jacobi."""
    app = PoissonIterationApp()
    app.controls["sweeps"].value = 1000
    return app


def poisson_landmarks(app: SliderApp) -> list[Landmark]:
    """Region pixels of ``seamless_clone`` after n sweeps, and their error against ``solve``."""
    lake, plane = _lake_and_plane()
    method, sweeps = app.value("method"), int(app.value("sweeps"))
    problem = poisson.clone_problem(lake, plane, PLANE_OFFSET)
    exact = poisson.solve(problem)
    iterate = poisson.solve(problem, method, iterations=sweeps)
    clone = poisson.seamless_clone(lake, plane, PLANE_OFFSET, method=method, iterations=sweeps)
    start = float(np.abs(problem.values - exact)[problem.region].max() * 255)
    error = np.abs(iterate - exact).max(axis=2) * 255
    x0, y0 = problem.corner
    height, width = problem.region.shape
    left, top = x0 - MARGIN, y0 - MARGIN  # the app's view: the region and a margin
    landmarks = []
    for row in (height // 4, height // 2, 3 * height // 4):
        for column in (width // 4, width // 2, 3 * width // 4):
            x, y = x0 + column, y0 + row
            what = f"{method}, {sweeps} sweeps: pixel ({x}, {y})"
            point = (x - left, y - top)
            color = _rgb(clone[y, x])
            landmarks.append(landmark_at(app, app.picture.axes, point, color, what, 12))
            color = _colormap("magma", float(error[row, column]), 0.0, start)
            landmarks.append(
                landmark_at(app, app.error_image.axes, point, color, f"{what}: error", 12)
            )
    return landmarks


def clone_comparison() -> bytes:
    lake, plane = _lake_and_plane()
    pictures = {
        "naive paste": poisson.naive_paste(lake, plane, PLANE_OFFSET),
        "seamless clone": poisson.seamless_clone(lake, plane, PLANE_OFFSET),
    }
    return figure_picture(show_images(pictures, window=AROUND_THE_PLANE))


def inpainting() -> bytes:
    scratched, scratches = images.scratched_photograph()
    pictures = {
        "scratched": scratched,
        "inpainted": poisson.inpaint(scratched, scratches),
        "original": images.photograph(),
    }
    return figure_picture(show_images(pictures, window=(slice(120, 420), slice(60, 460))))


def void_and_cluster_picture() -> bytes:
    return app_picture(VoidAndClusterApp(size=32, dots=120))
