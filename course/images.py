"""The course's examples: its curves, matplotlib's bundled photograph, procedural images.

Every example is defined here once, and every lesson, app, checker, test and
benchmark takes it from here. Curves are read-only float arrays ``(N, 2)``
of control points in image space; images are float arrays in [0, 1], gray
(H, W) or RGB (H, W, 3). Nothing is downloaded: photographs come from
matplotlib's own sample data.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib import cbook

from course._validate import as_choice, as_image, as_int, as_positive_float, as_rng, as_shape

__all__ = [
    "EXAMPLE_POINTS",
    "SEED_000_CUBIC",
    "SEED_000_SHAPE",
    "face",
    "lake",
    "photograph",
    "plane",
    "plane_mask",
    "ramp",
    "scratched_photograph",
    "to_gray",
    "zone_plate",
    "zone_plate_box",
]


def _read_only(points: list[list[float]]) -> np.ndarray:
    array = np.array(points, dtype=float)
    array.flags.writeable = False
    return array


# --- lessons 01-02 and 05: the curves -----------------------------------------

#: The GAMES101 handout's test curve (seed 000): a cubic S across a 700 x 700 window.
SEED_000_CUBIC = _read_only([[10, 10], [690, 10], [10, 690], [690, 690]])
#: The window, (H, W), seed 000 draws its curve in.
SEED_000_SHAPE = (700, 700)
#: Twelve control points for the de Casteljau app. The first four are a generic
#: cubic: no symmetry, so at t = 0.5 every level of the construction stands apart.
#: Then a zigzag, as seed 002's degree-9 curve could have. Take the first N for N points.
EXAMPLE_POINTS = _read_only(
    [
        [90, 610],
        [170, 130],
        [540, 80],
        [620, 470],
        [350, 600],
        [120, 350],
        [600, 150],
        [250, 60],
        [470, 480],
        [60, 520],
        [640, 380],
        [350, 250],
    ]
)

# --- images -------------------------------------------------------------------

# ITU-R BT.601 luma weights, as OpenCV's cvtColor(..., COLOR_RGB2GRAY).
_LUMA = np.array([0.299, 0.587, 0.114])


def photograph() -> np.ndarray:
    """Grace Hopper, 600 x 512 RGB, from matplotlib's sample data.

    Examples
    --------
    >>> image = photograph()
    >>> image.shape, image.dtype, bool(0 <= image.min() <= image.max() <= 1)
    ((600, 512, 3), dtype('float64'), True)
    """
    import matplotlib.image

    with cbook.get_sample_data("grace_hopper.jpg") as file:
        pixels = matplotlib.image.imread(file, format="jpg")
    return pixels[..., :3].astype(float) / 255.0


def face() -> np.ndarray:
    """The photograph's face, gray, 150 x 128: every other pixel of rows 150-449, columns
    128-383. Its right edge is the light wall, where lesson 07's border rules show.

    Examples
    --------
    >>> image = face()
    >>> image.shape, bool(image[20:70, -1].mean() > image.mean())   # the wall, beside the face
    ((150, 128), True)
    """
    return to_gray(photograph())[150:450:2, 128:384:2]


def to_gray(image: Any) -> np.ndarray:
    """Luma of an RGB image (BT.601 weights); a gray image is returned as a copy.

    Examples
    --------
    >>> to_gray(np.ones((2, 2, 3)))
    array([[1., 1.],
           [1., 1.]])
    """
    array = as_image(image)
    if array.ndim == 2:
        return array
    return np.clip(array @ _LUMA, 0.0, 1.0)


# --- procedural images with a known box-filtered downsample (lessons 04-05) ---


def zone_plate(shape: Any = (512, 512), max_frequency: float = 0.25) -> np.ndarray:
    """A zone plate: concentric rings whose frequency grows with the distance.

    ``0.5 + 0.5 * cos(pi * k * (x**2 + y**2))`` sampled at the pixel centres,
    with the rings centred on the top-left corner. The local frequency at
    distance d is ``k * d`` cycles per pixel, and ``k = max_frequency / max(H, W)``,
    so it reaches ``max_frequency`` at the far edges (and 1.41 times that in
    the far corner). Any downsampling that aliases shows false rings.

    Parameters
    ----------
    shape : (H, W)
    max_frequency : float
        Cycles per pixel at the right and bottom edges; below 0.5 the image
        itself is free of aliasing.

    See Also
    --------
    zone_plate_box : its exact mean over any grid of output pixels.

    Examples
    --------
    >>> plate = zone_plate((4, 6), max_frequency=0.25)
    >>> plate.shape, float(plate[0, 0].round(4))
    ((4, 6), 0.9989)
    """
    height, width = as_shape(shape)
    k = _zone_plate_rate(height, width, max_frequency)
    x = np.arange(width) + 0.5
    y = np.arange(height) + 0.5
    return 0.5 + 0.5 * np.cos(np.pi * k * (y[:, None] ** 2 + x[None, :] ** 2))


def zone_plate_box(shape: Any, out_shape: Any, max_frequency: float = 0.25) -> np.ndarray:
    """The exact box-filtered downsample of :func:`zone_plate`, in closed form.

    Output pixel (r, c) is the mean of the continuous zone plate over the
    input-space square it covers, ``[c W / w, (c + 1) W / w) x [r H / h,
    (r + 1) H / h)``: what an ideal camera with square pixels records, and
    the limit every supersampler should approach. Since ``cos(a + b) =
    Re(e^{ia} e^{ib})`` the integral splits into one per axis, each a
    difference of Fresnel integrals.

    Examples
    --------
    Shrinking 2500 x 2500 to 320 x 320, the rings near the corner are far
    finer than an output pixel and average out to mid-gray:

    >>> exact = zone_plate_box((2500, 2500), (320, 320))
    >>> exact.shape, float(exact[0, 0].round(4)), float(exact[-1, -1].round(4))
    ((320, 320), 0.9999, 0.5003)

    The mean over one pixel is close to the value at its centre when the
    rings are much wider than a pixel:

    >>> means = zone_plate_box((64, 64), (64, 64), max_frequency=0.05)
    >>> bool(np.abs(means - zone_plate((64, 64), max_frequency=0.05)).max() < 0.01)
    True
    """
    from scipy.special import fresnel

    height, width = as_shape(shape)
    out_height, out_width = as_shape(out_shape, "out_shape")
    k = _zone_plate_rate(height, width, max_frequency)
    # With x = t / sqrt(2 k), pi k x**2 = pi t**2 / 2, the Fresnel integrals' form.
    stretch = np.sqrt(2 * k)

    def axis_integral(size: int, out_size: int) -> np.ndarray:
        """Integral of exp(i pi k x**2) over each output pixel's span, over its length."""
        edges = np.arange(out_size + 1) * (size / out_size)
        sine, cosine = fresnel(edges * stretch)
        integral = np.diff(cosine) + 1j * np.diff(sine)
        return integral / stretch / (size / out_size)

    mean = np.real(np.outer(axis_integral(height, out_height), axis_integral(width, out_width)))
    return np.clip(0.5 + 0.5 * mean, 0.0, 1.0)


def _zone_plate_rate(height: int, width: int, max_frequency: float) -> float:
    max_frequency = as_positive_float(max_frequency, "max_frequency")
    return max_frequency / max(height, width)


# --- lessons 06-07: dithering and filtering ---------------------------------


def ramp(shape: Any = (32, 256)) -> np.ndarray:
    """A horizontal gray ramp of ``shape = (H, W)``, black to white: pixel x is (x + 0.5) / W.

    Every column has its own level, so a dithering method's tone (or its
    failure to keep it) shows along the ramp.

    Examples
    --------
    >>> ramp((2, 4))
    array([[0.125, 0.375, 0.625, 0.875],
           [0.125, 0.375, 0.625, 0.875]])
    """
    height, width = as_shape(shape)
    return np.tile((np.arange(width) + 0.5) / width, (height, 1))


# --- lesson 08: Poisson image editing ----------------------------------------
# A scene pair like the lab's (a plane pasted into a lake at (500, 300)) and a
# scratched photograph, all procedural and deterministic.

LAKE_SHAPE = (450, 800)
PLANE_SHAPE = (111, 280)


def lake(shape: Any = LAKE_SHAPE, rng: np.random.Generator | None = None) -> np.ndarray:
    """A lake at dusk: a blue sky with clouds, a wooded shore, rippled water; RGB.

    The default 450 x 800 holds the lab's 280 x 111 plane at offset (500, 300),
    over the water. Deterministic unless another ``rng`` is given.

    Examples
    --------
    >>> image = lake()
    >>> image.shape, bool(0 <= image.min() <= image.max() <= 1)
    ((450, 800, 3), True)
    >>> bool(image[50, 400, 2] > image[50, 400, 0])   # the sky is blue
    True
    """
    height, width = as_shape(shape)
    rng = np.random.default_rng(8) if rng is None else as_rng(rng)
    rows = np.arange(height)[:, None] / height
    columns = np.arange(width)[None, :] / width
    horizon = 0.42 + 0.03 * np.sin(2 * np.pi * columns * 1.3 + 0.4)
    shore = (
        horizon
        + 0.05
        + 0.02 * np.sin(2 * np.pi * columns * 3.1)
        + 0.012 * _smooth_noise((1, width), (0, 4), rng)
    )
    # Sky: deep blue overhead fading to pale at the horizon, soft clouds.
    height_above = np.clip(rows / horizon, 0, 1)
    sky = _mix((0.18, 0.36, 0.72), (0.78, 0.84, 0.92), height_above**1.5)
    clouds = np.clip(_smooth_noise((height, width), (10, 40), rng) * 1.6 - 0.3, 0, 1)
    sky = _mix(sky, (0.97, 0.96, 0.95), 0.75 * clouds[..., None] * (1 - height_above[..., None]))
    # Shore: dark trees with a ragged top.
    trees = _mix(
        (0.10, 0.22, 0.12), (0.20, 0.30, 0.16), _smooth_noise((height, width), (1, 2), rng)
    )
    # Water: the sky's colour darkened with depth, streaked by ripples.
    depth = np.clip((rows - shore) / (1 - shore), 0, 1)
    water = _mix((0.42, 0.56, 0.66), (0.08, 0.22, 0.33), depth**0.7)
    ripples = _smooth_noise((height, width), (0.8, 12), rng) * (0.35 + 0.65 * depth)
    water = water + 0.09 * ripples[..., None]
    image = np.where(
        (rows < horizon)[..., None], sky, np.where((rows < shore)[..., None], trees, water)
    )
    image = image + 0.012 * rng.standard_normal(image.shape)  # film grain
    return np.clip(image, 0.0, 1.0)


def plane(
    shape: Any = PLANE_SHAPE, rng: np.random.Generator | None = None, sky: str = "evening"
) -> np.ndarray:
    """A white seaplane in the sky, side view, facing right; RGB.

    ``sky="evening"`` (the lab's photograph) is orange, nothing like
    :func:`lake`'s water or sky: pasting the rectangle leaves a visible seam,
    and a seamless clone must shift the plane's colours as far as the sky's.
    ``sky="day"`` is a hazy pale blue, paler than the lake's sky and lit the
    other way (brightest at the top): the rectangle still shows when pasted
    as it is, but only its brightness, not its colour, has to change. The
    default 111 x 280 is the size of the lab's photograph. Deterministic
    unless another ``rng`` is given.

    Examples
    --------
    >>> image = plane()
    >>> image.shape
    (111, 280, 3)
    >>> bool(image[5, 5, 0] > image[5, 5, 2])   # orange sky: more red than blue
    True
    >>> bool(plane(sky="day")[5, 5, 2] > plane(sky="day")[5, 5, 0])   # a blue sky
    True
    """
    height, width = as_shape(shape)
    sky = as_choice(sky, "sky", ("evening", "day"))
    rng = np.random.default_rng(80) if rng is None else as_rng(rng)
    rows = np.arange(height)[:, None] / height
    top, bottom = ((0.93, 0.55, 0.25), (0.98, 0.80, 0.52))
    if sky == "day":
        top, bottom = ((0.80, 0.87, 0.96), (0.55, 0.68, 0.88))
    colour = _mix(top, bottom, np.broadcast_to(rows, (height, width)))
    sky_pixels = colour + 0.05 * _smooth_noise((height, width), (4, 20), rng)[..., None]
    body = _plane_coverage((height, width))
    # Light from above: the fuselage darkens towards its belly.
    paint = _mix((0.96, 0.96, 0.97), (0.62, 0.64, 0.70), np.broadcast_to(rows, (height, width)))
    stripe = _plane_parts((height, width), "stripe")
    paint = np.where(stripe[..., None] > 0, (0.75, 0.10, 0.12), paint)
    dark = _plane_parts((height, width), "windows")
    paint = _mix(paint, (0.15, 0.18, 0.25), dark[..., None])
    image = _mix(sky_pixels, paint, body[..., None])
    image = image + 0.008 * rng.standard_normal((height, width, 3))
    return np.clip(image, 0.0, 1.0)


def plane_mask(shape: Any = PLANE_SHAPE, margin: int = 4) -> np.ndarray:
    """The plane's silhouette grown by ``margin`` pixels: a mask for seamless_clone.

    False on the outer ring of pixels, as :func:`course.poisson.seamless_clone`
    requires of a mask.

    Examples
    --------
    >>> mask = plane_mask()
    >>> mask.shape, mask.dtype, bool(mask[0].any() or mask[:, 0].any())
    ((111, 280), dtype('bool'), False)
    >>> bool(0.2 < mask.mean() < 0.5)
    True
    """
    import scipy.ndimage

    height, width = as_shape(shape)
    margin = as_int(margin, "margin", minimum=0)
    silhouette = _plane_coverage((height, width)) > 0.5
    grown = scipy.ndimage.binary_dilation(silhouette, iterations=margin) if margin else silhouette
    grown[[0, -1], :] = False
    grown[:, [0, -1]] = False
    return grown


def scratched_photograph(
    scratches: int = 7, width: int = 3, rng: np.random.Generator | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`photograph` with white scratches, and the mask of the scratched pixels.

    Each scratch is a random quadratic Bézier curve ``width`` pixels wide,
    kept away from the image border so :func:`course.poisson.inpaint` has known
    pixels all around it. Returns ``(scratched, mask)``.

    Examples
    --------
    >>> scratched, mask = scratched_photograph()
    >>> scratched.shape, mask.shape, bool(mask[0].any())
    ((600, 512, 3), (600, 512), False)
    >>> bool((scratched[mask] > 0.9).all())
    True
    """
    import scipy.ndimage

    # The curves are made here, valid: de Casteljau's kernel, without its checks.
    from course.curves._bezier_fast import de_casteljau_chunked

    scratches = as_int(scratches, "scratches", minimum=0, maximum=1000)
    width = as_int(width, "width", minimum=1, maximum=100)
    rng = np.random.default_rng(88) if rng is None else as_rng(rng)
    image = photograph()
    height, columns = image.shape[:2]
    border = 10 + width
    mask = np.zeros((height, columns), bool)
    t = np.linspace(0.0, 1.0, 4 * (height + columns))
    for _ in range(scratches):
        control = rng.uniform((border, border), (columns - border, height - border), (3, 2))
        x, y = np.rint(de_casteljau_chunked(control, t)).astype(int).T
        mask[y, x] = True
    mask = scipy.ndimage.binary_dilation(mask, iterations=(width - 1) // 2) if width > 1 else mask
    scratched = image.copy()
    scratched[mask] = (0.96, 0.95, 0.93)
    return scratched, mask


def _mix(a: Any, b: Any, t: Any) -> np.ndarray:
    """``(1 - t) a + t b``, colours broadcast against a weight array (scalar or (H, W, 1))."""
    a, b, t = np.asarray(a, float), np.asarray(b, float), np.asarray(t, float)
    if t.ndim == 2 and (a.shape[-1:] == (3,) or b.shape[-1:] == (3,)):
        t = t[..., None]
    return (1 - t) * a + t * b


def _smooth_noise(shape: tuple[int, int], sigma: tuple[float, float], rng: np.random.Generator):
    """Gaussian-blurred white noise scaled to [-1, 1]: ``sigma`` = (rows, columns) in pixels."""
    import scipy.ndimage

    noise = scipy.ndimage.gaussian_filter(rng.standard_normal(shape), sigma, mode="wrap")
    return noise / max(np.abs(noise).max(), 1e-12)


def _plane_coverage(shape: tuple[int, int]) -> np.ndarray:
    """Fraction of each pixel inside the plane (2 x 2 samples per pixel)."""
    return _plane_parts(shape, "body")


def _plane_parts(shape: tuple[int, int], part: str) -> np.ndarray:
    """Coverage of one part of the plane, in coordinates scaled to the sprite's size."""
    height, width = shape
    total = np.zeros(shape)
    for sy in (0.25, 0.75):
        for sx in (0.25, 0.75):
            y = (np.arange(height)[:, None] + sy) / height * 111
            x = (np.arange(width)[None, :] + sx) / width * 280
            total += _plane_inside(x, y, part)
    return total / 4


def _plane_inside(x: np.ndarray, y: np.ndarray, part: str) -> np.ndarray:
    """Is (x, y) inside a part, on the 280 x 111 design grid (the plane faces right)."""
    fuselage = ((x - 140) / 112) ** 2 + ((y - 52) / 13) ** 2 <= 1
    fuselage |= (x >= 40) & (x <= 160) & (np.abs(y - 50 + (x - 40) * 0.02) <= 11 - (160 - x) * 0.04)
    if part == "stripe":
        return fuselage & (np.abs(y - 55) <= 1.5)
    if part == "windows":
        window_row = (np.abs(y - 47) <= 2.5) & (x >= 150) & (x <= 232) & ((x - 150) % 10 < 5)
        cockpit = ((x - 238) / 9) ** 2 + ((y - 46) / 4) ** 2 <= 1
        return fuselage & (window_row | cockpit)
    # Tail fin: trailing edge upright at x = 32, leading edge sloping up and back.
    fin = (y >= 14) & (y <= 50) & (x >= 32) & (x <= 48 + (y - 14))
    wing = (np.abs(y - 58) <= 3.5) & (x >= 105) & (x <= 205)
    tailplane = (np.abs(y - 47) <= 2.5) & (x >= 28) & (x <= 78)
    strut = ((np.abs(x - 130) <= 2) | (np.abs(x - 190) <= 2)) & (y >= 60) & (y <= 88)
    float_ = ((x - 165) / 80) ** 2 + ((y - 92) / 6) ** 2 <= 1
    return fuselage | fin | wing | tailplane | strut | float_
