"""Lesson 02, the Bernstein form: its registry entry, pictures, landmarks and printed lines.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

from dataclasses import replace

from course.classroom.pictures import (
    CRIMSON,
    app_picture,
    landmark_at,
    panel_picture,
    still_picture,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.curves.bezier import bernstein_basis
from course.i18n import N_, _, yes_no
from course.images import EXAMPLE_POINTS
from course.lessons.l02_bernstein import figures
from course.lessons.l02_bernstein.apps import BernsteinBasisApp
from course.lessons.printed import degree_column, degree_numeral
from course.widgets.base import SliderApp
from course.widgets.picture import rounding_level

UNCHECKED = True  # see the module docstring


def print_basis_properties(degree: int, total: float, mirror: float, ends: bool) -> None:
    """Print how far the basis of ``degree`` is from summing to 1 and from its mirror image.

    ``total`` and ``mirror`` are the largest differences, shown as rounding levels;
    ``ends`` says whether the basis at t = 0 and 1 is exactly the first and last unit row.

    Examples
    --------
    >>> print_basis_properties(3, 2e-16, 0.0, True)
    degree  3: |sum - 1| below 1e-12, |mirror| below 1e-12, ends exact: yes
    """
    print(
        _("degree {degree:>2}: |sum - 1| {total}, |mirror| {mirror}, ends exact: {ends}").format(
            degree=degree_column(degree),
            total=rounding_level(total),
            mirror=rounding_level(mirror),
            ends=yes_no(ends),
        )
    )


def print_comb_calls(m: int, calls: int, exact: int) -> None:
    """Print how many calls the recursive ``comb(m, m // 2)`` makes, beside C(m, m // 2).

    Examples
    --------
    >>> print_comb_calls(4, 11, 6)
    comb(4, 2): 11 calls for C(4, 2) = 6
    """
    print(
        _("comb({m}, {k}): {calls} calls for C({m}, {k}) = {exact}").format(
            m=m, k=m // 2, calls=calls, exact=exact
        )
    )


def print_comb_calls_against_binomial(m: int, calls: int, exact: int) -> None:
    """Print the recursive ``comb(m, m // 2)``'s calls beside C(m, m // 2) - 1, with commas.

    Examples
    --------
    >>> print_comb_calls_against_binomial(20, 184755, 184756)
    comb(20, 10): 184,755 calls, C(20, 10) - 1 = 184,755
    """
    print(
        _("comb({m}, {k}): {calls:,} calls, C({m}, {k}) - 1 = {less_one:,}").format(
            m=m, k=m // 2, calls=calls, less_one=exact - 1
        )
    )


def print_calls_growth(first: int, last: int, ratio: float) -> None:
    """Print by what factor the calls grow from ``m = first`` to ``last``, beside 2^(last - first).

    Examples
    --------
    >>> print_calls_growth(20, 24, 14.63)
    from m = 20 to 24: x14.6 (2^4 = 16)
    """
    power = last - first
    print(
        _("from m = {first} to {last}: x{ratio:.1f} (2^{power} = {doubled})").format(
            first=first, last=last, ratio=ratio, power=power, doubled=2**power
        )
    )


def print_calls_per_curve(degree: int, points: int, calls: int) -> None:
    """Print how many calls of the recursive ``comb`` ``naive_bezier`` makes for one curve.

    Examples
    --------
    >>> print_calls_per_curve(20, 1001, 1049605557)
    naive_bezier at degree 20, 1001 points: 1,049,605,557 calls of comb
    """
    print(
        _("naive_bezier at degree {degree}, {points} points: {calls:,} calls of comb").format(
            degree=degree_numeral(degree), points=points, calls=calls
        )
    )


def print_int32_binomial(m: int, value: int, exact: int) -> None:
    """Print C(m, m // 2) as a 32-bit Pascal row holds it, beside the exact value.

    Examples
    --------
    >>> print_int32_binomial(34, -1961361076, 2333606220)
    C(34, 17) in 32 bits: -1,961,361,076   exact:  2,333,606,220
    """
    print(
        _("C({m}, {k}) in 32 bits: {value:>14,}   exact: {exact:>14,}").format(
            m=m, k=m // 2, value=value, exact=exact
        )
    )


def print_horner_gap(degree: int, gap: float) -> None:
    """Print how far Horner's Bernstein form is from the handout's sum, as a rounding level.

    Examples
    --------
    >>> print_horner_gap(3, 1e-13)
    degree  3: Horner against the handout's sum: below 1e-10 px
    """
    print(
        _("degree {degree:>2}: Horner against the handout's sum: {gap} px").format(
            degree=degree_column(degree), gap=rounding_level(gap, 1e-10)
        )
    )


def print_comb_timing(m: int, calls: int, seconds: float) -> None:
    """Print how long the recursive ``comb(m, m // 2)`` took: its calls, ms, and ns a call.

    Examples
    --------
    >>> print_comb_timing(14, 3431, 0.000645)
    m = 14:    3,431 calls,     0.6 ms,   188 ns a call
    """
    print(
        _("m = {m}: {calls:>8,} calls, {ms:7.1f} ms, {ns:5.0f} ns a call").format(
            m=m, calls=calls, ms=seconds * 1e3, ns=seconds / calls * 1e9
        )
    )


#: Python's message for an int too large for a float (``float(10**400)``).
INT_TOO_LARGE = N_("int too large to convert to float")


def print_binomial_as_float(m: int, value: float | OverflowError) -> None:
    """Print C(m, m // 2) as a float, or the ``OverflowError`` converting it raised.

    Examples
    --------
    >>> print_binomial_as_float(1029, 1.4302e308)
    C(1029, 514) as a float: 1.430e+308
    >>> print_binomial_as_float(1030, OverflowError("int too large to convert to float"))
    C(1030, 515) as a float: int too large to convert to float
    >>> from course.i18n import language
    >>> with language("zh-CN"):
    ...     print_binomial_as_float(1030, OverflowError("int too large to convert to float"))
    C(1030, 515) 转成浮点数：整数太大，无法转成浮点数（OverflowError）
    """
    if isinstance(value, OverflowError):
        # Python's own message is English: the known one is shown in the current language.
        error = _(INT_TOO_LARGE) if str(value) == INT_TOO_LARGE else value
        line = _("C({m}, {k}) as a float: {error}").format(m=m, k=m // 2, error=error)
    else:
        line = _("C({m}, {k}) as a float: {value:.3e}").format(m=m, k=m // 2, value=value)
    print(line)


def print_de_casteljau_error(degree: int, worst: float) -> None:
    """Print de Casteljau's worst relative error at ``degree``, as a rounding level.

    Examples
    --------
    >>> print_de_casteljau_error(100, 3e-15)
    degree 100: de Casteljau's worst error below 1e-12 of the polygon's size
    """
    print(
        _("degree {degree}: de Casteljau's worst error {worst} of the polygon's size").format(
            degree=degree_numeral(degree), worst=rounding_level(worst)
        )
    )


def print_middle_peak(degree: int, peak: float) -> None:
    """Print the peak of the middle Bernstein polynomial of ``degree``, at t = 1/2.

    Examples
    --------
    >>> print_middle_peak(4, 0.375)
    degree  4: the middle bump's peak B(n/2, n)(1/2) = 0.375
    """
    print(
        _("degree {degree:>2}: the middle bump's peak B(n/2, n)(1/2) = {peak:.3f}").format(
            degree=degree_column(degree), peak=peak
        )
    )


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


def preview() -> bytes:
    """The course map's preview: the cubic Bernstein basis at t = 0.3."""
    app = BernsteinBasisApp(degree=3, t=0.3)
    return panel_picture(app, app.axes)


LESSON = Lesson(
    outcomes=(
        N_("write a Bézier curve as its control points weighted by Bernstein polynomials"),
        N_("compute binomials exactly by Pascal's rule and write naive_bezier for any degree"),
        N_("read a curve's end tangents and derivative off its control polygon"),
    ),
    minutes=50,
    preview=Picture(
        "02_preview", "the four cubic Bernstein polynomials, and their values at t = 0.3", preview
    ),
    handout=N_(
        "the GAMES101 framework's naive_bezier, generalised to any degree with the "
        "recursive comb of the any-degree report (任意多次的曲线绘制)"
    ),
    teaches=N_(
        "the Bernstein basis under a degree slider; binomials by Pascal's rule, written "
        "and checked, against the handout's exponential recursion and 32-bit int; naive_bezier of "
        "any degree; end tangents and the hodograph; accuracy against the degree"
    ),
    pictures=(
        bernstein_picture(3, 0.3),
        bernstein_picture(9, 0.5),
        still_picture(
            "02_pascal_triangle",
            "Pascal's triangle: each entry the sum of two",
            figures.pascal_figure,
        ),
        still_picture(
            "02_end_tangents",
            "the end tangents along the polygon's edges",
            figures.tangents_figure,
            EXAMPLE_POINTS[:4],
        ),
        still_picture(
            "02_hodograph",
            "velocities along a cubic and its hodograph",
            figures.hodograph_figure,
            EXAMPLE_POINTS[:4],
        ),
        still_picture(
            "02_accuracy_by_degree", "four evaluations' error by degree", figures.accuracy_figure
        ),
    ),
    sliders=(
        SliderMove(
            build=bernstein_app,
            control="t",
            moves=(("ArrowLeft", "ArrowLeft"), ("Home",)),
            landmarks=bernstein_landmarks,
        ),
    ),
)
