"""Lesson 01, de Casteljau's algorithm: its registry entry, pictures, landmarks and printed lines.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

import re

from course.classroom.pictures import CRIMSON, app_picture, landmark_at, still_picture
from course.classroom.registry import DragMove, Landmark, Lesson, Picture, SliderMove
from course.curves.bezier import de_casteljau
from course.curves.handout_loops import HandoutLoop
from course.i18n import N_, _, yes_no
from course.images import EXAMPLE_POINTS, SEED_000_CUBIC
from course.lessons.l01_de_casteljau import figures
from course.lessons.l01_de_casteljau.apps import DeCasteljauApp
from course.lessons.printed import degree_numeral, padded
from course.widgets.base import SliderApp, parse_points
from course.widgets.picture import Still

UNCHECKED = True  # see the module docstring

#: The caption of the lesson's opening picture.
OPENING_CAPTION = N_("a cubic's construction at t = 0.5")
#: The loops the yellow check runs, as ``HandoutLoop.name`` names them.
LOOP_NAMES = (
    N_("the GAMES101 report"),
    N_("the any-degree report"),
    N_("the VS2022 report"),
    N_("the lab 6 report"),
    N_("textbook step, float t"),
)
#: The textbook step, (1 - t) P[i] + t P[i+1], in the reports' ``float t`` loop, each point
#: truncated to its pixel: the yellow check's yardstick for the handouts' own loops.
TEXTBOOK_FLOAT_LOOP = HandoutLoop(
    LOOP_NAMES[4],
    "for (float t = 0; t <= 1; t += 0.001f) window.at<cv::Vec3b>(point.y, point.x)",
    accumulate="float32",
    rounding="trunc",
)
#: What the pixel holding B(1) shows, indexed by ``red + 2 * green``.
END_PIXEL_STATES = (N_("dark"), N_("red only"), N_("green only"), N_("yellow"))


def opening_still() -> Still:
    """The lesson's opening picture: :class:`DeCasteljauApp` at t = 0.5, captioned."""
    return DeCasteljauApp(t=0.5).still(_(OPENING_CAPTION))


def print_yellow_check(name: str, fraction: float, state: str) -> None:
    """Print one loop's yellow check: the share of yellow pixels and what B(1)'s pixel shows.

    ``name`` is one of :data:`LOOP_NAMES` and ``state`` one of :data:`END_PIXEL_STATES`,
    both shown in the current language.

    Examples
    --------
    >>> print_yellow_check("the VS2022 report", 1.0, "dark")
          the VS2022 report: 100.0% yellow, B(1)'s pixel dark
    """
    print(
        _("{name}: {fraction:.1%} yellow, B(1)'s pixel {state}").format(
            name=padded(_(name), 23, ">"), fraction=fraction, state=_(state)
        )
    )


def print_iterative_against(recursive: bool, last_level: bool) -> None:
    """Print whether ``de_casteljau`` equals the recursive form and the levels' last point.

    Examples
    --------
    >>> print_iterative_against(True, False)
    iterative == recursive: yes
    iterative == last level: no
    """
    print(_("iterative == recursive: {equal}").format(equal=yes_no(recursive)))
    print(_("iterative == last level: {equal}").format(equal=yes_no(last_level)))


def print_recursion_error(error: RecursionError) -> None:
    """Print what ``de_casteljau_recursive``'s ``RecursionError`` says: degree, calls, limit.

    The message also names the stack's depth, which varies with how the code is run,
    so that part is not printed. A message of another form is printed whole.

    Examples
    --------
    >>> print_recursion_error(RecursionError(
    ...     "de_casteljau_recursive: a degree-1999 curve needs 2000 nested calls, and the "
    ...     "stack is already 40 deep; Python's recursion limit is 1000. Use de_casteljau "
    ...     "(iterative), or raise the limit with sys.setrecursionlimit(2140)."))
    de_casteljau_recursive: a degree-1999 curve needs 2000 nested calls.
    Python's recursion limit is 1000. Use de_casteljau (iterative).
    """
    message = str(error)
    found = re.search(
        r"degree-(\d+) curve needs (\d+) nested calls.*recursion limit is (\d+)", message
    )
    if found is None:
        print(message)
        return
    degree, calls, limit = (int(number) for number in found.groups())
    print(
        _("de_casteljau_recursive: a degree-{degree} curve needs {calls} nested calls.").format(
            degree=degree_numeral(degree), calls=calls
        )
    )
    print(
        _("Python's recursion limit is {limit}. Use de_casteljau (iterative).").format(limit=limit)
    )


def print_step_table(rows: list[tuple[float, int, int, int, float]]) -> None:
    """Print the step table: per t step, the points, pixels, gaps and overdraw of the loop.

    Each row is ``(step, points, pixels, gaps, overdraw)``, as
    :func:`course.curves.bezier_handouts.step_report` counts them.

    Examples
    --------
    >>> print_step_table([(0.01, 101, 101, 100, 1.0)])
        step  points  pixels  gaps  overdraw
        0.01     101     101   100      1.00
    """
    # One message for the whole heading: "points" here are samples, not control points,
    # and a translation lines its words up with the columns itself.
    print(padded(_("step  points  pixels  gaps  overdraw"), 40, ">"))
    for step, points, pixels, gaps, overdraw in rows:
        print(f"{step:>8} {points:>7} {pixels:>7} {gaps:>5} {overdraw:>9.2f}")


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
        lambda: app_picture(DeCasteljauApp(points=EXAMPLE_POINTS[:count], t=t)),
    )


#: The lesson's tiny example: three points with exact binary-fraction levels at t = 1/4.
THREE_POINTS = ((0.0, 0.0), (2.0, 4.0), (8.0, 0.0))


def preview() -> bytes:
    """The course map's preview: the construction at t = 0.5."""
    return app_picture(DeCasteljauApp())


LESSON = Lesson(
    outcomes=(
        N_("find a point of a Bézier curve by hand, by repeated linear interpolation"),
        N_("write the GAMES101 handout's recursive_bezier and the loop that draws the curve"),
        N_("measure the handouts' pitfalls: a curve run backwards, a loop short of t = 1, gaps"),
    ),
    minutes=60,
    preview=Picture("01_preview", "de Casteljau's construction of a cubic at t = 0.5", preview),
    handout=N_(
        "the GAMES101 handout's basic part (基础部分): recursive_bezier and the bezier "
        "loop; the reversed step and float loops of the any-degree, VS2022 and lab 6 reports"
    ),
    teaches=N_(
        "a Bézier curve by repeated linear interpolation: by hand on three points, "
        "recursive_bezier and the drawing loop written and checked, every level under a t slider "
        "and draggable points; the handouts' pitfalls as pictures and numbers"
    ),
    pictures=(
        de_casteljau_picture(0.5),
        de_casteljau_picture(0.25),
        de_casteljau_picture(0.3, count=10),
        still_picture(
            "01_three_points",
            "de Casteljau by hand on three points at t = 1/4",
            figures.three_points_figure,
            THREE_POINTS,
            0.25,
        ),
        still_picture(
            "01_end_of_curve",
            "the last pixels two handout loops paint, beside B(1)",
            figures.end_of_curve_figure,
            SEED_000_CUBIC,
        ),
        still_picture(
            "01_yellow_check_games101",
            "the GAMES101 report's yellow check: rounding against truncation",
            figures.yellow_check_figure,
            SEED_000_CUBIC,
            "000",
        ),
    ),
    sliders=(
        SliderMove(
            build=DeCasteljauApp,
            control="t",
            moves=(("ArrowRight", "ArrowRight", "ArrowRight"), ("ArrowLeft",), ("End",)),
            landmarks=de_casteljau_landmarks,
        ),
    ),
    drags=(
        DragMove(
            build=DeCasteljauApp,
            handle="P1",
            path=((15, 20), (40, 55), (70, 90)),
            landmarks=de_casteljau_landmarks,
        ),
    ),
)
