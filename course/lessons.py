"""The course's lessons: found from the notebooks, described by a small registry.

Everything that can be read off a notebook is read off it: a lesson exists
when ``notebooks/NN_topic.ipynb`` exists, its title is the notebook's first
heading and its summary the paragraph after it. What cannot be read off a
notebook is registered here, one :class:`Lesson` per number in
:data:`LESSONS`: the handout task it answers, what it teaches in one line,
its key pictures (for ``python -m course gallery`` and the course map), and
the sliders that the browser tests move like a student and what the picture
must show afterwards. A notebook without an entry is still listed, tested
and exported; adding the entry is all a new lesson needs. For example::

    "04": Lesson(
        "04",
        handout="Lab 1 report (seed 001), Task 4 (line drawing) and Task 5 (triangles)",
        teaches="one line on what the lesson teaches",
        pictures=(Picture("04_name", "caption", lambda: app_picture(LineApp())),),
        sliders=(
            SliderMove(
                build=LineApp,  # exactly as the notebook's cell builds the app
                control="y1",  # a key of app.controls: a slider
                moves=(("ArrowRight", "ArrowRight"), ("End",)),
                landmarks=views.line_landmarks,  # app -> [Landmark], by the library
                app=0,  # the notebook's first slider app
            ),
        ),
    ),

where the pictures and landmark functions live in :mod:`course.lesson_views`:
``line_landmarks(app)`` computes, with the library (``course.raster.line``),
not from the app's artists, pixels whose colour is then known, using
:func:`course.showcase.landmark_at` to map data coordinates to the picture.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

from course import lesson_views as views
from course.showcase import Landmark, Picture, SliderMove, app_picture, landmark_at
from course.widgets import DeCasteljauApp, LineApp, SupersampleApp

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
class Lesson:
    """What the notebook cannot say about itself."""

    number: str
    handout: str
    teaches: str
    pictures: tuple[Picture, ...] = ()
    sliders: tuple[SliderMove, ...] = ()


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


#: One entry per lesson number; later lessons add theirs here.
LESSONS: dict[str, Lesson] = {
    "01": Lesson(
        "01",
        handout="GAMES101 homework 4, basic part (seed 000): recursive_bezier and the bezier "
        "loop; seeds 002-004's reversed step and float loop",
        teaches="a Bézier curve by repeated linear interpolation, every level under a t "
        "slider; recursion vs iteration; the handouts' pitfalls measured",
        pictures=(
            views.de_casteljau_picture(0.5),
            views.de_casteljau_picture(0.25),
            views.de_casteljau_picture(0.75),
            views.de_casteljau_picture(0.3, count=10),
        ),
        sliders=(
            SliderMove(
                build=DeCasteljauApp,
                control="t",
                moves=(("ArrowRight", "ArrowRight", "ArrowRight"), ("ArrowLeft",), ("End",)),
                landmarks=views.de_casteljau_landmarks,
            ),
        ),
    ),
    "02": Lesson(
        "02",
        handout="GAMES101 homework 4's naive_bezier (seed 000), generalised to any degree "
        "with the recursive binomial (seed 002)",
        teaches="the Bernstein basis under a degree slider; binomials three ways; "
        "from Bernstein to de Casteljau; accuracy against the degree",
        pictures=(views.bernstein_picture(3, 0.3), views.bernstein_picture(9, 0.5)),
        sliders=(
            SliderMove(
                build=views.bernstein_app,
                control="t",
                moves=(("ArrowLeft", "ArrowLeft"), ("Home",)),
                landmarks=views.bernstein_landmarks,
            ),
        ),
    ),
    "03": Lesson(
        "03",
        handout="Lab 1 report (seed 001), Task 4 (Bresenham's line in every octant) and "
        "Task 5 (scanline triangle filling)",
        teaches="Bresenham's line in all eight octants against the report's 4-connected "
        "staircase; filled triangles with the top-left rule, no cracks and no double paint",
        pictures=(
            Picture(
                "03_line_bresenham_report_wu",
                "the line from (3, 6) to (27, 17): Bresenham, the report's staircase "
                "(|dx| + |dy| + 1 pixels) and Wu's anti-aliased line",
                lambda: app_picture(LineApp()),
            ),
            Picture(
                "03_triangles_top_left",
                "two triangles sharing an edge, filled with the top-left rule: every "
                "pixel painted once; right, 4 x 4 supersampled coverage",
                lambda: views.triangle_picture("top-left"),
            ),
            Picture(
                "03_triangles_closed",
                "the same triangles with the closed rule: the pixels whose centres lie on "
                "the shared edge are painted twice (red)",
                lambda: views.triangle_picture("closed"),
            ),
        ),
        sliders=(
            SliderMove(
                build=LineApp,
                control="y1",
                moves=(("ArrowRight",) * 4, ("Home",), ("End",)),
                landmarks=views.line_landmarks,
            ),
        ),
    ),
    "04": Lesson(
        "04",
        handout="Lab 1 report (seed 001), Task 6: shrink a 2500 x 2500 image to 320 x 320 "
        "by supersampling",
        teaches="supersampling as an estimate of the box filter, measured against a zone "
        "plate's exact downsample; the report's half-sample shift found and measured",
        pictures=(
            Picture(
                "04_zone_plate_rate1",
                "the zone plate shrunk to 320 x 320 with one sample per pixel: false rings, "
                "their difference from the exact box filter, and the error at every rate",
                lambda: app_picture(views.supersample_app(1)),
            ),
            Picture(
                "04_zone_plate_rate4",
                "the same at rate 4 (16 samples per pixel): the false rings are gone",
                lambda: app_picture(views.supersample_app(4)),
            ),
        ),
        sliders=(
            SliderMove(
                build=SupersampleApp,
                control="rate",
                moves=(("ArrowRight", "ArrowRight"), ("End",)),
                landmarks=views.supersample_landmarks,
            ),
        ),
    ),
    "05": Lesson(
        "05",
        handout="GAMES101 homework 4, improvement part (seeds 000, 002, 003): anti-aliasing "
        "the curve with seed 000's three addColor splats, seed 002's sub-sample falloff and "
        "seed 003's normalised splat",
        teaches="a curve's pixels as the coverage of a stroke: every handout splat measured "
        "against an exact reference and Agg, the t-step pitfall and the arc-length fix",
        pictures=(
            Picture(
                "05_every_variant_zoomed",
                "seed 000's curve near its first control point, every variant as 14 x 14 "
                "flat pixels under the true curve (red), beside the exact reference",
                views.zoom_every_variant,
            ),
            Picture(
                "05_seed000_three_splats_position0.10",
                "seed 000's left, middle and right addColor beside the exact reference, "
                "10% of the way along the curve, with each window's RMSE",
                lambda: app_picture(views.zoom_app()),
            ),
            Picture(
                "05_t_step_0.001_count",
                "bilinear_centres at the handouts' t step 0.001, splats counted as the "
                "handouts do: the brightness per unit length follows the curve's speed, "
                "about half at the fast ends",
                lambda: views.step_app_picture("count"),
            ),
            Picture(
                "05_t_step_0.001_arc_length",
                "the same splats weighted by arc length: brightness 1 per unit length "
                "along the curve, dipping only near the fast ends, where samples 0.001 "
                "apart leave gaps",
                lambda: views.step_app_picture("arc_length"),
            ),
        ),
        sliders=(
            SliderMove(
                build=views.zoom_app,
                control="position",
                moves=(("ArrowRight", "ArrowRight"), ("ArrowRight",) * 4, ("End",), ("Home",)),
                landmarks=views.zoom_landmarks,
            ),
        ),
    ),
    "06": Lesson(
        "06",
        handout="Lab 1 report (seed 001), Task 1: threshold, uniform random, blue noise, "
        "ordered 3 x 3 and Floyd-Steinberg error diffusion",
        teaches="gray levels from black and white dots: the lab's five methods and the "
        "classics beside them, error diffusion bit for bit fast, blue noise by "
        "void-and-cluster, the ordered matrix's bias and the x - 1 slip measured",
        pictures=(
            Picture(
                "06_dithering_table",
                "the photograph and every dithering method, each above the same window "
                "zoomed to show single dots",
                views.dithering_table,
            ),
            Picture(
                "06_dithering_ramp",
                "a gray ramp from 0 to 1 through every method",
                views.dithering_ramp,
            ),
            Picture(
                "06_gray_level_0.30",
                "a flat 0.30 patch: the ten ordered 3 x 3 patterns (k = 3 framed) and what "
                "each method makes of it",
                lambda: app_picture(views.gray_level_app()),
            ),
            Picture(
                "06_void_and_cluster_120_dots",
                "void-and-cluster after 120 dots of a 32 x 32 mask: the dots over their "
                "energy, the next dot circled, and the spectrum against white noise",
                views.void_and_cluster_picture,
            ),
        ),
        sliders=(
            SliderMove(
                build=views.gray_level_app,
                control="level",
                moves=(("ArrowLeft",), ("ArrowRight",) * 5, ("End",)),
                landmarks=views.gray_level_landmarks,
                app=1,
            ),
        ),
    ),
    "07": Lesson(
        "07",
        handout="Lab 1 report (seed 001), Task 2: 3 x 3 blur with the report's border rule "
        "and Sobel edges",
        teaches="blur and Sobel edges with 3 x 3 kernels, separable and fast; the four "
        "border rules and zero padding's dark frame, measured; scipy.ndimage agrees inside",
        pictures=(
            Picture(
                "07_blur_and_edges",
                "the photograph blurred once and five times, and its Sobel magnitude (gray "
                "and per channel, clipped to 1), each above a zoomed window",
                views.blur_and_edges,
            ),
            Picture(
                "07_repeated_blur_8",
                "eight blurs under each border rule: zero padding darkens the frame, the "
                "other rules keep the edge's brightness (top-right corner zoomed)",
                lambda: app_picture(views.repeated_blur_app()),
            ),
        ),
        sliders=(
            SliderMove(
                build=views.repeated_blur_app,
                control="repeats",
                moves=(("ArrowRight", "ArrowRight"), ("Home",), ("End",)),
                landmarks=views.repeated_blur_landmarks,
            ),
        ),
    ),
    "08": Lesson(
        "08",
        handout="Lab 1 report (seed 001), Task 3: Poisson image editing, the plane pasted "
        "into the lake with the lab's 8000 'Jacobi' sweeps",
        teaches="seamless cloning and inpainting as a Poisson equation, solved exactly "
        "(DST, sparse) and by Jacobi, Gauss-Seidel and SOR; why 8000 sweeps are not enough",
        pictures=(
            Picture(
                "08_naive_paste_and_seamless_clone",
                "the plane pasted into the lake: copied pixels leave a frame, the seamless "
                "clone has none",
                views.clone_comparison,
            ),
            Picture(
                "08_jacobi_1000_sweeps",
                "1000 Jacobi sweeps: the result and its error against the exact solution, "
                "still large in the middle of the region",
                lambda: app_picture(views.poisson_app()),
            ),
            Picture(
                "08_inpainting",
                "seven scratches across the photograph, filled by solving Laplace's "
                "equation, beside the original",
                views.inpainting,
            ),
        ),
        sliders=(
            SliderMove(
                build=views.poisson_app,
                control="sweeps",
                moves=(("ArrowRight",), ("ArrowLeft", "ArrowLeft"), ("End",)),
                landmarks=views.poisson_landmarks,
            ),
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
