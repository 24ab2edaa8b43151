"""The capacitance matrix method: the exact solution on any region from solves on a box.

The sine transform solves the Poisson equation on a rectangle in a few
milliseconds, but a mask is not a rectangle. Buzbee, Dorr, George and Golub
(1971) [1]_ embed the region in a box anyway and correct the box's solution with
"charges": one per pixel just outside the region.

Let ``L`` be the five-point operator ``4 u_p - sum_q u_q`` on a box that holds
the region ``R``, with zero values around the box; :func:`box_solve` applies
``L^{-1}`` with two sine transforms. Let ``c`` be the right-hand side on ``R``
(the guidance plus the known neighbours' values) extended by zero, and ``B``
the box pixels outside ``R`` that touch it. For any charges ``w`` on ``B``,
``y = L^{-1} (c + w)`` satisfies the region's equations wherever its values on
``B`` are zero: those are the only outside values a region pixel sees. So the
charges solve the small dense system

    C w = -(L^{-1} c)[B],      C = L^{-1}[B, B]   (the capacitance matrix),

and ``y = L^{-1} (c + w)`` is the exact solution on ``R``. ``C`` is symmetric
positive definite (a principal submatrix of ``L^{-1}``) and well conditioned
for a compact region (condition number about 50 for the benchmark's
200-pixel ellipse), so a Cholesky factorisation solves it to rounding level.
Two box solves and one ``|B| x |B|`` factorisation: the dense work grows with
the length of the region's border, ``|B|``, not with its area, which is why
this beats the sparse factorisation on compact regions and loses on thin or
ragged ones (:func:`faster_than_direct`). :func:`box_green` computes ``C``
without any box solve, from the Green's function of the box in closed form
(the solver computes only the triangle its factorisation reads,
:func:`green_upper`).
O'Leary and Widlund [2]_ develop the family of capacitance matrix methods.

This module holds pure array functions with no input checks, like
:mod:`course.poisson.solvers`, whose ``(values, region, source)`` convention
it shares. The solver limits its BLAS threads to the idle cores
(:mod:`course.poisson._threads`).

References
----------
.. [1] B. L. Buzbee, F. W. Dorr, J. A. George and G. H. Golub, "The direct
   solution of the discrete Poisson equation on irregular regions", SIAM
   Journal on Numerical Analysis 8(4), 722-736, 1971.
.. [2] D. P. O'Leary and O. Widlund, "Capacitance matrix methods for the
   Helmholtz equation on general three-dimensional regions", Mathematics of
   Computation 33(147), 849-879, 1979.

Unchecked kernels: like dhermes/bezier's ``hazmat``, this module trusts its
caller and checks no input (``UNCHECKED = True``, which the fuzz test reads).
Its public callers (:mod:`course.poisson`, :class:`course.poisson.problem.PoissonProblem`)
validate once, at their boundary.
"""

from __future__ import annotations

import itertools

import numpy as np
import scipy.fft
import scipy.linalg

from course.poisson._threads import with_limited_threads
from course.poisson.sine_transform import box_solve, sine_matrix
from course.poisson.solvers import defect

__all__ = [
    "BREAK_EVEN",
    "REFINEMENTS",
    "box_green",
    "box_shape",
    "box_solve",
    "charge_pixels",
    "dense_work",
    "embedding",
    "faster_than_direct",
    "green_upper",
    "solve_capacitance",
    "sorted_along_long_side",
]

UNCHECKED = True  # kernels for checked callers; see the module docstring

# The capacitance method is expected faster than the sparse factorisation when
# dense_work(region) < BREAK_EVEN * |region|^1.5 (measured; see faster_than_direct).
BREAK_EVEN = 200.0

# Iterative refinement: correct while the residual exceeds REFINE_ABOVE times the
# right-hand side's scale, at most REFINEMENTS times (one is nearly always enough).
REFINE_ABOVE = 1e-12
REFINEMENTS = 3

# Rows of the box that one run of green_upper's pixels spans: the closed form
# multiplies exp(theta * row) by exp(-theta * row), theta < 1.77, and within a
# run every factor and product stays below exp(1.77 * BLOCK_ROWS) < 1e200,
# far from overflow (1e308).
BLOCK_ROWS = 256

# green_upper computes its triangle in blocks of runs of this many pixels: with
# three runs it skips a third of the product, and smaller blocks are slower.
RUN_PIXELS = 160


@with_limited_threads
def solve_capacitance(values: np.ndarray, region: np.ndarray, source: np.ndarray) -> np.ndarray:
    """The exact solution for any region: box solves corrected by charges on its border.

    Embeds the region in its bounding box, grown to a size whose sine
    transforms are fast (:func:`embedding`), solves there, and corrects with
    the charges ``w`` of the capacitance system ``C w = -(L^{-1} c)[B]`` on the
    pixels ``B`` around the region (:func:`charge_pixels`), as in the module's
    description [1]_. One factorisation of ``C`` serves every channel.

    Rounding in ``C`` leaves a residual of about 1e-12 on a compact region;
    on a ragged one, where ``C`` is less well conditioned, it can reach 1e-10.
    While the residual exceeds ``1e-12`` times the right-hand side's scale,
    the same factorisation solves for the correction (iterative refinement),
    at most :data:`REFINEMENTS` times.

    Examples
    --------
    >>> values = np.zeros((1, 3, 4)); values[0, :, 0] = 1.0
    >>> region = np.zeros((3, 4), bool); region[1, 1:3] = True
    >>> u = solve_capacitance(values, region, np.zeros((1, 3, 4)))
    >>> np.round(u[0, 1] * 15, 12)   # 4/15, 1/15, as the direct solve
    array([15.,  4.,  1.,  0.])
    """
    height, width = region.shape
    inside = embedding(region)
    rows, columns = charge_pixels(inside)
    order = sorted_along_long_side(rows, columns, inside.shape)
    rows, columns = rows[order], columns[order]
    factor = None
    if rows.size:
        capacitance = green_upper(rows, columns, inside.shape)
        factor = scipy.linalg.cho_factor(
            capacitance, lower=False, overwrite_a=True, check_finite=False
        )

    def solve_on_region(rhs: np.ndarray) -> np.ndarray:
        """The box whose region pixels are ``A^{-1} rhs``, for ``rhs`` of the window's shape."""
        box = np.zeros((rhs.shape[0], *inside.shape))
        box[:, : height - 2, : width - 2] = rhs[:, 1:-1, 1:-1]
        if factor is not None:
            seen = box_solve(box)[:, rows, columns]  # what B sees without charges
            charges = scipy.linalg.cho_solve(factor, -seen.T, check_finite=False)
            box[:, rows, columns] = charges.T  # B is outside the region: its c is 0
        return box_solve(box)

    # Start from 0 on the region: the defect is then the right-hand side c, the
    # guidance plus the known neighbours; each pass solves for the correction.
    u = np.where(region, 0.0, values)
    unknown = u[:, 1:-1, 1:-1]  # a view: the region's pixels are written through it
    inner = region[1:-1, 1:-1]
    scale = None
    for _ in range(1 + REFINEMENTS):
        remaining = defect(u, region, source)
        largest = float(np.abs(remaining).max(initial=0.0))
        scale = max(1.0, largest) if scale is None else scale
        if largest <= REFINE_ABOVE * scale:
            break
        correction = solve_on_region(remaining)[:, : height - 2, : width - 2]
        # A masked add: ten times faster than gathering and scattering the region's pixels.
        np.add(unknown, correction, out=unknown, where=inner)
    return u


def embedding(region: np.ndarray) -> np.ndarray:
    """The region inside its box: the window without its outer ring, grown to :func:`box_shape`.

    Examples
    --------
    >>> region = np.zeros((4, 5), bool); region[1:3, 1:4] = True
    >>> embedding(region).astype(int)   # a 2 x 3 box is fast already
    array([[1, 1, 1],
           [1, 1, 1]])
    """
    height, width = region.shape
    inside = np.zeros(box_shape((height - 2, width - 2)), bool)
    inside[: height - 2, : width - 2] = region[1:-1, 1:-1]
    return inside


def dense_work(region: np.ndarray) -> float:
    """Operations the method spends on dense algebra: ``2 |B|^2 k + |B|^3 / 3``.

    Building ``C`` costs ``2 |B|^2 k`` (``k`` the box's shorter side, the
    number of sine modes), factorising it ``|B|^3 / 3``. The two box solves
    are cheap beside these once ``|B|`` is more than a few dozen.

    Examples
    --------
    >>> region = np.zeros((5, 5), bool); region[2, 2] = True   # 4 charges in a 3 x 3 box
    >>> dense_work(region)   # 2 * 16 * 3 + 64 / 3
    117.33333333333333
    """
    inside = embedding(region)
    charges = charge_pixels(inside)[0].size
    return 2.0 * charges**2 * min(inside.shape) + charges**3 / 3.0


def faster_than_direct(region: np.ndarray) -> bool:
    """Whether this method should beat the sparse factorisation on ``region``.

    The factorisation's work grows like ``|R|^1.5`` for a compact region of
    ``|R|`` pixels, this method's like :func:`dense_work`, which is small when
    the border is short for the area. Timing both on ellipses, rings, blobs,
    scratches and the plane's silhouette (``benchmarks/bench_poisson.py``
    prints some), they break even near ``dense_work = 200 |R|^1.5``: an
    ellipse is about 30 (six times faster than the factorisation), a
    200-pixel ring 12 pixels wide about 1500 (four times slower).

    Examples
    --------
    >>> disc = np.hypot(*np.indices((41, 41)) - 20) < 19
    >>> ring = disc & (np.hypot(*np.indices((41, 41)) - 20) > 16)
    >>> faster_than_direct(disc), faster_than_direct(ring)
    (True, False)
    """
    return dense_work(region) < BREAK_EVEN * float(region.sum()) ** 1.5


def box_shape(shape: tuple[int, int]) -> tuple[int, int]:
    """The smallest box at least ``shape = (H, W)`` whose sine transforms are fast.

    A type-I sine transform of length ``n`` is an FFT of length ``2 (n + 1)``,
    fast when ``n + 1`` has only small prime factors. The box may be larger
    than the region's: its extra pixels are simply outside the region.

    Examples
    --------
    >>> box_shape((160, 190))   # 161 = 7 x 23 and 191 is prime; 162 = 2 x 3^4, 192 = 2^6 x 3
    (161, 191)
    """
    height, width = shape
    return (
        scipy.fft.next_fast_len(height + 1, real=True) - 1,
        scipy.fft.next_fast_len(width + 1, real=True) - 1,
    )


def charge_pixels(inside: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rows and columns of ``B``: the box pixels outside the region with a neighbour in it.

    Pixels beyond the box's edge are zero in every box solve, so they need no
    charge.

    Examples
    --------
    >>> inside = np.zeros((3, 4), bool); inside[1, 1] = True
    >>> charge_pixels(inside)
    (array([0, 1, 1, 2]), array([1, 0, 2, 1]))
    """
    touching = np.zeros_like(inside)
    touching[1:] |= inside[:-1]
    touching[:-1] |= inside[1:]
    touching[:, 1:] |= inside[:, :-1]
    touching[:, :-1] |= inside[:, 1:]
    touching &= ~inside
    # np.nonzero of a 2-D array takes three times as long; the clone calls this thrice.
    return np.divmod(np.flatnonzero(touching), inside.shape[1])


def box_green(rows: np.ndarray, columns: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    """``L^{-1}[p, q]`` for the box pixels ``p, q`` at ``(rows, columns)``: the capacitance matrix.

    The whole symmetric matrix, for pixels in any order: :func:`green_upper`
    on the pixels sorted along the box's longer side, mirrored and put back in
    the given order.

    Examples
    --------
    >>> box_green(np.array([0]), np.array([0]), (1, 1))   # L = [4]
    array([[0.25]])
    >>> rows, columns = np.divmod(np.arange(6), 3)   # the whole 2 x 3 box
    >>> matrix = 4 * np.eye(6) - np.eye(6, k=1) - np.eye(6, k=-1) - np.eye(6, k=3) - np.eye(6, k=-3)
    >>> matrix[2, 3] = matrix[3, 2] = 0   # (0, 2) and (1, 0) are not neighbours
    >>> bool(np.allclose(box_green(rows, columns, (2, 3)) @ matrix, np.eye(6)))
    True
    """
    order = sorted_along_long_side(rows, columns, shape)
    upper = np.triu(green_upper(rows[order], columns[order], shape))
    green = upper + np.triu(upper, 1).T
    back = np.empty_like(order)
    back[order] = np.arange(order.size)
    return green[np.ix_(back, back)]


def sorted_along_long_side(
    rows: np.ndarray, columns: np.ndarray, shape: tuple[int, int]
) -> np.ndarray:
    """The order of the pixels that :func:`green_upper` needs: along the box's longer side.

    Examples
    --------
    >>> sorted_along_long_side(np.array([1, 0, 0]), np.array([0, 2, 1]), (2, 3))   # by column
    array([0, 2, 1])
    """
    along = rows if shape[0] >= shape[1] else columns
    return np.argsort(along, kind="stable")


def green_upper(rows: np.ndarray, columns: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    """:func:`box_green` on and above its diagonal, the pixels in :func:`sorted_along_long_side`.

    Below the diagonal the values are meaningless: a Cholesky factorisation
    of the upper triangle reads no more, and computing the lower blocks and
    mirroring cost the benchmark's ellipse clone a twentieth of its time.

    Expand in the sine modes of the shorter side (say the columns, mode ``l``
    with ``s_l(x) = sqrt(2 / (n + 1)) sin(pi l (x + 1) / (n + 1))`` and
    eigenvalue ``mu_l``); along the other side each mode leaves the
    tridiagonal system ``(2 + mu_l) g_y - g_{y-1} - g_{y+1}``, whose inverse is
    known in closed form. With ``2 + mu_l = 2 cosh(theta_l)`` and rows
    counted from 1,

        G_l(i, j) = sinh(t i) sinh(t (m + 1 - j)) / (sinh(t) sinh(t (m + 1))),   t = theta_l,

    for ``i <= j``, a product of a function of ``i`` and one of ``j``, so
    ``L^{-1}[p, q] = sum_l s_l(x_p) s_l(x_q) G_l(y_p, y_q)`` is one matrix
    product per block: about ``|B|^2 n`` operations for the triangle, no box
    solve. As the pixels are sorted by row, ``i <= j`` holds on and above the
    diagonal.

    Examples
    --------
    >>> rows, columns = np.array([0, 0, 1]), np.array([0, 1, 0])
    >>> np.triu(green_upper(rows, columns, (2, 2))) * 24   # L^{-1} = [[7, 2, 2], ...] / 24
    array([[7., 2., 2.],
           [0., 7., 1.],
           [0., 0., 7.]])
    """
    height, width = shape
    if height < width:  # modes along the shorter side: fewer of them
        return green_upper(columns, rows, (width, height))
    modes = np.arange(1, width + 1)
    # 2 + mu = 2 cosh(theta) with mu = 4 sin^2(pi l / (2 (n + 1))), without cancellation:
    theta = 2.0 * np.arcsinh(np.sin(np.pi * modes / (2.0 * (width + 1))))
    sines = np.sqrt(2.0 / (width + 1)) * sine_matrix(width)[columns]
    # sinh(theta i) = e^(theta i) (1 - e^(-2 theta i)) / 2, and likewise the others.
    # Each exponential depends on a row, or a distance between rows, 0 .. height:
    # two tables of height + 1 rows instead of four exponentials per pixel, a fifth
    # of the evaluations for the benchmark's ellipse, where they took a tenth of the
    # clone's time. The tables hold the very same products, so nothing changes.
    steps = np.arange(height + 1, dtype=float)[:, None]
    one_minus_decay = -np.expm1(-2.0 * theta * steps)
    decay = np.exp(theta * -steps)
    rising = one_minus_decay[rows + 1]
    falling = one_minus_decay[height - rows]  # at height + 1 - i
    falling /= 2.0 * np.sinh(theta) * -np.expm1(-2.0 * theta * (height + 1))

    # Runs of at most RUN_PIXELS pixels, none across two bands of BLOCK_ROWS rows.
    # The pixels are sorted by row, so every row of a run is at most every row
    # of a later run, and the blocks on and above the diagonal are enough.
    bands = [0, *(np.flatnonzero(np.diff(rows // BLOCK_ROWS)) + 1).tolist(), rows.size]
    edges = sorted(
        {
            int(edge)
            for start, stop in itertools.pairwise(bands)
            for edge in np.linspace(start, stop, -(-(stop - start) // RUN_PIXELS) + 1).round()
        }
    )
    runs = [slice(start, stop) for start, stop in itertools.pairwise(edges)]
    # exp(theta i) exp(-theta j) = exp(theta (i - j)), factored so that nothing
    # overflows: each run's exponentials from its own last row (left) or first
    # row (right), at most 1 each, and the block's product of the two, at most
    # exp(theta BLOCK_ROWS) < 1e200 on the diagonal and 1 above it.
    lefts, rights, lasts, firsts = [], [], [], []
    for run in runs:
        last, first = int(rows[run].max()), int(rows[run].min())
        lasts.append(last + 1.0)
        firsts.append(first + 1.0)
        lefts.append(sines[run] * (decay[last - rows[run]] * rising[run]))
        rights.append(sines[run] * (decay[rows[run] - first] * falling[run]))
    # Fortran order: LAPACK's, so that the factorisation need not copy it.
    green = np.empty((rows.size, rows.size), order="F")
    for index, upper in enumerate(runs):
        for other in range(index, len(runs)):
            scale = np.exp(theta * (lasts[index] - firsts[other]))
            green[upper, runs[other]] = lefts[index] @ (rights[other] * scale).T
    return green
