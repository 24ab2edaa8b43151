"""What every app shares: a matplotlib figure shown as a picture the student can grab.

The picture is a :class:`~course.widgets.picture.Picture` widget holding a PNG
that a matplotlib ``Figure`` renders on the Agg canvas
(:class:`~course.widgets.figure_view.FigureView`). An app builds its figure and artists
once; a control's change calls ``update``, which only changes artist data,
and then the figure is rendered again. No pyplot, no figure rebuilt per step,
no frontend backend: it passes nbval, runs in JupyterLab and Voila, and the
update can be driven from plain Python in a test by setting control values.

Where a parameter is a point (a control point, a vertex, where to paste), the
student drags it on the picture (:mod:`course.widgets.pointer`: its
:class:`~course.widgets.pointer.Handle`, which apps import from here with
:class:`SliderApp`). Every point also has a text box, for the keyboard
(:func:`parse_points`, :func:`format_points`); the two stay in step.
"""

from __future__ import annotations

import base64
import itertools
import re
import unicodedata
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import ipywidgets as widgets
import numpy as np
from matplotlib.axes import Axes

from course import limits
from course._validate import as_choice, as_int, as_shape, describe
from course.i18n import N_, _
from course.widgets.figure_view import FigureView
from course.widgets.picture import Still, ZoomedPixels
from course.widgets.pointer import Handle, PointerMixin

# Handle is listed here too: an app's handles() returns them, and apps import both from here.
__all__ = [
    "Handle",
    "SliderApp",
    "format_points",
    "pad",
    "parse_points",
]

# A decimal number in ASCII digits (``\\d`` would take Arabic-Indic and full-width ones too).
# Each digit has one place in it, so a long run of digits that fails is given up in one pass:
# the ambiguous ``\\d+\\.?\\d*`` tried every split of the run, and took seconds on 16,000.
_NUMBER = r"[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
# One point: two decimal numbers and a comma between them, in brackets if the student likes.
_POINT = re.compile(
    rf"\s*(?:\(\s*({_NUMBER})\s*,\s*({_NUMBER})\s*\)"
    rf"|\[\s*({_NUMBER})\s*,\s*({_NUMBER})\s*\]"
    rf"|({_NUMBER})\s*,\s*({_NUMBER}))\s*"
)
_FORM = N_("write each point as x, y and separate points with ';' or a new line")


def pad(text: str, width: int, align: str = "<") -> str:
    """``text`` padded with spaces to ``width`` columns of a monospaced font, as in a table.

    A Chinese character takes two columns, so a table of Chinese names keeps its columns
    where ``f"{text:{width}s}"`` would not; for English it is exactly that. ``align`` is
    ``"<"`` (text on the left) or ``">"``; text wider than ``width`` is left whole.

    Examples
    --------
    >>> pad("RMSE", 6, ">") + "|", pad("均方根", 8) + "|"
    ('  RMSE|', '均方根  |')
    """
    if not isinstance(text, str):
        raise TypeError(_("text must be a str; got {text}").format(text=describe(text)))
    width = as_int(width, "width", minimum=0, maximum=1000)
    align = as_choice(align, "align", ("<", ">"))
    columns = sum(2 if unicodedata.east_asian_width(c) in "WF" else 1 for c in text)
    fill = " " * max(width - columns, 0)
    return fill + text if align == ">" else text + fill


def _why_not_a_point(piece: str) -> str:
    """What keeps ``piece`` (one point's text) from reading as x, y, for the student to fix."""
    numbers = re.findall(_NUMBER, piece)
    foreign = next((character for character in piece if not character.isascii()), None)
    if foreign is not None:
        return _(
            "write the numbers with the digits 0-9 and the ASCII comma, point and minus; "
            "got {character}"
        ).format(character=repr(foreign))
    if re.search(r"\b0[xXbBoO]", piece):
        return _("numbers must be decimal (0x10 and 0b1 are not read)")
    if re.search(r"[0-9],[0-9]", piece) and len(numbers) > 2:
        return _("a decimal comma is not read: write 90.5, not 90,5")
    if len(numbers) > 2 or (len(numbers) == 1 and "," not in piece):
        return _("a point is two numbers; got {count}").format(count=len(numbers))
    if not numbers:
        return _("there is no number in it")
    if "," not in piece:
        return _("the x and the y need a comma between them")
    return _("expected two decimal numbers such as 90.5, -3 or 1e2")


def parse_points(text: str, single: bool = False) -> np.ndarray:
    """Read ``"x, y; x, y; ..."`` into an (N, 2) array; ValueError on anything else.

    Each point is two decimal numbers separated by a comma, optionally in
    brackets; points are separated by ``;`` or new lines. Text that could be
    read more than one way is refused, never guessed at: decimal commas
    (``90,5``), hexadecimal or binary literals (``0x10``), a point without
    its comma (``3 4``), digits other than 0-9 (``١٢``, ``１２``). Text longer than
    ``course.limits.MAX_TYPED_TEXT`` characters is refused before it is read.
    ``single`` is for a box that holds one point: its messages speak of that point alone.

    Examples
    --------
    >>> parse_points("10, 10; 690, 10.5; (3, 4)")
    array([[ 10. ,  10. ],
           [690. ,  10.5],
           [  3. ,   4. ]])
    >>> parse_points("90,5 610,5; 170, 130")
    Traceback (most recent call last):
    ...
    ValueError: points: point 1, '90,5 610,5', is not x, y: a decimal comma is not read: \
write 90.5, not 90,5 (write each point as x, y and separate points with ';' or a new line)
    >>> parse_points("abc", single=True)
    Traceback (most recent call last):
    ...
    ValueError: 'abc' is not x, y: there is no number in it (type one point as x, y, such as \
10, 20)
    """
    if not isinstance(text, str):
        raise TypeError(
            _("text must be a string such as '10, 10; 690, 10'; got {text}").format(
                text=describe(text)
            )
        )
    if len(text) > limits.MAX_TYPED_TEXT:  # before any parsing: its work stays bounded
        raise ValueError(
            _("points: expected at most {most} characters; got {count}").format(
                most=limits.MAX_TYPED_TEXT, count=len(text)
            )
        )
    pieces = [piece.strip() for piece in re.split(r"[;\n]", text)]
    pieces = [piece for piece in pieces if piece]
    if not pieces:
        empty = (
            _("expected one point such as '10, 20'; got {text}")
            if single
            else _("points: expected text such as '10, 10; 690, 10'; got {text}")
        )
        raise ValueError(empty.format(text=repr(text)))
    numbers = []
    for index, piece in enumerate(pieces, start=1):
        match = _POINT.fullmatch(piece)
        if match is None:
            shown = piece if len(piece) <= 40 else piece[:37] + "..."
            wrong = (
                _("{shown} is not x, y: {why} (type one point as x, y, such as 10, 20)")
                if single
                else _("points: point {index}, {shown}, is not x, y: {why} ({form})")
            )
            raise ValueError(
                wrong.format(
                    index=index, shown=repr(shown), why=_why_not_a_point(piece), form=_(_FORM)
                )
            )
        numbers.extend(float(value) for value in match.groups() if value is not None)
    points = np.array(numbers).reshape(-1, 2)
    if not np.isfinite(points).all():
        raise ValueError(_("points must be finite numbers"))
    if np.abs(points).max() > limits.MAX_COORDINATE:
        raise ValueError(
            _("points must lie within +-{bound:g}").format(bound=limits.MAX_COORDINATE)
        )
    return points


def format_points(points: Any) -> str:
    """The text form :func:`parse_points` reads.

    Examples
    --------
    >>> format_points(np.array([[10.0, 10.0], [2.5, 3.0]]))
    '10, 10; 2.5, 3'
    """
    return "; ".join(f"{x:g}, {y:g}" for x, y in np.asarray(points, dtype=float))


_MODEL_NUMBERS: dict[str, Iterator[int]] = {}


def _next_model_id(name: str) -> str:
    """A widget model id counted per app class in this kernel, not a random UUID.

    The notebook stores the id of the app it shows; counted, it is the same each
    time a lesson is run from the top, so running and saving a lesson leaves git
    clean. Each kernel counts from 1, and no two apps in one kernel share an id.
    """
    number = next(_MODEL_NUMBERS.setdefault(name, itertools.count(1)))
    return f"course-{name}-{number}"


class SliderApp(PointerMixin):
    """Controls beside a picture; a control's change, or a drag on the picture, redraws it.

    Subclasses build their artists in ``__init__`` (after calling this one
    with their controls) and implement ``update``, which reads the controls'
    values and changes artist data. ``controls`` maps names to widgets, so a
    test can do ``app.controls["t"].value = 0.3`` and inspect the result.
    Apps with points to drag also implement :meth:`handles` and :meth:`drag`
    (and, if they like, :meth:`click` and :meth:`double_click`); a test drives
    them with :meth:`pointer`, as the browser does.
    """

    #: Apps whose axes stay put redraw only their moving artists (:meth:`animate`)
    #: over a cached background; they call ``view.invalidate()`` when it changes.
    BLIT = False

    def __init__(
        self,
        controls: dict[str, widgets.ValueWidget],
        shape: tuple[int, int] = (500, 500),
        dpi: int = 100,
        format: str = "png",
    ) -> None:
        if not isinstance(controls, dict) or not all(
            isinstance(control, widgets.ValueWidget) for control in controls.values()
        ):
            raise TypeError(
                _("controls must map names to ipywidgets controls; got {controls}").format(
                    controls=describe(controls)
                )
            )
        shape = as_shape(shape, max_pixels=limits.MAX_FIGURE_PIXELS)
        dpi = as_int(dpi, "dpi", minimum=10, maximum=1000)
        format = as_choice(format, "format", ("png", "jpeg"))
        self.controls = controls
        self.view = FigureView(shape, dpi, format)
        self.figure = self.view.figure
        self.renders = 0
        self.status = widgets.Label()
        super().__init__()  # the pointer: nothing grabbed yet
        self._held = False
        self._restoring = False
        self._refused = False  # the status line says a value was refused
        self.moving: list[Any] = []
        # Pictures shown pixel for pixel, by axes: pasted, not drawn (BLIT apps).
        self.pixel_images: dict[Axes, np.ndarray | ZoomedPixels] = {}
        for control in controls.values():
            control.observe(self._on_change, names="value")
        self.view.image.on_msg(self._on_message)
        # Controls beside the picture when the window is wide enough, below it
        # when not: they never shrink, so their labels are never cut off.
        panel = widgets.VBox(
            [*controls.values(), self.status], layout=widgets.Layout(flex="0 0 auto")
        )
        self.widget = widgets.HBox(
            [self.view.image, panel],
            layout=widgets.Layout(align_items="flex-start", flex_flow="row wrap"),
            model_id=_next_model_id(type(self).__name__),
        )

    def value(self, name: str) -> Any:
        """The current value of control ``name``."""
        return self.controls[name].value

    def update(self) -> None:  # pragma: no cover - every app overrides it
        raise NotImplementedError

    def refresh(self) -> bytes:
        """Update the artists from the controls and render the picture."""
        self.update()
        self._place_highlight()
        self.renders += 1
        png = self.render()
        if self.grabbed is None:  # during a drag the browser shows a grabbing hand anyway
            self._publish_handles()
        return png

    def render(self) -> bytes:
        """Draw the figure, or only what moves over the cached rest when the app blits."""
        if self.BLIT:
            # While a handle is held, each step sends only what changed; the release
            # publishes the whole picture again.
            patches = self.grabbed is not None
            return self.view.render_moving(self.moving, self.pixel_images, patches)
        return self.view.render()

    def still(self, caption: str | None = None) -> Still:
        """The app's picture as it stands, as a :class:`~course.widgets.picture.Still`.

        For a lesson's opening picture: what the app shows, without the controls.
        """
        return Still(self.refresh(), caption or self.describe())

    def animate(self, *artists: Any) -> None:
        """Mark artists as moving: with :attr:`BLIT`, only these are redrawn each step."""
        for artist in artists:
            artist.set_animated(True)
            self.moving.append(artist)

    def _on_change(self, change: dict) -> None:
        if self._restoring:  # putting back a refused value: just draw it
            self.refresh()
            return
        refused = _not_finite(change["new"])
        if refused:
            self._restore(change, refused)
            return
        if self._held:
            return  # one redraw after the drag has set every control it moves
        if self._refused:
            self.status.value = ""  # a good value follows a refused one
            self._refused = False
        try:
            self.refresh()
        except (ValueError, TypeError) as error:
            self._restore(change, str(error))

    def _restore(self, change: dict, reason: str) -> None:
        """Put back a control's last good value and say why on the status line.

        A browser's slider sends only values it can show, but a notebook cell
        can set any (``app.controls["t"].value = float("nan")``; ipywidgets
        clamps an infinite value but lets NaN through). The app keeps drawing
        what it drew, and the student reads what was refused.
        """
        owner = change.get("owner")
        name = next((key for key, control in self.controls.items() if control is owner), "?")
        old = change.get("old")
        self._restoring = True
        try:
            owner.value = old
        finally:
            self._restoring = False
        self.status.value = _("Refused {name} = {value}: {reason}; kept {kept}").format(
            name=name, value=_format(change["new"]), reason=reason, kept=_format(old)
        )
        self._refused = True

    @contextmanager
    def holding(self) -> Iterator[None]:
        """Change several controls with one redraw, after the block."""
        self._held = True
        try:
            yield
        finally:
            self._held = False
        self.refresh()

    def typed_points(
        self,
        control: str,
        kept: Any,
        count: int,
        low: Any = -np.inf,
        high: Any = np.inf,
        whole: bool = False,
    ) -> np.ndarray:
        """The ``count`` points typed in text ``control``, if they are within bounds; else ``kept``.

        ``low`` and ``high`` bound x and y (a number, or one per axis), both
        included; ``whole`` asks for whole pixels. A text that fails keeps
        the last points, stays as typed for the student to fix, and the
        status line says why.
        """
        try:
            points = parse_points(self.value(control), single=count == 1)
            if len(points) != count:
                expected = (
                    _("expected {count} points; got {given}")
                    if count > 1
                    else _("expected {count} point; got {given}")
                )
                raise ValueError(expected.format(count=count, given=len(points)))
            if whole and (points != np.round(points)).any():
                raise ValueError(_("expected whole pixels"))
            low_x, low_y = np.broadcast_to(low, 2)
            high_x, high_y = np.broadcast_to(high, 2)
            if (
                not ((low_x <= points[:, 0]) & (points[:, 0] <= high_x)).all()
                or not ((low_y <= points[:, 1]) & (points[:, 1] <= high_y)).all()
            ):
                raise ValueError(
                    _("x must lie from {x0:g} to {x1:g}, y from {y0:g} to {y1:g}").format(
                        x0=low_x, x1=high_x, y0=low_y, y1=high_y
                    )
                )
        except ValueError as error:
            self.status.value = _("Kept the last {control}: {error}").format(
                control=control, error=error
            )
            return np.array(kept, dtype=float)
        self.status.value = ""
        return points

    # --- text -----------------------------------------------------------------

    def describe(self) -> str:
        """A stable one-line summary: the app's name and its controls' values."""
        values = ", ".join(
            f"{name}={_format(control.value)}" for name, control in self.controls.items()
        )
        return f"{type(self).__name__}({values})"

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        # JupyterLab shows the live widget. The text is what nbval compares, so
        # it must not hold PNG bytes; the PNG is the still picture that static
        # viewers (GitHub, nbviewer, a notebook opened without a kernel) show.
        if self.renders == 0:
            self.refresh()
        bundle = self.widget._repr_mimebundle_(**kwargs)
        bundle["text/plain"] = self.describe()
        picture = base64.b64encode(bytes(self.view.image.value)).decode("ascii")
        bundle[f"image/{self.view.image.format}"] = picture
        return bundle


def _not_finite(value: Any) -> str:
    """Why a control's value is refused before drawing ("" when it is not): NaN or infinite."""
    values = value if isinstance(value, tuple) else (value,)
    for item in values:
        if isinstance(item, (float, np.floating)) and not np.isfinite(item):
            return _("expected a finite number")
    return ""


def _format(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, tuple):
        return "(" + ", ".join(_format(v) for v in value) + ")"
    return repr(value)
