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
without any box solve, from the Green's function of the box in closed form.
O'Leary and Widlund [2]_ develop the family of capacitance matrix methods.

This module holds pure array functions with no input checks, like
:mod:`course.poisson_solvers`, whose ``(values, region, source)`` convention
it shares.

References
----------
.. [1] B. L. Buzbee, F. W. Dorr, J. A. George and G. H. Golub, "The direct
   solution of the discrete Poisson equation on irregular regions", SIAM
   Journal on Numerical Analysis 8(4), 722-736, 1971.
.. [2] D. P. O'Leary and O. Widlund, "Capacitance matrix methods for the
   Helmholtz equation on general three-dimensional regions", Mathematics of
   Computation 33(147), 849-879, 1979.
"""

from __future__ import annotations

import numpy as np
import scipy.fft
import scipy.linalg

from course.poisson_solvers import defect
from course.sine_transform import laplacian_eigenvalues, sine_matrix

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
    "solve_capacitance",
]

# The capacitance method is expected faster than the sparse factorisation when
# dense_work(region) < BREAK_EVEN * |region|^1.5 (measured; see faster_than_direct).
BREAK_EVEN = 200.0

# Iterative refinement: correct while the residual exceeds REFINE_ABOVE times the
# right-hand side's scale, at most REFINEMENTS times (one is nearly always enough).
REFINE_ABOVE = 1e-12
REFINEMENTS = 3

# Rows of the box that one block of box_green spans: the closed form
# multiplies exp(theta * row) by exp(-theta * row), theta < 1.77, and within a
# block every factor and product stays below exp(1.77 * BLOCK_ROWS) < 1e200,
# far from overflow (1e308).
BLOCK_ROWS = 256


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
    factor = None
    if rows.size:
        capacitance = box_green(rows, columns, inside.shape)
        factor = scipy.linalg.cho_factor(capacitance, lower=True, check_finite=False)

    def solve_on_region(rhs: np.ndarray) -> np.ndarray:
        """``A^{-1} rhs`` on the region, for ``rhs`` of the window's shape, zero off the region."""
        box = np.zeros((rhs.shape[0], *inside.shape))
        box[:, : height - 2, : width - 2] = rhs[:, 1:-1, 1:-1]
        if factor is not None:
            seen = box_solve(box)[:, rows, columns]  # what B sees without charges
            charges = scipy.linalg.cho_solve(factor, -seen.T, check_finite=False)
            box[:, rows, columns] = charges.T  # B is outside the region: its c is 0
        return box_solve(box)[:, inside]

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
        unknown[:, inner] += solve_on_region(remaining)
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
    return np.nonzero(touching & ~inside)


def box_solve(rhs: np.ndarray) -> np.ndarray:
    """``L^{-1} rhs`` on a ``(C, m, n)`` box with zero values around it: two sine transforms.

    The box's sine modes are the eigenvectors of ``L``, with eigenvalues
    ``4 - 2 cos(pi k / (m + 1)) - 2 cos(pi l / (n + 1))``.

    Examples
    --------
    >>> box_solve(np.ones((1, 1, 3)))   # 4 y_1 - y_2 = 1, 4 y_2 - y_1 - y_3 = 1
    array([[[0.35714286, 0.42857143, 0.35714286]]])
    """
    height, width = rhs.shape[1:]
    eigenvalues = laplacian_eigenvalues(height)[:, None] + laplacian_eigenvalues(width)[None, :]
    spectrum = scipy.fft.dstn(rhs, type=1, axes=(1, 2)) / eigenvalues
    return scipy.fft.idstn(spectrum, type=1, axes=(1, 2))


def box_green(rows: np.ndarray, columns: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    """``L^{-1}[p, q]`` for the box pixels ``p, q`` at ``(rows, columns)``: the capacitance matrix.

    Expand in the sine modes of the shorter side (say the columns, mode ``l``
    with ``s_l(x) = sqrt(2 / (n + 1)) sin(pi l (x + 1) / (n + 1))`` and
    eigenvalue ``mu_l``); along the other side each mode leaves the
    tridiagonal system ``(2 + mu_l) g_y - g_{y-1} - g_{y+1}``, whose inverse is
    known in closed form. With ``2 + mu_l = 2 cosh(theta_l)`` and rows
    counted from 1,

        G_l(i, j) = sinh(t i) sinh(t (m + 1 - j)) / (sinh(t) sinh(t (m + 1))),   t = theta_l,

    for ``i <= j``, a product of a function of ``i`` and one of ``j``, so
    ``L^{-1}[p, q] = sum_l s_l(x_p) s_l(x_q) G_l(y_p, y_q)`` is one matrix
    product per block of rows: about ``2 |B|^2 n`` operations, no box solve.
    The exponentials are factored around a centre row of each block so that
    none overflows.

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
    height, width = shape
    if height < width:  # modes along the shorter side: fewer of them
        return box_green(columns, rows, (width, height))
    modes = np.arange(1, width + 1)
    # 2 + mu = 2 cosh(theta) with mu = 4 sin^2(pi l / (2 (n + 1))), without cancellation:
    theta = 2.0 * np.arcsinh(np.sin(np.pi * modes / (2.0 * (width + 1))))
    sines = np.sqrt(2.0 / (width + 1)) * sine_matrix(width)[columns]
    i = (rows + 1)[:, None].astype(float)
    # sinh(theta i) = e^(theta i) (1 - e^(-2 theta i)) / 2, and likewise the others.
    rising = -np.expm1(-2.0 * theta * i)
    falling = -np.expm1(-2.0 * theta * (height + 1 - i))
    falling /= 2.0 * np.sinh(theta) * -np.expm1(-2.0 * theta * (height + 1))

    def block(upper: np.ndarray, lower: np.ndarray) -> np.ndarray:
        """``G`` between two sets of pixels, each row of ``upper`` <= each of ``lower``.

        Any centre row cancels in the product; this one keeps both factors bounded.
        """
        centre = (rows[upper].max() + rows[lower].min()) / 2.0 + 1.0
        left = sines[upper] * (np.exp(theta * (i[upper] - centre)) * rising[upper])
        right = sines[lower] * (np.exp(theta * (centre - i[lower])) * falling[lower])
        return left @ right.T

    bands = rows // BLOCK_ROWS
    groups = [np.flatnonzero(bands == label) for label in np.unique(bands)]

    def band(members: np.ndarray) -> np.ndarray:
        """``G`` within one band: the formula holds where row_p <= row_q; mirror it elsewhere."""
        inner = block(members, members)
        return np.where(rows[members, None] <= rows[None, members], inner, inner.T)

    if len(groups) == 1:
        return band(groups[0])
    green = np.empty((rows.size, rows.size))
    for index, upper in enumerate(groups):
        green[np.ix_(upper, upper)] = band(upper)
        for lower in groups[index + 1 :]:
            outer = block(upper, lower)
            green[np.ix_(upper, lower)] = outer
            green[np.ix_(lower, upper)] = outer.T
    return green
