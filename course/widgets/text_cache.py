"""Agg's text drawn fast during a drag, pixel for pixel as Agg draws it.

A drag redraws the moving artists' text at every step: a title with new
numbers, a point's label. Three caches spare FreeType the work that does not
change: :class:`GlyphCache` keeps each glyph's bitmap, the layout cache it
installs keeps each text's glyph layout (numbers laid out from their pairs of
characters), and :class:`FixedText` is a text placed once for each ascent and
descent of its strings, not measured anew. The tests compare their pixels
with Agg's own.

:class:`~course.widgets.figure_view.FigureView` installs the glyph cache on
its renderer; the apps draw their changing numbers as :class:`FixedText`. The
apps are the only callers (``UNCHECKED = True``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib import colors as mcolors
from matplotlib import ft2font
from matplotlib.backends import backend_agg
from matplotlib.text import Text

__all__ = ["FixedText", "GlyphCache", "SteadyText"]

UNCHECKED = True  # see the module docstring


# Matplotlib 3.11's FreeType render mode; older releases draw text their own way, uncached.
_RENDER_NORMAL = getattr(getattr(ft2font, "RenderMode", None), "NORMAL", None)


class GlyphCache:
    """Agg's text drawing with each glyph's bitmap rendered once, then reused.

    Matplotlib 3.11 asks FreeType for every glyph of a text at every draw; a
    drag redraws the title of lesson 01's app (41 glyphs, its numbers new at
    each step) and a point's label, which cost half the drawing. FreeType's
    bitmap of a glyph depends on its font, size, flags and the position's
    fraction of a pixel (in 1/64ths) only: moved by whole pixels, it is the
    same bitmap, so a cached copy painted at the new place gives exactly the
    pixels Agg draws (the tests compare them). Rotated, slanted, stretched,
    aliased and mathtext text goes to Agg's own method unchanged, as does
    everything on a matplotlib without this private method.
    """

    def __init__(self, renderer: Any, original: Any) -> None:
        self.renderer, self.original = renderer, original
        self.bitmaps: dict[tuple, tuple[np.ndarray, int, int]] = {}

    @classmethod
    def install(cls, renderer: Any) -> None:
        """Route ``renderer``'s glyph drawing through a cache, once, where matplotlib allows."""
        original = getattr(renderer, "_draw_text_glyphs_and_boxes", None)
        if original is None or isinstance(original, cls) or _RENDER_NORMAL is None:
            return
        renderer._draw_text_glyphs_and_boxes = cls(renderer, original)
        renderer.draw_text = _LayoutCache(renderer, renderer.draw_text)

    def __call__(self, gc: Any, x: float, y: float, angle: float, glyphs: Any, boxes: Any) -> None:
        glyphs = list(glyphs)
        plain = all(glyph[3] == 0 and glyph[4] == 1 for glyph in glyphs)  # no slant, no stretch
        if angle != 0 or boxes or not gc.get_antialiased() or not plain:
            self.original(gc, x, y, angle, glyphs, boxes)
            return
        flags = backend_agg.get_hinting_flag()
        renderer = self.renderer
        height = renderer.height
        pieces = []  # (bitmap, left column, top row) per glyph
        for font, size, glyph_index, _slant, _extend, dx, dy in glyphs:  # dy is upwards
            # The glyph's origin in FreeType's 26.6 fixed point, y upwards, as Agg places it.
            origin_x = round(0x40 * (x + dx))
            origin_y = round(0x40 * (height - y + dy))
            key = (font.fname, size, renderer.dpi, glyph_index, flags, origin_x % 64, origin_y % 64)
            cached = self.bitmaps.get(key)
            if cached is None:
                font.set_size(size, renderer.dpi)
                font._set_transform([[0x10000, 0], [0, 0x10000]], [origin_x, origin_y])
                bitmap = font._render_glyph(glyph_index, flags, _RENDER_NORMAL)
                cached = (
                    np.array(bitmap.buffer),
                    bitmap.left - (origin_x >> 6),
                    bitmap.top - (origin_y >> 6),
                )
                self.bitmaps[key] = cached
            buffer, left, top = cached
            pieces.append((buffer, (origin_x >> 6) + left, int(height) - ((origin_y >> 6) + top)))
        # One call into Agg for the whole text where no two glyphs' inked pixels meet
        # (each call converts the graphics context anew: a tenth of a millisecond for
        # B(t)'s numbers); where they do, Agg blends each glyph over the last, as it does.
        merged = _merged_bitmaps(pieces) if len(pieces) > 1 else None
        for buffer, left, top in [merged] if merged is not None else pieces:
            # draw_text_image's y is downwards, at the bitmap's bottom side.
            renderer._renderer.draw_text_image(buffer, left, top + buffer.shape[0], 0, gc)


def _merged_bitmaps(
    pieces: list[tuple[np.ndarray, int, int]],
) -> tuple[np.ndarray, int, int] | None:
    """Glyph bitmaps placed at (left, top) as one bitmap; None if two inked pixels meet.

    Agg leaves a pixel a bitmap does not cover (0) as it is, so one bitmap of
    glyphs that share no inked pixel paints what painting them one by one does.

    >>> dot = np.full((1, 1), 200, dtype=np.uint8)
    >>> image, left, top = _merged_bitmaps([(dot, 3, 5), (dot, 5, 6)])
    >>> image.tolist(), left, top
    ([[200, 0, 0], [0, 0, 200]], 3, 5)
    >>> _merged_bitmaps([(dot, 3, 5), (dot, 3, 5)]) is None
    True
    """
    left = min(piece[1] for piece in pieces)
    top = min(piece[2] for piece in pieces)
    right = max(piece[1] + piece[0].shape[1] for piece in pieces)
    bottom = max(piece[2] + piece[0].shape[0] for piece in pieces)
    image = np.zeros((bottom - top, right - left), dtype=np.uint8)
    for buffer, column, row in pieces:
        height, width = buffer.shape
        region = image[row - top : row - top + height, column - left : column - left + width]
        if np.logical_and(region, buffer).any():
            return None
        region |= buffer
    return image, left, top


class _LayoutCache:
    """Agg's ``draw_text`` with each text's glyph layout computed once, then reused.

    Matplotlib 3.11 lays a text out anew (shaping it, loading and hinting
    every glyph) at every draw: a quarter of a millisecond for a point's
    label "P1", which a drag redraws at every step. The layout (which glyphs
    of which font, at which offsets from the text's origin) depends on the
    string, the font, its size, the resolution and the hinting only, not on
    where the text stands, so the cached one is the one Agg computes (the
    tests compare the pixels). Mathtext and anything with font features or
    a language go to Agg unchanged. At most :attr:`SIZE` layouts are kept.

    A drag shows new numbers at every step ("(355.0, 213.8)" takes Agg a
    millisecond to lay out): a string of :data:`COMPOSABLE` characters is
    laid out from the layouts of its pairs of neighbours, each computed
    once. Shaping such a string moves each glyph by its predecessor's
    advance and their pair's kerning, which is what the pair's layout holds;
    the sums are of multiples of 1/64 pixel, exact in floating point (the
    tests compare with Agg's layout of every pair and of random strings).
    """

    SIZE = 256
    #: Numbers and what surrounds them: no ligatures, nothing shaped beyond a pair.
    COMPOSABLE = frozenset("0123456789.,-+() ")

    def __init__(self, renderer: Any, original: Any) -> None:
        self.renderer, self.original = renderer, original
        self.layouts: dict[tuple, list[tuple]] = {}
        self.pairs: dict[tuple, tuple | None] = {}

    def __call__(
        self,
        gc: Any,
        x: float,
        y: float,
        s: str,
        prop: Any,
        angle: float,
        ismath: Any = False,
        mtext: Any = None,
    ) -> None:
        plain = mtext is None or (mtext.get_fontfeatures() is None and mtext.get_language() is None)
        if ismath or not plain:
            self.original(gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)
            return
        renderer = self.renderer
        font = renderer._prepare_font(prop)  # the font list rcParams give now, sized
        size = prop.get_size_in_points()
        flags = backend_agg.get_hinting_flag()
        key = (font, s, size, renderer.dpi, flags)
        glyphs = self.layouts.get(key)
        if glyphs is None:
            glyphs = self._composed(font, s, size, flags)
            if glyphs is None:
                glyphs = [
                    (item.ft_object, size, item.glyph_index, 0, 1, item.x, item.y)
                    for item in font._layout(s, flags=flags)
                ]
            if len(self.layouts) >= self.SIZE:
                self.layouts.clear()
            self.layouts[key] = glyphs
        renderer._draw_text_glyphs_and_boxes(gc, x, y, angle, glyphs, [])

    def _composed(self, font: Any, s: str, size: float, flags: Any) -> list[tuple] | None:
        """The layout of ``s`` from its pairs' layouts; None unless every pair is plain."""
        if len(s) < 2 or not self.COMPOSABLE.issuperset(s):
            return None
        glyphs, x, previous = [], 0.0, None
        for index in range(len(s) - 1):
            pair = self._pair(font, s[index : index + 2], size, flags)
            if pair is None or (previous is not None and previous != pair[0]):
                return None  # a pair shaped into something else: Agg lays the string out
            glyphs.append((*pair[0], 0, 1, x, 0.0))
            x += pair[2]
            previous = pair[1]
        glyphs.append((*previous, 0, 1, x, 0.0))
        return glyphs

    def _pair(self, font: Any, pair: str, size: float, flags: Any) -> tuple | None:
        """((font, size, glyph), (font, size, glyph), advance) of a two-glyph layout, or None."""
        key = (font, pair, size, self.renderer.dpi, flags)
        if key not in self.pairs:
            items = font._layout(pair, flags=flags)
            plain = len(items) == 2 and items[0].x == 0 and items[0].y == 0 and items[1].y == 0
            self.pairs[key] = (
                (
                    (items[0].ft_object, size, items[0].glyph_index),
                    (items[1].ft_object, size, items[1].glyph_index),
                    items[1].x,
                )
                if plain
                else None
            )
        return self.pairs[key]


class FixedText(Text):
    """A one-line text that stays where it stands while its characters change: numbers.

    ``Text.draw`` measures every new string to place it, and FreeType lays
    it out and hints its glyphs to do so (a millisecond for "(355.0,
    213.8)"), though a left-aligned text only moves when its ascent or
    descent do. Those of a string are the largest of its characters' (its
    box is the union of theirs), so a string of characters measured once
    needs no measuring: it is drawn where ``Text.draw`` puts the first
    string with the same ascent and descent, by the call ``Text.draw``
    makes. Anything else (rotated, centred, several lines, mathtext, a box,
    path effects) is drawn by ``Text.draw``.

    Examples
    --------
    >>> from course.widgets.figure_view import FigureView
    >>> view = FigureView(shape=(30, 100))
    >>> numbers = view.figure.add_artist(FixedText(0.05, 0.3, "(3.5, -2.0)", animated=True))
    >>> _ = view.render_moving([numbers])
    >>> numbers.set_text("(41.0, 7.5)")
    >>> _ = view.render_moving([numbers])
    >>> bool((view.pixels()[..., 0] < 128).any()), len(numbers._origins)
    (True, 1)
    """

    #: The horizontal alignments it places itself; Text.draw draws the others.
    PLACED_ALIGNMENTS: tuple[str, ...] = ("left",)

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._extents: dict[tuple, tuple[float, float]] = {}
        self._origins: dict[tuple, tuple[float, float]] = {}

    def draw(self, renderer: Any) -> None:
        text = self.get_text()
        plain = (
            renderer is not None
            and self.get_visible()
            and text
            and "\n" not in text
            and self.get_rotation() == 0
            and self.get_horizontalalignment() in self.PLACED_ALIGNMENTS
            and not self.get_usetex()
            and not self.get_wrap()
            and self._bbox_patch is None
            and not self.get_path_effects()
            and not self._preprocess_math(text)[1]
        )
        origin = self._origin(renderer, text) if plain else None
        if origin is None:
            super().draw(renderer)
            return
        self._renderer = renderer
        renderer.open_group("text", self.get_gid())
        gc = renderer.new_gc()  # set up as Text.draw sets it up
        gc.set_foreground(mcolors.to_rgba(self.get_color()), isRGBA=True)
        gc.set_alpha(self.get_alpha())
        gc.set_url(self._url)
        gc.set_antialiased(self._antialiased)
        gc.set_snap(self.get_snap())
        self._set_gc_clip(gc)
        renderer.draw_text(
            gc, *origin, text, self._fontproperties, self.get_rotation(), ismath=False, mtext=self
        )
        gc.restore()
        renderer.close_group("text")
        self.stale = False

    def _position(self) -> tuple[float, float]:
        """Its position in display pixels, through its transform, as Text.draw finds it."""
        return self.get_transform().transform(
            (float(self.convert_xunits(self._x)), float(self.convert_yunits(self._y)))
        )

    def _origin(self, renderer: Any, text: str) -> tuple[float, float] | None:
        """Where Text.draw would draw ``text``: measured for its ascent and descent once."""
        place = (
            id(renderer),
            renderer.dpi,
            hash(self._fontproperties),
            renderer.get_canvas_width_height(),
            self._x,
            self._y,
            self.get_verticalalignment(),
            tuple(self.get_transform().get_matrix().ravel()),
        )
        ascent = descent = 0.0
        for character in set(text):
            key = (place[:3], character)
            if key not in self._extents:
                _, height, down = renderer.get_text_width_height_descent(
                    character, self._fontproperties, False
                )
                self._extents[key] = (height - down, down)
            up, down = self._extents[key]
            ascent, descent = max(ascent, up), max(descent, down)
        key = (*place, ascent, descent)
        if key not in self._origins:
            _, height, down = renderer.get_text_width_height_descent(
                text, self._fontproperties, False
            )
            if (height - down, down) != (ascent, descent):
                return None  # not the union of its characters' boxes: measured by Text.draw
            # Text.draw's own arithmetic, on this text's layout.
            _, info, _ = self._get_layout(renderer)
            x, y = info[0][2]
            posx, posy = self._position()
            x, y = x + posx, y + posy
            if renderer.flipy():
                y = renderer.get_canvas_width_height()[1] - y
            self._origins[key] = (x, y)
        return self._origins[key]


class SteadyText(FixedText):
    """A centred or right-aligned :class:`FixedText` whose letters stay put as its digits change.

    A centred text moves as its width does: "RMSE here 0.111" stands a
    little right of "RMSE here 0.888", and measuring each new string to
    centre it is what :class:`FixedText` spares. This one is placed by the
    width of its string with every digit a 0, measured once per such
    string: its numbers change in place, and it moves only when a digit
    comes or goes. It stands where ``Text.draw`` puts that string of zeros,
    to the pixel: centred to within the difference of two digits' ink.

    Examples
    --------
    >>> from course.widgets.figure_view import FigureView
    >>> view = FigureView(shape=(30, 200))
    >>> note = view.figure.add_artist(SteadyText(0.5, 0.3, "RMSE 0.111", ha="center"))
    >>> renderer = view.canvas.get_renderer()
    >>> note._origin(renderer, "RMSE 0.111") == note._origin(renderer, "RMSE 0.888")
    True
    """

    PLACED_ALIGNMENTS = ("left", "center", "right")

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._widths: dict[tuple, float] = {}

    def _origin(self, renderer: Any, text: str) -> tuple[float, float] | None:
        origin = super()._origin(renderer, text)  # its y follows the ascent and descent alone
        share = {"left": 0.0, "center": 0.5, "right": 1.0}[self.get_horizontalalignment()]
        if origin is None or not share:
            return origin
        zeros = text.translate(_DIGITS_AS_ZEROS)
        key = (id(renderer), renderer.dpi, hash(self._fontproperties), zeros)
        if key not in self._widths:
            self._widths[key] = renderer.get_text_width_height_descent(
                zeros, self._fontproperties, False
            )[0]
        return self._position()[0] - share * self._widths[key], origin[1]


_DIGITS_AS_ZEROS = str.maketrans("123456789", "000000000")
