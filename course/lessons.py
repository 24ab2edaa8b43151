"""The course's lessons: found from the notebooks, described by a small registry.

Everything that can be read off a notebook is read off it: a lesson exists
when ``notebooks/NN_topic.ipynb`` exists, its title is the notebook's first
heading and its summary the paragraph after it. What cannot be read off a
notebook is registered here, one :class:`Lesson` per number in
:data:`LESSONS`: the handout task it answers, what it teaches in one line,
its key pictures (for ``python -m course gallery`` and the course map), and
the slider that the browser tests move like a student and what the picture
must show afterwards. A notebook without an entry is still listed, tested
and exported; adding the entry is all a new lesson needs. For example::

    "03": Lesson(
        "03",
        handout="GAMES101 homework 4, improvement part (seed 000): anti-aliasing",
        teaches="one line on what the lesson teaches",
        pictures=(Picture("03_name", "caption", lambda: app_picture(SomeApp(...))),),
        slider=SliderMove(
            build=lambda: SomeApp(...),  # exactly as the notebook's first app cell
            control="width",  # a key of app.controls: an IntSlider or FloatSlider
            moves=(("ArrowRight", "ArrowRight"), ("End",)),
            landmarks=_some_landmarks,  # app -> [Landmark], from the library's functions
        ),
    ),

where ``_some_landmarks(app)`` computes, with the library (not the app's
artists), a few pixels whose colour is then known, using
:func:`landmark_at` to map data coordinates to the picture.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from course.bezier import bernstein_basis, de_casteljau
from course.widgets import BernsteinBasisApp, DeCasteljauApp, SliderApp
from course.widgets.de_casteljau import DEFAULT_POINTS, parse_points

__all__ = [
    "LESSONS",
    "NOTEBOOKS",
    "Landmark",
    "Lesson",
    "Notebook",
    "Picture",
    "SliderMove",
    "app_picture",
    "landmark_at",
    "notebooks",
]

#: The lessons' folder when the package is used from its repository (``pip install -e``).
NOTEBOOKS = Path(__file__).resolve().parent.parent / "notebooks"
_LESSON_FILE = re.compile(r"^(\d\d)_\w+\.ipynb$")
_HEADING = re.compile(r"^#\s+(.+?)\s*$", re.MULTILINE)


@dataclass(frozen=True)
class Landmark:
    """A pixel of an app's picture whose colour the library determines.

    ``row`` and ``column`` index the picture (row 0 at the top); the pixel
    must be within ``tolerance`` of ``color`` in every RGB channel (0-255).
    """

    what: str
    row: int
    column: int
    color: tuple[int, int, int]
    tolerance: int = 40


@dataclass(frozen=True)
class SliderMove:
    """How a student moves one slider of a lesson's first app, and what must follow.

    ``build`` makes the app exactly as the notebook's first app cell does,
    so that a test can set ``control`` to the value the browser shows and
    render the picture the kernel should have sent. ``moves`` are key
    sequences pressed on the slider's focused handle (Playwright key names);
    the picture is checked after each one. ``landmarks(app)`` names pixels
    whose colour the library computes for the app's current control values
    (for lesson 01, the red dot at the point ``de_casteljau`` returns).
    """

    build: Callable[[], SliderApp]
    control: str
    moves: tuple[tuple[str, ...], ...]
    landmarks: Callable[[SliderApp], list[Landmark]]


@dataclass(frozen=True)
class Picture:
    """One key figure of a lesson: a file name (no suffix), a caption, a PNG renderer."""

    name: str
    caption: str
    render: Callable[[], bytes]


@dataclass(frozen=True)
class Lesson:
    """What the notebook cannot say about itself."""

    number: str
    handout: str
    teaches: str
    pictures: tuple[Picture, ...] = ()
    slider: SliderMove | None = None


@dataclass(frozen=True)
class Notebook:
    """A lesson notebook as found on disk, with its registry entry if it has one."""

    number: str
    path: Path
    title: str
    summary: str
    lesson: Lesson | None

    @property
    def teaches(self) -> str:
        return self.lesson.teaches if self.lesson else self.summary

    @property
    def handout(self) -> str:
        return self.lesson.handout if self.lesson else ""

    @property
    def pictures(self) -> tuple[Picture, ...]:
        return self.lesson.pictures if self.lesson else ()


def notebooks(folder: str | Path = NOTEBOOKS, index: bool = False) -> list[Notebook]:
    """Every ``NN_topic.ipynb`` in ``folder``, in lesson order.

    The course map ``00_index.ipynb`` is left out unless ``index`` is true.

    Examples
    --------
    >>> [(book.number, book.title) for book in notebooks()][:2]
    [('01', "Lesson 01 · de Casteljau's algorithm"), ('02', 'Lesson 02 · The Bernstein form')]
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise ValueError(f"notebooks: expected a folder of NN_topic.ipynb files; got {folder}")
    found = []
    for path in sorted(folder.iterdir()):
        match = _LESSON_FILE.match(path.name)
        if not match or (match.group(1) == "00" and not index):
            continue
        title, summary = _title_and_summary(path)
        number = match.group(1)
        found.append(Notebook(number, path, title, summary, LESSONS.get(number)))
    return found


def _title_and_summary(path: Path) -> tuple[str, str]:
    """The first markdown heading and the first paragraph after it."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    for cell in cells:
        if cell["cell_type"] != "markdown":
            continue
        text = "".join(cell["source"])
        heading = _HEADING.search(text)
        if heading:
            rest = text[heading.end() :].strip()
            paragraph = rest.split("\n\n")[0] if rest else ""
            return heading.group(1), " ".join(paragraph.split())
    raise ValueError(f"{path.name}: a lesson notebook starts with a '# Title' markdown heading")


def app_picture(app: SliderApp) -> bytes:
    """The PNG an app shows for its current control values."""
    return app.refresh()


def landmark_at(
    app: SliderApp, axes, point, color: tuple[int, int, int], what: str, tolerance: int = 40
) -> Landmark:
    """The picture pixel where ``axes`` draws the data point ``point``.

    Matplotlib's display coordinates have y up from the figure's bottom;
    the picture's rows go down from its top, hence the flip.
    """
    x, y = axes.transData.transform(np.asarray(point, dtype=float))
    height = app.figure.bbox.height
    return Landmark(what, round(float(height - y)), round(float(x)), color, tolerance)


CRIMSON = (220, 20, 60)


# Lesson 01: de Casteljau's algorithm.
def _de_casteljau_landmarks(app: SliderApp) -> list[Landmark]:
    points = parse_points(app.value("points"))
    t = float(app.value("t"))
    point = de_casteljau(points, t)
    return [landmark_at(app, app.axes, point, CRIMSON, f"B({t:.2f}) by de_casteljau")]


def _de_casteljau_picture(t: float, count: int = 4) -> Picture:
    return Picture(
        f"01_de_casteljau_degree{count - 1}_t{t:.2f}",
        f"de Casteljau's levels for {count} control points at t = {t:.2f}",
        lambda: app_picture(DeCasteljauApp(points=DEFAULT_POINTS[:count], t=t)),
    )


# Lesson 02: the Bernstein form.
def _bernstein_landmarks(app: SliderApp) -> list[Landmark]:
    degree, t = int(app.value("degree")), float(app.value("t"))
    weights = bernstein_basis(degree, t)[0]
    landmarks = []
    for i, weight in enumerate(weights):
        centre = landmark_at(app, app.axes, (t, weight), CRIMSON, f"B_{i},{degree}({t:.2f})")
        # The vertical line at t is crimson too: look 2 px to its right, still
        # inside the marker (radius about 2.8 px), where only the marker is red.
        landmarks.append(replace(centre, column=centre.column + 2))
    return landmarks


def _bernstein_picture(degree: int, t: float) -> Picture:
    return Picture(
        f"02_bernstein_degree{degree}_t{t:.2f}",
        f"the degree-{degree} Bernstein basis and its weights at t = {t:.2f}",
        lambda: app_picture(BernsteinBasisApp(degree=degree, t=t)),
    )


#: One entry per lesson number; later lessons add theirs here.
LESSONS: dict[str, Lesson] = {
    "01": Lesson(
        "01",
        handout="GAMES101 homework 4, basic part (seed 000): recursive_bezier and the bezier "
        "loop; seeds 002-004's reversed step and float loop",
        teaches="a Bézier curve by repeated linear interpolation, every level under a t "
        "slider; recursion vs iteration; the handouts' pitfalls measured",
        pictures=(
            _de_casteljau_picture(0.5),
            _de_casteljau_picture(0.25),
            _de_casteljau_picture(0.75),
            _de_casteljau_picture(0.3, count=10),
        ),
        slider=SliderMove(
            build=DeCasteljauApp,
            control="t",
            moves=(("ArrowRight", "ArrowRight", "ArrowRight"), ("ArrowLeft",), ("End",)),
            landmarks=_de_casteljau_landmarks,
        ),
    ),
    "02": Lesson(
        "02",
        handout="GAMES101 homework 4's naive_bezier (seed 000), generalised to any degree "
        "with the recursive binomial (seed 002)",
        teaches="the Bernstein basis under a degree slider; binomials three ways; "
        "from Bernstein to de Casteljau; accuracy against the degree",
        pictures=(_bernstein_picture(3, 0.3), _bernstein_picture(9, 0.5)),
        slider=SliderMove(
            build=lambda: BernsteinBasisApp(degree=3, t=0.3),
            control="t",
            moves=(("ArrowLeft", "ArrowLeft"), ("Home",)),
            landmarks=_bernstein_landmarks,
        ),
    ),
}


def course_map(folder: str | Path = NOTEBOOKS) -> str:
    """The course map as a Markdown table: one row per lesson notebook in ``folder``.

    Each title links to its notebook (relative to ``folder``, so the table
    works in the notebooks' own folder and in a copy of it).

    Examples
    --------
    >>> print(course_map().splitlines()[0])
    | lesson | what it teaches | handout task it answers |
    """
    rows = [
        "| lesson | what it teaches | handout task it answers |",
        "|---|---|---|",
    ]
    for book in notebooks(folder):
        cells = [
            f"[{_escape(book.title)}]({book.path.name})",
            _escape(book.teaches),
            _escape(book.handout) or "(not registered in course.lessons)",
        ]
        rows.append("| " + " | ".join(cells) + " |")
    return "\n".join(rows)


def _escape(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")
