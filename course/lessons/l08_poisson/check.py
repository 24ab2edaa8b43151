"""Lesson 08's exercises: the lab's boundary ring for the correction ``g``, and its sweep.

The lab's skeleton solves for ``g = result - foreground``, starting from an
array of zeros whose outer ring the student fills with ``background -
foreground`` (:func:`poisson_boundary`); Jacobi sweeps then make ``g``
harmonic inside, each pixel the mean of its four neighbours, until the
residual is small (:func:`jacobi_sweep`). Failures draw the difference and
recognise the sign flipped, x and y swapped, the sweep done in place (the
lab's loop: Gauss-Seidel), a stop one sweep late, the lab's fixed count of
sweeps, a stop on the change between sweeps, on a quarter of the residual, on
its mean or on its first channel alone. A function that writes into
its inputs (``g = background[...]; g -= foreground`` changes the background)
fails, however right its values. A pass shows the student's ``g`` beside the
expected one.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("jacobi_exercise")`` says more at once and
``check.hint("jacobi_exercise", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import poisson
from course.check.base import CheckResult, Mistake, close, hint, register_hints, run_cases
from course.check.hints import Hints
from course.check.pictures import image_picture, side_by_side
from course.check.references import public_name
from course.i18n import N_, _
from course.poisson import solvers as poisson_solvers
from course.poisson.problem import image_of, planes_of
from course.poisson.solvers import jacobi_sweeps, residual

__all__ = ["hint", "jacobi_sweep", "poisson_boundary"]

_LIBRARY_FUNCTIONS = (
    poisson.correction_boundary,
    poisson.seamless_clone,
    poisson.solve,
    poisson_solvers.jacobi_sweeps,
    poisson_solvers.iterate,
)


def _library() -> dict[Any, str]:
    """The library's own answers, each with what a student who calls it is told."""
    return {
        function: _(
            "your function calls {function}, the library's own answer: this exercise writes it"
        ).format(function=public_name(function))
        for function in _LIBRARY_FUNCTIONS
    }


_LIBRARY = _library()


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


def poisson_boundary(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(background, foreground, offset)`` against the lab's boundary setup.

    It must return ``g``, of the foreground's shape: ``background - foreground``
    on the foreground's outer ring (``offset = (x, y)`` places the
    foreground's top-left pixel at ``background[y, x]``), and 0 inside.

    Examples
    --------
    >>> zeros = lambda background, foreground, offset: foreground * 0
    >>> print(poisson_boundary(zeros))  # doctest: +ELLIPSIS
    FAIL boundary_exercise: case 1 is wrong
    ...
    """
    return run_cases(
        "boundary_exercise",
        student,
        _cases(),
        poisson.correction_boundary,
        close(atol=1e-12, rtol=0),
        convert=lambda g: np.asarray(g, dtype=float),
        hint=BOUNDARY_HINTS,
        mistakes=_boundary_mistakes(),
        picture=_boundary_picture,
        forbidden=_library(),
        pass_picture=lambda results: side_by_side(
            _shown(results[2][1]), _shown(results[2][2]), (_("expected g"), _("your g"))
        ),
    )


BOUNDARY_HINTS = register_hints(
    "boundary_exercise",
    Hints(
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
    ),
    "boundary_exercise",
    "poisson_boundary",
)


def _boundary_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    # g lies in [-1, 1]: shown as (g + 1) / 2, so 0 is mid-gray.
    return image_picture(
        (np.asarray(expected, dtype=float) + 1) / 2,
        (np.asarray(given, dtype=float) + 1) / 2,
        title=_("g, shown as (g + 1) / 2: 0 is mid-gray"),
    )


def _swapped_offset(background: Any, foreground: Any, offset: Any) -> np.ndarray:
    return poisson.correction_boundary(background, foreground, (offset[1], offset[0]))


def _boundary_mistakes() -> tuple[Mistake, ...]:
    """The known mistakes, in the current language."""
    return (
        Mistake(
            _("the sign flipped"),
            _(
                "your ring holds foreground - background. The report's formula is right: "
                "g = background - foreground, so that foreground + g is the background on the ring."
            ),
            lambda background, foreground, offset: (
                -poisson.correction_boundary(background, foreground, offset)
            ),
        ),
        Mistake(
            _("the background alone"),
            _(
                "your ring holds the background, without subtracting the foreground: the result "
                "foreground + g is then the background plus the foreground on the ring."
            ),
            lambda background, foreground, offset: poisson.correction_boundary(
                background, np.zeros_like(foreground), offset
            ),
        ),
        Mistake(
            _("x and y swapped"),
            _(
                "you read the background at (offset[1], offset[0]): offset is (x, y), the column "
                "first, and background[y, x] is row y."
            ),
            _swapped_offset,
        ),
    )


BOUNDARY_MISTAKES = _boundary_mistakes()


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


def _jacobi_until(g: Any, tolerance: float, late: int = 0) -> tuple[np.ndarray, int]:
    """Jacobi sweeps on ``g``'s inside until the residual is below ``tolerance``, then
    ``late`` more (a loop that tests after it sweeps)."""
    image = np.asarray(g, dtype=float)
    planes = planes_of(image)
    region = np.zeros(planes.shape[1:], dtype=bool)
    region[1:-1, 1:-1] = True
    source = np.zeros_like(planes)
    count, u = 0, planes
    sweeps = jacobi_sweeps(planes, region, source)
    while residual(u, region, source) >= tolerance:
        u, count = next(sweeps), count + 1
    for _late in range(late):
        u, count = next(sweeps), count + 1
    return image_of(u, image), count


def _gauss_seidel_until(g: Any, tolerance: float) -> tuple[np.ndarray, int]:
    """The lab's loop, which writes g in place: Gauss-Seidel."""
    u = np.array(g, dtype=float)
    height, width = u.shape[:2]
    count = 0
    while True:
        inner = u[:-2, 1:-1] + u[2:, 1:-1] + u[1:-1, :-2] + u[1:-1, 2:] - 4 * u[1:-1, 1:-1]
        if np.abs(inner).max() < tolerance:
            return u, count
        for y in range(1, height - 1):
            for x in range(1, width - 1):
                u[y, x] = (u[y - 1, x] + u[y + 1, x] + u[y, x - 1] + u[y, x + 1]) * 0.25
        count += 1


def _same_sweeps(expected: Any, given: Any) -> bool:
    try:
        g, sweeps = given
    except (TypeError, ValueError):
        return False
    want_g, want_sweeps = expected
    g = np.asarray(g, dtype=float)
    return (
        int(sweeps) == want_sweeps
        and g.shape == want_g.shape
        and bool(np.allclose(g, want_g, atol=1e-12, rtol=0.0))
    )


def _sweep_difference(expected: Any, given: Any) -> str:
    want_g, want_sweeps = expected
    try:
        g, sweeps = given
        g = np.asarray(g, dtype=float)
    except (TypeError, ValueError):
        return _("return two things: the array g and the number of sweeps")
    parts = [
        _("sweeps: expected {expected}, given {given}").format(expected=want_sweeps, given=sweeps)
    ]
    if g.shape == want_g.shape and np.allclose(g, want_g, atol=1e-12, rtol=0.0):
        return _(
            "g is right; only the number of sweeps differs (expected {expected}, given {given})"
        ).format(expected=want_sweeps, given=sweeps)
    if g.shape != want_g.shape:
        parts.append(
            _("g: expected shape {expected}, given {given}").format(
                expected=want_g.shape, given=g.shape
            )
        )
    else:
        worst = np.unravel_index(np.abs(g - want_g).argmax(), g.shape)
        parts.append(
            _(
                "largest difference in g at [row, column] {where}: expected {expected}, "
                "given {given}"
            ).format(
                where=list(map(int, worst[:2])),
                expected=f"{want_g[worst]:.6g}",
                given=f"{g[worst]:.6g}",
            )
        )
    return "; ".join(parts)


def _sweep_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes | None:
    try:
        g = np.asarray(given[0], dtype=float)
    except (TypeError, ValueError, IndexError):
        return None
    return image_picture(
        (expected[0] + 1) / 2, (g + 1) / 2, title=_("g after the sweeps, shown as (g + 1) / 2")
    )


def _show_sweeps(answer: Any) -> str:
    try:
        g, sweeps = answer
        return _("g of shape {shape} after {sweeps} sweeps").format(
            shape=np.shape(g), sweeps=sweeps
        )
    except (TypeError, ValueError):
        return _("{kind} (expected a pair: g and the number of sweeps)").format(
            kind=type(answer).__name__
        )


def _until_change(g: Any, tolerance: float) -> tuple[np.ndarray, int]:
    """Jacobi sweeps until the largest change of one sweep is below ``tolerance``."""
    u = np.array(g, dtype=float)
    count = 0
    while True:
        new = u.copy()
        new[1:-1, 1:-1] = (u[:-2, 1:-1] + u[2:, 1:-1] + u[1:-1, :-2] + u[1:-1, 2:]) / 4
        count += 1
        if u.size == 0 or np.abs(new - u).max() < tolerance:
            return new, count
        u = new


def _until_residual_measure(
    g: Any, tolerance: float, measure: Callable[[np.ndarray], float]
) -> tuple[np.ndarray, int]:
    """Jacobi sweeps until ``measure(|residual|)`` (over the inside, every channel) is below
    ``tolerance``: the residual's mean, a quarter of its max, or its first channel's."""
    u = np.array(g, dtype=float)
    count = 0
    while True:
        neighbours = u[:-2, 1:-1] + u[2:, 1:-1] + u[1:-1, :-2] + u[1:-1, 2:]
        if neighbours.size == 0 or measure(np.abs(neighbours - 4 * u[1:-1, 1:-1])) < tolerance:
            return u, count
        u = u.copy()
        u[1:-1, 1:-1] = neighbours / 4
        count += 1


def _first_channel(size: np.ndarray) -> float:
    return float((size[..., 0] if size.ndim == 3 else size).max())


def _fixed_count(expected: Any, given: Any) -> bool:
    """A sweep count far past what the tolerance needs: the lab's fixed loop of 8000."""
    try:
        _, sweeps = given
        return int(sweeps) >= 1000 and int(sweeps) != int(expected[1])
    except (TypeError, ValueError):
        return False


def _sweep_mistakes() -> tuple[Mistake, ...]:
    """The known mistakes, in the current language."""
    return (
        Mistake(
            _("in place: Gauss-Seidel"),
            _(
                "your sweep writes g as it goes, so each pixel already sees its new upper and left "
                "neighbours: that is Gauss-Seidel, and so is the lab's loop, whatever its comment "
                "says. Jacobi computes every new value from the old array (a copy, or all four "
                "shifted slices at once)."
            ),
            _gauss_seidel_until,
        ),
        Mistake(
            _("a fixed number of sweeps"),
            _(
                "you ran a fixed count of sweeps, as the lab's loop runs 8000: the exercise "
                "stops as soon as the residual is below the tolerance, and returns how many "
                "sweeps that took."
            ),
            lambda g, tolerance: (np.asarray(g, dtype=float), 0),
            matches=_fixed_count,
        ),
        # Before the stop on the change: on an array already harmonic both give one sweep, and
        # only a loop that sweeps before it tests fails nothing else.
        Mistake(
            _("one sweep late"),
            _(
                "you sweep before you test: the loop must stop as soon as the residual is below "
                "the tolerance, so an array already within it gets no sweep at all."
            ),
            lambda g, tolerance: _jacobi_until(g, tolerance, late=1),
        ),
        Mistake(
            _("a stop on the change between sweeps"),
            _(
                "you stopped when one sweep changed g by less than the tolerance: that change is "
                "a quarter of the residual, so your loop stops while the residual is still up to "
                "four times the tolerance. Test the residual, max |up + down + left + right - 4 "
                "g| over the inside, before each sweep."
            ),
            _until_change,
        ),
        Mistake(
            _("the mean of the residual instead of its largest value"),
            _(
                "you compared the mean of |up + down + left + right - 4 g| over the inside with "
                "the tolerance: the exercise compares its largest value, so the loop goes on "
                "while any one pixel is still far from the mean of its neighbours."
            ),
            lambda g, tolerance: _until_residual_measure(g, tolerance, np.mean),
        ),
        # Before the quarter: on the residual equal to the tolerance (case 5) both stop at once.
        Mistake(
            _("a stop at a residual equal to the tolerance"),
            _(
                "your loop stops when the residual is at or below the tolerance (<=): it stops "
                "only below it (<), so a residual equal to the tolerance still gets a sweep."
            ),
            lambda g, tolerance: _until_residual_measure(
                g, tolerance, lambda size: float(np.nextafter(size.max(), -np.inf))
            ),
        ),
        Mistake(
            _("a quarter of the residual"),
            _(
                "you compared the residual divided by 4 (the mean of the four neighbours minus "
                "g, which is the change the next sweep makes) with the tolerance: your loop "
                "stops while the residual is still up to four times the tolerance. Compare the "
                "residual itself, max |up + down + left + right - 4 g|."
            ),
            lambda g, tolerance: _until_residual_measure(
                g, tolerance, lambda size: float(size.max()) / 4
            ),
        ),
        Mistake(
            _("the residual of the first channel only"),
            _(
                "your residual looks at channel 0 only: on an RGB g the loop goes on until the "
                "residual of every channel is below the tolerance, the largest value over the "
                "inside and all three channels."
            ),
            lambda g, tolerance: _until_residual_measure(g, tolerance, _first_channel),
        ),
    )


SWEEP_MISTAKES = _sweep_mistakes()


def jacobi_sweep(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(g, tolerance) -> (g, sweeps)``: Jacobi sweeps until the residual is small.

    The outer ring of ``g`` (gray ``(H, W)`` or RGB ``(H, W, 3)``) is fixed;
    each sweep replaces every inside pixel by the mean of its four
    neighbours in the previous array. Before each sweep, the residual
    ``max |g_up + g_down + g_left + g_right - 4 g|`` over the inside is
    compared with ``tolerance``: below it, stop and return the array and the
    number of sweeps done. The input is not changed.

    Examples
    --------
    >>> jacobi_sweep(_gauss_seidel_until).mistake
    'in place: Gauss-Seidel'
    """
    return run_cases(
        "jacobi_exercise",
        student,
        _sweep_cases(),
        _jacobi_until,
        _same_sweeps,
        hint=SWEEP_HINTS,
        mistakes=_sweep_mistakes(),
        difference=_sweep_difference,
        picture=_sweep_picture,
        show=_show_sweeps,
        forbidden=_library(),
        pass_picture=lambda results: side_by_side(
            _shown(results[1][1][0]), _shown(results[1][2][0]), (_("expected g"), _("your g"))
        ),
    )


SWEEP_HINTS = register_hints(
    "jacobi_exercise",
    Hints(
        where=N_(
            "look at when your loop tests the residual (before or after a sweep), at what "
            "each sweep reads, and at what you count."
        ),
        more=N_(
            "before each sweep, the residual max |up + down + left + right - 4 g| over the "
            "inside is compared with the tolerance; a sweep computes every new inside value "
            "from the previous array only, and the ring never changes. Work on a copy of g."
        ),
        recipe=N_(
            "g = np.array(g, dtype=float); for sweeps in itertools.count(): n = the sum of "
            "the four shifted slices; if max |n - 4 g[1:-1, 1:-1]| < tolerance: return g, sweeps; "
            "g[1:-1, 1:-1] = n / 4."
        ),
    ),
    "jacobi_exercise",
    "jacobi_sweep",
)
