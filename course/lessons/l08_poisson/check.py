"""Lesson 08's exercises: the lab's boundary ring for the correction ``g``, and its sweep.

The lab's skeleton solves for ``g = result - foreground``, starting from an
array of zeros whose outer ring the student fills with ``background -
foreground`` (:func:`boundary_ring`); Jacobi sweeps then make ``g``
harmonic inside, each pixel the mean of its four neighbours, until the
residual is small (:func:`jacobi_solve`; an RGB ``g``'s channels are swept
together, and its residual is the largest over every channel). Failures draw
the difference (a wrong sweep: both loops' stops on Jacobi's residual, and
the difference, :mod:`.sweep_picture`) and recognise the sign flipped, x and
y swapped, the offset ignored, the ring read one pixel out or filled one pixel
in, the sweep done in place (the lab's loop: Gauss-Seidel), a stop one
sweep late, the lab's fixed count of sweeps, a stop on the change between
sweeps, on a quarter of the residual, on its mean or on its first channel
alone, each channel stopped on its own, the count returned before ``g``, and a
sweep that moves the ring (:mod:`.mistakes` reproduces each). A
function that writes into its inputs (``g = background[...]; g -= foreground``
changes the background) fails, however right its values. A pass shows the
student's ``g`` beside the expected one.

Each exercise has one name, that of what the student's function does: ``boundary_ring`` fills
the ring, ``jacobi_solve`` sweeps until the residual is small (not ``jacobi_sweeps``, the
library's generator of single sweeps).

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("jacobi_solve")`` says more at once and
``check.hint("jacobi_solve", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import poisson
from course.check.base import CheckResult, close, hint, run_cases
from course.check.exercises import exercise
from course.check.hints import Hints
from course.check.pictures import image_picture, side_by_side
from course.check.shown import show_value
from course.i18n import N_, _
from course.lessons.graded_cases import drawn_in_order
from course.lessons.l08_poisson.mistakes import (
    boundary_mistakes,
    count_of,
    jacobi_until,
    same_sweeps,
    sweep_mistakes,
)
from course.lessons.l08_poisson.sweep_picture import sweep_picture
from course.poisson import solvers as poisson_solvers

__all__ = ["boundary_ring", "hint", "jacobi_solve"]

_LIBRARY_FUNCTIONS = (
    poisson.correction_boundary,
    poisson.seamless_clone,
    poisson.solve,
    poisson_solvers.jacobi_sweeps,
    poisson_solvers.iterate,
)


def _shown(g: Any) -> np.ndarray:
    """A correction g in [-1, 1] as a picture: (g + 1) / 2, so 0 is mid-gray."""
    return (np.asarray(g, dtype=float) + 1) / 2


def _cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(8)

    def image(*shape: int) -> np.ndarray:
        # Multiples of 1/16: every difference is exact, so equality is too.
        return rng.integers(0, 17, shape) / 16

    return [
        # Gray, square, one pixel in: the smallest case.
        {"background": image(5, 5), "foreground": image(3, 3), "offset": (1, 1)},
        # x and y differ, and so do width and height: swapping them shows.
        {"background": image(6, 9), "foreground": image(3, 5), "offset": (3, 1)},
        # RGB, in the background's bottom-right corner: the far edges count.
        {"background": image(7, 8, 3), "foreground": image(4, 6, 3), "offset": (2, 3)},
        # At the origin.
        {"background": image(6, 6, 3), "foreground": image(5, 4, 3), "offset": (0, 0)},
    ]


def _drawn_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``boundary_ring``, in the fixed cases' order and sizes, drawn from
    ``rng``: images of multiples of 1/16 (every difference exact).

    Gray 3 x 3 in 5 x 5, one pixel in; gray 3 x 5 in 6 x 9 at an offset (x, y) with x != y
    that stays inside when swapped; RGB 4 x 6 in 7 x 8 in its bottom-right corner; RGB 5 x 4
    in 6 x 6 at the origin. Each named mistake is caught, and named, at the case where the
    fixed cases catch it (:func:`~course.lessons.graded_cases.drawn_in_order`).
    """

    def image(*shape: int) -> np.ndarray:
        return rng.integers(0, 17, shape) / 16

    def pair(background: tuple, foreground: tuple, offset: Callable[[], tuple]) -> Callable:
        return lambda: [
            {"background": image(*background), "foreground": image(*foreground), "offset": offset()}
        ]

    def apart() -> tuple[int, int]:
        x, y = (int(v) for v in rng.choice(4, size=2, replace=False))
        return x, y

    families = [
        pair((5, 5), (3, 3), lambda: (1, 1)),
        pair((6, 9), (3, 5), apart),
        pair((7, 8, 3), (4, 6, 3), lambda: (2, 3)),
        pair((6, 6, 3), (5, 4, 3), lambda: (0, 0)),
    ]
    return drawn_in_order(
        _cases(),
        families,
        poisson.correction_boundary,
        close(atol=1e-12, rtol=0),
        boundary_mistakes(),
        lambda g: np.asarray(g, dtype=float),
    )


BOUNDARY_HINTS = Hints(
    where=N_(
        "look at the pixels of the foreground's outer ring, at where they sit in the "
        "background, and at the inside."
    ),
    more=N_(
        "offset = (x, y) puts the foreground's top-left pixel at background[y, x]; on "
        "the ring, g is what the background has there minus the foreground; inside, 0. The "
        "background and the foreground stay as they were."
    ),
    recipe=N_(
        "window = background[y : y + height, x : x + width]; g = window - foreground "
        "(a new array); g[1:-1, 1:-1] = 0."
    ),
)


@exercise(
    hints=BOUNDARY_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    draw=_drawn_cases,
)
def boundary_ring(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(background, foreground, offset)`` against the lab's boundary setup.

    It must return ``g``, of the foreground's shape: ``background - foreground``
    on the foreground's outer ring (``offset = (x, y)`` places the
    foreground's top-left pixel at ``background[y, x]``), and 0 inside.

    Examples
    --------
    >>> zeros = lambda background, foreground, offset: foreground * 0
    >>> print(boundary_ring(zeros))  # doctest: +ELLIPSIS
    FAIL boundary_ring: case 1 is wrong
    ...
    """
    return run_cases(
        "boundary_ring",
        student,
        _cases(),
        poisson.correction_boundary,
        close(atol=1e-12, rtol=0),
        convert=lambda g: np.asarray(g, dtype=float),
        mistakes=boundary_mistakes(),
        picture=_boundary_picture,
        pass_picture=lambda results: side_by_side(
            _shown(results[2][1]), _shown(results[2][2]), (_("expected g"), _("your g"))
        ),
    )


def _boundary_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    # g lies in [-1, 1]: shown as (g + 1) / 2, so 0 is mid-gray.
    return image_picture(
        (np.asarray(expected, dtype=float) + 1) / 2,
        (np.asarray(given, dtype=float) + 1) / 2,
        title=_("g, shown as (g + 1) / 2: 0 is mid-gray"),
    )


def _sweep_cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(18)

    def ring(*shape: int) -> np.ndarray:
        g = np.zeros(shape)
        edge = rng.integers(-16, 17, shape) / 16  # multiples of 1/16, as the ring's differences
        g[0], g[-1], g[:, 0], g[:, -1] = edge[0], edge[-1], edge[:, 0], edge[:, -1]
        return g

    first = ring(4, 5)
    cases = [
        # 1e-4, where the residual's max (16 sweeps), its mean (15), a stop on the change (14)
        # and a quarter of the residual (13) all stop at different sweeps: each is named.
        {"g": first, "tolerance": 1e-4},
        {"g": ring(7, 12), "tolerance": 1e-6},
        {"g": ring(6, 9, 3), "tolerance": 1e-4},
        {"g": np.zeros((5, 5)), "tolerance": 1e-6},  # already harmonic: no sweep at all
        # The residual is exactly the tolerance, 4: not below it, so one sweep (to zeros).
        {"g": np.array([[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]]), "tolerance": 4.0},
    ]
    # RGB whose red ring is 16 times fainter: red converges first, so a residual of channel 0
    # alone stops early (multiples of 1/256, still exact).
    rgb = ring(5, 6, 3)
    rgb[..., 0] /= 16
    cases.append({"g": rgb, "tolerance": 1e-4})
    return cases


def _drawn_sweep_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``jacobi_solve``, in the fixed cases' order and sizes, drawn from
    ``rng``: rings of multiples of 1/16 around zeros (every sum exact).

    A 4 x 5 ring at tolerance 1e-4, on which the residual's max, its mean, the change between
    sweeps and a quarter of the residual stop at sweeps of their own; 7 x 12 at 1e-6; RGB
    6 x 9 at 1e-4; a 5 x 5 plane, already harmonic (no sweep at all); a 3 x 3 whose residual
    is exactly the tolerance (one sweep); RGB 5 x 6 whose red ring is 16 times fainter, at
    1e-4 (red converges first). Each named mistake is caught, and named, at the case where
    the fixed cases catch it (:func:`~course.lessons.graded_cases.drawn_in_order`).
    """

    def ring(*shape: int) -> np.ndarray:
        g = np.zeros(shape)
        edge = rng.integers(-16, 17, shape) / 16
        g[0], g[-1], g[:, 0], g[:, -1] = edge[0], edge[-1], edge[:, 0], edge[:, -1]
        return g

    def plane() -> np.ndarray:
        rows, columns = np.mgrid[0:5, 0:5]
        a, b, c = rng.integers(-4, 5, size=3) / 16
        return a + b * rows + c * columns

    def exactly_at_tolerance() -> dict[str, Any]:
        while True:
            g = rng.integers(-16, 17, (3, 3)) / 16
            residual = abs(g[0, 1] + g[2, 1] + g[1, 0] + g[1, 2] - 4 * g[1, 1])
            if residual > 0:
                return {"g": g, "tolerance": float(residual)}

    def faint_red() -> np.ndarray:
        g = ring(5, 6, 3)
        g[..., 0] /= 16
        return g

    families = [
        lambda: [{"g": ring(4, 5), "tolerance": 1e-4}],
        lambda: [{"g": ring(7, 12), "tolerance": 1e-6}],
        lambda: [{"g": ring(6, 9, 3), "tolerance": 1e-4}],
        lambda: [{"g": plane(), "tolerance": 1e-6}],
        lambda: [exactly_at_tolerance()],
        lambda: [{"g": faint_red(), "tolerance": 1e-4}],
    ]
    return drawn_in_order(_sweep_cases(), families, jacobi_until, same_sweeps, sweep_mistakes())


def _what(value: Any) -> str:
    """One thing a student returned, in a few words: an array by its shape."""
    try:
        shape = np.shape(value)
    except (TypeError, ValueError):
        return type(value).__name__
    if shape:
        return _("an array of shape {shape}").format(shape=shape)
    return show_value(value)


def _sweep_difference(expected: Any, given: Any) -> str:
    want_g, want_sweeps = expected
    try:
        g, sweeps = given
        g = np.asarray(g, dtype=float)
    except (TypeError, ValueError):
        return _("return two things: the array g and the number of sweeps")
    count = count_of(sweeps)
    if count is None:
        if g.ndim == 0 and np.ndim(sweeps) > 0:
            return _("you returned the number of sweeps first: return g, sweeps")
        return _("the second thing returned must be the number of sweeps, a whole number")
    if g.shape == want_g.shape and np.allclose(g, want_g, atol=1e-12, rtol=0.0):
        return _(
            "g is right; only the number of sweeps differs (expected {expected}, given {given})"
        ).format(expected=want_sweeps, given=count)
    if count == want_sweeps:
        parts = [_("the number of sweeps is right ({count}); g is not").format(count=count)]
    else:
        parts = [
            _("sweeps: expected {expected}, given {given}").format(
                expected=want_sweeps, given=count
            )
        ]
    if g.shape != want_g.shape:
        parts.append(
            _("g: expected shape {expected}, given {given}").format(
                expected=want_g.shape, given=g.shape
            )
        )
    else:
        worst = np.unravel_index(np.abs(g - want_g).argmax(), g.shape)
        place = (
            _(
                "largest difference in g at [row, column] {where}: expected {expected}, "
                "given {given}"
            )
            if g.ndim == 2
            else _(
                "largest difference in g at [row, column, channel] {where}: expected "
                "{expected}, given {given}"
            )
        )
        # "[2, 4]" in English; the catalog may spell the place out ("第 2 行第 4 列").
        where = (
            _("[{row}, {column}]").format(row=int(worst[0]), column=int(worst[1]))
            if g.ndim == 2
            else _("[{row}, {column}, {channel}]").format(
                row=int(worst[0]), column=int(worst[1]), channel=int(worst[2])
            )
        )
        parts.append(
            place.format(
                where=where,
                expected=f"{want_g[worst]:.6g}",
                given=f"{g[worst]:.6g}",
            )
        )
    return _("; ").join(parts)


def _show_sweeps(answer: Any) -> str:
    try:
        g, sweeps = answer
    except (TypeError, ValueError):
        return _("{kind} (expected a pair: g and the number of sweeps)").format(
            kind=type(answer).__name__
        )
    count = count_of(sweeps)
    if count is None:
        return _("({first}, {second}): expected g, then the number of sweeps").format(
            first=_what(g), second=_what(sweeps)
        )
    return _("g of shape {shape} after {sweeps} sweeps").format(shape=np.shape(g), sweeps=count)


SWEEP_HINTS = Hints(
    where=N_(
        "look at when your loop tests the residual (before or after a sweep), at what "
        "each sweep reads, and at what you count."
    ),
    more=N_(
        "before each sweep, the residual max |up + down + left + right - 4 g| over the "
        "inside and every channel is compared with the tolerance; a sweep computes every new "
        "inside value, all channels together, from the previous array only, and the ring "
        "never changes. Work on a copy of g."
    ),
    recipe=N_(
        "g = np.array(g, dtype=float); for sweeps in itertools.count(): n = the sum of "
        "the four shifted slices; if max |n - 4 g[1:-1, 1:-1]| < tolerance: return g, sweeps; "
        "g[1:-1, 1:-1] = n / 4."
    ),
)


@exercise(
    hints=SWEEP_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    draw=_drawn_sweep_cases,
)
def jacobi_solve(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(g, tolerance) -> (g, sweeps)``: Jacobi sweeps until the residual is small.

    The outer ring of ``g`` (gray ``(H, W)`` or RGB ``(H, W, 3)``) is fixed;
    each sweep replaces every inside pixel by the mean of its four
    neighbours in the previous array, every channel at once. Before each
    sweep, the residual ``max |g_up + g_down + g_left + g_right - 4 g|`` over
    the inside and every channel is compared with ``tolerance``: below it,
    stop and return the array and the number of sweeps done. The input is
    not changed.

    Examples
    --------
    >>> from course.lessons.l08_poisson.mistakes import gauss_seidel_until
    >>> jacobi_solve(gauss_seidel_until).mistake
    'in place: Gauss-Seidel'
    """
    return run_cases(
        "jacobi_solve",
        student,
        _sweep_cases(),
        jacobi_until,
        same_sweeps,
        mistakes=sweep_mistakes(),
        difference=_sweep_difference,
        picture=sweep_picture,
        show=_show_sweeps,
        pass_picture=lambda results: side_by_side(
            _shown(results[1][1][0]), _shown(results[1][2][0]), (_("expected g"), _("your g"))
        ),
    )
