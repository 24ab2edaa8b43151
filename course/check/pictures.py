"""Pictures of a wrong answer, for the checkers' reports.

Two kinds: a curve (the expected curve and the student's points along it,
each from its t = 0 end) and a set of pixels (the pixels both have in gray,
the missing ones in one colour and the extra ones in another, each pixel a
flat square at a whole zoom). Titles and labels follow the language
(:mod:`course.i18n`): a caller's title, marked with ``N_``, is translated
here. Colours are Okabe and Ito's, safe for
colour-blind readers, and every one has a legend entry.
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap
from matplotlib.figure import Figure
from matplotlib.patches import Patch

from course import limits
from course._validate import as_float_array, as_int, as_points, as_positive_float, require_finite
from course.i18n import N_, _

__all__ = [
    "EXPECTED",
    "EXTRA",
    "GIVEN",
    "MISSING",
    "curve_picture",
    "figure_png",
    "image_picture",
    "pixel_picture",
    "shown_difference",
    "side_by_side",
]

#: Okabe and Ito's blue, for what was expected (a curve, or the pixels missing from the answer).
EXPECTED = MISSING = "#0072B2"
#: Okabe and Ito's vermillion, for what was given (a curve, or the extra pixels).
GIVEN = EXTRA = "#D55E00"
_BOTH = "#999999"


def figure_png(figure: Figure) -> bytes:
    """A matplotlib figure as PNG bytes, drawn with Agg."""
    if not isinstance(figure, Figure):
        raise TypeError(
            _("figure must be a matplotlib Figure; got {figure_type}").format(
                figure_type=type(figure).__name__
            )
        )
    buffer = io.BytesIO()
    FigureCanvasAgg(figure).print_png(buffer)
    return buffer.getvalue()


def curve_picture(
    control: Any,
    expected: Any,
    given: Any,
    title: str = "",
    width_inches: float = 4.2,
    mark_start: bool = True,
    given_label: str = N_("your points"),
    expected_point: Any = None,
    expected_label: str = N_("expected point"),
) -> bytes:
    """The control polygon, the expected curve and the student's points, as a PNG.

    ``expected`` and ``given`` are (M, 2) points at the same parameters, from
    t = 0 to t = 1; the first of each is ringed and labelled t = 0, so a
    curve run backwards shows at a glance. Image space: y points down.
    ``expected_point``, if given, is the (1, 2) point the student's single point
    should be, drawn as a cross: a wrong point can lie on the curve itself; it may be several
    points (a level of de Casteljau's construction), labelled ``expected_label``.
    """
    control = as_points(control, "control", bound=limits.MAX_COORDINATE)
    if len(control) > 100:  # each control point is labelled: a picture has room for 100
        raise ValueError(
            _("control must hold at most 100 points; got {control_count}").format(
                control_count=len(control)
            )
        )
    expected = _as_pairs(expected, "expected")
    require_finite(expected, "expected")
    given = _as_pairs(given, "given")  # a student's points: NaN shows as a gap
    width_inches = as_positive_float(width_inches, "width_inches", smallest=1.0, largest=20.0)
    if expected_point is not None:
        expected_point = _as_pairs(expected_point, "expected_point")
        require_finite(expected_point, "expected_point")
    figure = Figure(figsize=(width_inches, width_inches), dpi=100)
    axes = figure.add_subplot()
    axes.plot(*control.T, "o--", color="0.6", linewidth=1, markersize=5, label=_("control polygon"))
    # Past a dozen points their labels overlap: label the ends and every tenth between.
    labelled = range(len(control)) if len(control) <= _ALL_LABELLED else _sparse(len(control))
    for index in labelled:
        axes.annotate(
            f"P{index}", control[index], xytext=(5, 5), textcoords="offset points", fontsize=8
        )
    axes.plot(*expected.T, "-", color=EXPECTED, linewidth=2, label=_("expected curve"))
    axes.plot(*given.T, "o", color=GIVEN, markersize=3.5, label=_translated(str(given_label)))
    if expected_point is not None:
        axes.plot(
            *expected_point.T,
            "X",
            color=EXPECTED,
            markersize=8,
            label=_translated(str(expected_label)),
        )
    for points, colour in ((expected, EXPECTED), (given, GIVEN)) if mark_start else ():
        if len(points) and np.isfinite(points[0]).all():
            axes.plot(*points[0], "o", markersize=11, fillstyle="none", color=colour)
            axes.annotate(
                _("t = 0"), points[0], xytext=(6, -12), textcoords="offset points", color=colour
            )
    axes.set_aspect("equal", adjustable="datalim")
    axes.invert_yaxis()
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=7, loc="best")
    axes.set_title(_translated(title), fontsize=9)
    figure.tight_layout()
    return figure_png(figure)


#: The most control points a curve picture labels each of.
_ALL_LABELLED = 12


def _sparse(count: int) -> list[int]:
    """The control points labelled when there are many: P0, every tenth, and the last.

    Examples
    --------
    >>> _sparse(41)
    [0, 10, 20, 30, 40]
    """
    return sorted({*range(0, count - 5, 10), count - 1})


def pixel_picture(
    expected: Any,
    given: Any,
    window: int = 16,
    zoom: int = 18,
    title: str = "",
    outline: Any = None,
) -> bytes:
    """Pixels around the first difference, as a PNG: both in gray, missing and extra in colour.

    ``expected`` and ``given`` are (K, 2) integer (x, y) pixels; ``outline``, if given, is a
    polygon drawn over them (a triangle's edges). The view frames them all, and the outline,
    with a pixel to spare, when that fits in ``window`` pixels each way; along an axis where
    it does not, it is ``window`` pixels centred on the first missing pixel in reading order
    (else the first extra one), kept inside what there is to see. Each pixel is ``zoom`` x
    ``zoom`` screen pixels, so nothing is resampled.

    The axes number pixels as the lessons' figures do: the ticks are coordinates, on pixel
    corners, so pixel (x, y) is the square from tick x to tick x + 1 (its centre at
    (x + 0.5, y + 0.5)), and an outline's vertex at (0, 0) is drawn at the ticks (0, 0).
    """
    return figure_png(_pixel_figure(expected, given, window, zoom, title, outline))


def _pixel_figure(
    expected: Any, given: Any, window: int, zoom: int, title: str, outline: Any
) -> Figure:
    """:func:`pixel_picture`'s figure, before it is drawn."""
    window = as_int(window, "window", minimum=1, maximum=256)
    zoom = as_int(zoom, "zoom", minimum=1, maximum=64)
    want = _pixel_keys(expected, "expected")
    have = _pixel_keys(given, "given")
    if outline is not None:
        outline = as_points(outline, "outline", bound=limits.MAX_COORDINATE)
    both, missing, extra = (
        np.intersect1d(want, have),
        np.setdiff1d(want, have),
        np.setdiff1d(have, want),
    )
    differing = np.union1d(missing, extra)
    first = next((group[0] for group in (missing, differing, want, have) if len(group)), None)
    left, top, width, height = _frame(np.union1d(want, have), outline, first, window)
    codes = np.zeros((height, width), dtype=int)
    for keys, code in ((both, 1), (missing, 2), (extra, 3)):
        xs, ys = keys % _WIDE - _OFFSET - left, keys // _WIDE - _OFFSET - top
        inside = (xs >= 0) & (xs < width) & (ys >= 0) & (ys < height)
        codes[ys[inside], xs[inside]] = code
    # Inches at 100 dpi: one image pixel is zoom screen pixels.
    side_w, side_h = width * zoom / 100, height * zoom / 100
    margin, legend_width, title_height = 0.3, 1.5, 0.35
    figure_w = side_w + 2 * margin + legend_width
    figure_h = max(side_h, 0.9) + 2 * margin + title_height  # room for the legend's three rows
    figure = Figure(figsize=(figure_w, figure_h), dpi=100)
    axes = figure.add_axes(
        (margin / figure_w, margin / figure_h, side_w / figure_w, side_h / figure_h)
    )
    colours = ListedColormap(["white", _BOTH, MISSING, EXTRA])
    extent = (left, left + width, top + height, top)
    axes.imshow(codes, cmap=colours, vmin=0, vmax=3, interpolation="nearest", extent=extent)
    grid = [[(left + e, top), (left + e, top + height)] for e in range(width + 1)]
    grid += [[(left, top + e), (left + width, top + e)] for e in range(height + 1)]
    axes.add_collection(LineCollection(grid, colors="0.85", linewidths=0.5))
    if outline is not None:
        closed = np.vstack([outline, outline[:1]])
        axes.plot(*closed.T, "-", color="black", linewidth=1.2)
    axes.set_xlim(left, left + width)
    axes.set_ylim(top + height, top)
    every = max(1, max(width, height) // 8)
    xs = [left + e for e in range(width + 1) if (left + e) % every == 0]
    ys = [top + e for e in range(height + 1) if (top + e) % every == 0]
    axes.set_xticks(xs)
    axes.set_xticklabels([str(x) for x in xs], fontsize=6)
    axes.set_yticks(ys)
    axes.set_yticklabels([str(y) for y in ys], fontsize=6)
    axes.tick_params(length=2, pad=1)
    counts = (len(both), len(missing), len(extra))
    labels = (
        _("in both ({count})").format(count=counts[0]),
        _("missing ({count})").format(count=counts[1]),
        _("extra ({count})").format(count=counts[2]),
    )
    figure.legend(
        handles=[
            Patch(color=colour, label=label)
            for colour, label in zip((_BOTH, MISSING, EXTRA), labels, strict=True)
        ],
        loc="center left",
        bbox_to_anchor=((side_w + 2 * margin) / figure_w, 0.5),
        fontsize=8,
        frameon=False,
    )
    around = _("pixels ({left}..{right}, {top}..{bottom})").format(
        left=left, right=left + width - 1, top=top, bottom=top + height - 1
    )
    axes.set_title(_translated(title) or around, fontsize=8)
    return figure


#: The fewest pixels a framed view shows each way: a one-pixel answer still has a neighbourhood.
_SMALLEST_FRAME = 6


def _frame(
    keys: np.ndarray, outline: np.ndarray | None, first: Any, window: int
) -> tuple[int, int, int, int]:
    """(left, top, width, height) of the pixels :func:`pixel_picture` shows.

    Along each axis: the pixels' and the outline's extent with one pixel to spare, widened to
    :data:`_SMALLEST_FRAME` (or ``window``, if smaller) about its middle; when that is more
    than ``window``, ``window`` pixels centred on ``first``, moved inside that extent.

    Examples
    --------
    >>> triangle = np.array([[1.0, 1.0], [9.0, 2.0], [4.0, 8.0]])
    >>> keys = _pixel_keys([[1, 1], [8, 2], [4, 7]], "pixels")
    >>> _frame(keys, triangle, keys[0], 16)
    (0, 0, 10, 9)
    >>> far = _pixel_keys([[0, 0], [40, 0]], "pixels")
    >>> _frame(far, None, far[-1], 16)
    (26, -2, 16, 6)
    """
    if len(keys):
        xs, ys = keys % _WIDE - _OFFSET, keys // _WIDE - _OFFSET
        low = [int(xs.min()), int(ys.min())]
        high = [int(xs.max()) + 1, int(ys.max()) + 1]  # the far corners: one past the last pixel
    else:
        low, high = [0, 0], [1, 1]
    if outline is not None and len(outline):
        low = [min(low[k], int(np.floor(outline[:, k].min()))) for k in (0, 1)]
        high = [max(high[k], int(np.ceil(outline[:, k].max()))) for k in (0, 1)]
    centre = (0, 0) if first is None else _pixel_at(first)
    frame = []
    for axis in (0, 1):
        start, stop = low[axis] - 1, high[axis] + 1
        size = stop - start
        smallest = min(_SMALLEST_FRAME, window)
        if size < smallest:
            start -= (smallest - size) // 2
            size = smallest
        elif size > window:
            start = min(max(centre[axis] - window // 2, start), stop - window)
            size = window
        frame.append((start, size))
    (left, width), (top, height) = frame
    return left, top, width, height


def image_picture(expected: Any, given: Any, title: str = "") -> bytes:
    """Expected and given images and their difference, each pixel a square at a whole zoom.

    The difference (given minus expected; in colour, each pixel's largest over its channels,
    with its sign, so that swapped channels show) is drawn red where
    the answer is too bright and blue where it is too dark, with a colour bar in image units,
    so the place and the size of the error show at a glance. Its axes number pixels as the
    lessons' figures do: ticks on pixel corners, pixel (x, y) the square from tick x to
    tick x + 1.
    """
    want = np.asarray(expected, dtype=float)
    have = np.asarray(given, dtype=float)
    if want.ndim not in (2, 3) or want.size == 0 or max(want.shape[:2]) > limits.MAX_SIDE:
        raise ValueError(
            _("expected must be a non-empty image (H, W) or (H, W, 3); got {want_shape}").format(
                want_shape=want.shape
            )
        )
    have, difference = shown_difference(want, have)
    height, width = want.shape[:2]
    zoom = max(1, min(24, 192 // max(height, width, 1)))
    side_w, side_h = width * zoom, height * zoom
    # Each panel sits in a slot wide enough for its title, so that titles never run together.
    slot = max(side_w, 84)
    margin, bar, gap, top = 12, 14, 24, 40
    columns = margin + 3 * slot + 2 * gap + 8 + bar + 44
    rows = top + side_h + margin + 14
    bottom = margin + 14  # room for the difference panel's pixel numbers
    figure = Figure(figsize=(columns / 100, rows / 100), dpi=100)
    limit = max(float(np.abs(np.nan_to_num(difference)).max(initial=0.0)), 1e-12)
    # Values past 1 (a gradient magnitude) get a gray scale that reaches them, named in the title.
    top = max(1.0, float(np.max(np.nan_to_num(want), initial=0.0)))
    if top == 1.0:
        expected_title, given_title = _("expected"), _("your result")
    else:
        expected_title = _("expected, 0 to {top:.3g}").format(top=top)
        given_title = _("your result, 0 to {top:.3g}").format(top=top)
    panels = (
        (want, expected_title, {"cmap": "gray", "vmin": 0, "vmax": top}),
        (have, given_title, {"cmap": "gray", "vmin": 0, "vmax": top}),
        (
            difference,
            _("your result minus expected"),
            {"cmap": "RdBu_r", "vmin": -limit, "vmax": limit},
        ),
    )
    shown = None
    for index, (picture, name, style) in enumerate(panels):
        left = margin + index * (slot + gap) + (slot - side_w) / 2
        axes = figure.add_axes((left / columns, bottom / rows, side_w / columns, side_h / rows))
        if picture.ndim == 3:
            style = {}
            picture = np.clip(picture, 0, 1)
        # Image coordinates, as the lessons' figures have them: pixel (x, y) is the square
        # from (x, y) to (x + 1, y + 1).
        extent = (0, width, height, 0)
        shown = axes.imshow(picture, interpolation="nearest", extent=extent, **style)
        axes.set_xticks([])
        axes.set_yticks([])
        axes.set_title(name, fontsize=8)
    # Coordinates on the difference, x below it, y on its left, a few of each, on pixel corners.
    step_x, step_y = max(1, -(-width // 4)), max(1, -(-height // 4))
    axes.set_xticks(range(0, width + 1, step_x))
    axes.set_yticks(range(0, height + 1, step_y))
    axes.tick_params(labelsize=6, length=2, pad=1)
    bar_left = margin + 3 * slot + 2 * gap + 8
    colour_bar = figure.add_axes((bar_left / columns, bottom / rows, bar / columns, side_h / rows))
    figure.colorbar(shown, cax=colour_bar, format="%.2g")  # no offset text over the title
    colour_bar.tick_params(labelsize=7)
    if title:
        figure.suptitle(_translated(title), fontsize=9, y=1 - 6 / rows, va="top")
    return figure_png(figure)


def shown_difference(want: np.ndarray, have: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The answer as :func:`image_picture` shows it, and its difference from ``want``.

    A gray answer to a colour image is shown gray; an answer of another shape is blank (NaN).
    In colour the difference of a pixel is its largest over the channels, with its sign, so
    that an answer with its channels swapped shows, where their mean would cancel.

    Examples
    --------
    >>> want = np.zeros((1, 1, 3)); want[0, 0] = (0.2, 0.5, 0.8)
    >>> shown_difference(want, want[..., ::-1])[1]
    array([[0.6]])
    """
    if have.shape == want.shape[:2] and want.ndim == 3:
        have = np.repeat(have[..., None], want.shape[2], axis=2)
    elif have.shape != want.shape:
        blank = np.full(want.shape[:2], np.nan)
        return blank, blank
    difference = have - want
    if difference.ndim == 3:
        largest = np.argmax(np.abs(np.nan_to_num(difference)), axis=2)[..., None]
        difference = np.take_along_axis(difference, largest, axis=2)[..., 0]
    return have, difference


def _as_pairs(points: Any, name: str) -> np.ndarray:
    """(M, 2) float points from any array of an even number of values."""
    array = as_float_array(points, name)
    if array.size % 2:
        raise ValueError(
            _("{name} must hold (x, y) pairs; got {size} numbers").format(
                name=name, size=array.size
            )
        )
    if array.size > 2 * limits.MAX_SAMPLES:
        raise ValueError(
            _("{name} must hold at most {most} points").format(name=name, most=limits.MAX_SAMPLES)
        )
    with np.errstate(invalid="ignore"):
        array[np.abs(array) > limits.MAX_COORDINATE] = np.nan  # off any picture: not drawn
    return array.reshape(-1, 2)


# Pixels as one int64 key each, sorted in reading order: (x, y) -> (y + _OFFSET) * _WIDE + x + ...
_OFFSET = 2**21
_WIDE = 2**22


def _pixel_keys(pixels: Any, name: str) -> np.ndarray:
    array = _as_pairs(pixels, name)
    require_finite(array, name)
    whole = np.floor(array).astype(np.int64)
    return np.unique((whole[:, 1] + _OFFSET) * _WIDE + whole[:, 0] + _OFFSET)


def _pixel_at(key: Any) -> tuple[int, int]:
    return int(key % _WIDE - _OFFSET), int(key // _WIDE - _OFFSET)


def side_by_side(
    left: Any,
    right: Any,
    titles: tuple[str, str] = (N_("expected"), N_("your result")),
    shrink: str = "mean",
) -> bytes:
    """Two images in [0, 1] side by side, each at most 160 screen pixels across, as a PNG.

    A pass's picture: the reference's result beside the student's. An image
    larger than that is shrunk by whole blocks, each block's ``"mean"`` (a
    dithered picture's tone) or ``"max"`` (a one-pixel curve stays visible);
    a smaller one is zoomed by whole pixels, so nothing is blurred.
    """
    shrink = str(shrink)
    if shrink not in ("mean", "max"):
        raise ValueError(
            _("shrink must be 'mean' or 'max'; got {shrink}").format(shrink=repr(shrink))
        )
    panels = [_fitted(np.asarray(image, dtype=float), shrink) for image in (left, right)]
    height = max(p.shape[0] for p in panels)
    width = sum(p.shape[1] for p in panels) + 36
    figure = Figure(figsize=(width / 100, (height + 24) / 100), dpi=100)
    offset = 12
    for panel, name in zip(panels, titles, strict=True):
        h, w = panel.shape[:2]
        axes = figure.add_axes((offset / width, 4 / (height + 24), w / width, h / (height + 24)))
        style = {} if panel.ndim == 3 else {"cmap": "gray", "vmin": 0.0, "vmax": 1.0}
        axes.imshow(np.clip(panel, 0, 1), interpolation="nearest", **style)
        axes.set_xticks([])
        axes.set_yticks([])
        axes.set_title(_translated(str(name)), fontsize=7, pad=2)
        offset += w + 12
    return figure_png(figure)


def _translated(text: str) -> str:
    """A title or label in the current language; the empty title stays empty."""
    return _(text) if text else text


def _fitted(image: np.ndarray, shrink: str, largest: int = 160) -> np.ndarray:
    """``image`` at a whole zoom, or shrunk by whole blocks, to at most ``largest`` pixels."""
    if image.ndim not in (2, 3) or image.size == 0 or max(image.shape[:2]) > limits.MAX_SIDE:
        return np.zeros((8, 8))
    image = np.where(np.isfinite(image), image, 0.0)
    side = max(image.shape[:2])
    if side <= largest:
        zoom = max(1, largest // side)
        return np.repeat(np.repeat(image, zoom, axis=0), zoom, axis=1)
    block = -(-side // largest)
    height, width = (-(-n // block) * block for n in image.shape[:2])
    padding = [(0, height - image.shape[0]), (0, width - image.shape[1])]
    padded = np.pad(image, padding + [(0, 0)] * (image.ndim - 2))
    blocks = padded.reshape(height // block, block, width // block, block, *image.shape[2:])
    return blocks.max(axis=(1, 3)) if shrink == "max" else blocks.mean(axis=(1, 3))
