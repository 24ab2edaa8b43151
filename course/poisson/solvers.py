"""Solvers for the discrete Poisson equation on a region of pixels.

Every solver here takes the same three arrays, channels first so that each
channel is one plane:

``values``, shape ``(C, h, w)``
    The known values outside the region (its boundary) and, inside the region,
    the starting guess of the iterative methods.
``region``, shape ``(h, w)``, bool
    The unknown pixels. It is False on the outer ring of rows and columns, so
    every unknown pixel has four neighbours in the array.
``source``, shape ``(C, h, w)``
    The guidance term ``b_p`` of each unknown pixel ``p``.

and solves, for every unknown pixel ``p`` with its four neighbours ``q``::

    4 u_p - sum_q u_q = b_p

where a neighbour outside the region keeps its known value. With
``b_p = sum_q (f_p - f_q) = -laplacian(f)_p`` this is Poisson image editing
(Pérez, Gangnet and Blake, 2003); with ``b = 0`` it is the Laplace equation of
inpainting. :mod:`course.poisson` builds the arrays; these are the pure array
functions behind it, with no input checks.

Two exact solvers (a sparse factorisation for any region, the discrete sine
transform for a rectangle) and three iterations (Jacobi, Gauss-Seidel and
successive over-relaxation) for the convergence lesson. The iterations have a
readable per-pixel form beside the vectorised one; the tests prove they agree.
The solvers run with their BLAS and FFT threads limited to the idle cores
(:func:`course.poisson._threads.limited_threads`): on a busy machine, a thread per core
made them several times slower.

References
----------
.. [1] P. Pérez, M. Gangnet and A. Blake, "Poisson image editing",
   ACM Transactions on Graphics 22(3), 313-318, 2003.
.. [2] Y. Saad, *Iterative Methods for Sparse Linear Systems*, 2nd ed., SIAM,
   2003, section 4.1 (Jacobi, Gauss-Seidel, SOR).

Unchecked kernels: like dhermes/bezier's ``hazmat``, this module trusts its
caller and checks no input (``UNCHECKED = True``, which the fuzz test reads).
Its public callers (:mod:`course.poisson`, :class:`course.poisson.problem.PoissonProblem`)
validate once, at their boundary.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np
import scipy.sparse
import scipy.sparse.linalg

from course._validate import as_choice
from course.poisson._threads import with_limited_threads
from course.poisson.sine_transform import box_solve

__all__ = [
    "JACOBI_SWEEPS_METHODS",
    "SOR_SWEEPS_METHODS",
    "PixelSystem",
    "defect",
    "iterate",
    "jacobi_rate",
    "jacobi_sweeps",
    "optimal_omega",
    "residual",
    "solve_direct",
    "solve_dst",
    "sor_sweeps",
    "sweeps",
]

UNCHECKED = True  # kernels for checked callers; see the module docstring

# The four neighbours as (dy, dx), in the order every sum below adds them:
# up, down, left, right. The loop form and the vectorised form add in the same
# order, so their floating-point results are identical, not just close.
NEIGHBOURS = ((-1, 0), (1, 0), (0, -1), (0, 1))
JACOBI_SWEEPS_METHODS = ("slices", "loop")
SOR_SWEEPS_METHODS = ("triangular_solve", "loop")


def neighbour_sum(u: np.ndarray) -> np.ndarray:
    """Sum of the four neighbours of every pixel but the outer ring: ``(C, h-2, w-2)``.

    Examples
    --------
    >>> u = np.arange(9.0).reshape(1, 3, 3)
    >>> neighbour_sum(u)  # 1 + 7 + 3 + 5
    array([[[16.]]])
    """
    return u[:, :-2, 1:-1] + u[:, 2:, 1:-1] + u[:, 1:-1, :-2] + u[:, 1:-1, 2:]


def defect(u: np.ndarray, region: np.ndarray, source: np.ndarray) -> np.ndarray:
    """How far ``u`` is from solving the equation: ``b_p + sum_q u_q - 4 u_p`` per pixel.

    Zero outside the region. This is the residual of the linear system, in the
    units of the image (1 is white).

    Examples
    --------
    >>> u = np.zeros((1, 3, 3)); u[0, 0, 1] = 1.0  # the pixel above the centre
    >>> region = np.zeros((3, 3), bool); region[1, 1] = True
    >>> defect(u, region, np.zeros((1, 3, 3)))[0]
    array([[0., 0., 0.],
           [0., 1., 0.],
           [0., 0., 0.]])
    """
    out = np.zeros_like(u)
    inner = neighbour_sum(u) + source[:, 1:-1, 1:-1] - 4.0 * u[:, 1:-1, 1:-1]
    np.copyto(out[:, 1:-1, 1:-1], inner, where=region[1:-1, 1:-1])  # no temporary, unlike where
    return out


def residual(u: np.ndarray, region: np.ndarray, source: np.ndarray) -> float:
    """The largest absolute :func:`defect` over the region and the channels.

    Examples
    --------
    >>> u = np.zeros((1, 3, 3)); u[0, 0, 1] = 0.5
    >>> region = np.zeros((3, 3), bool); region[1, 1] = True
    >>> residual(u, region, np.zeros((1, 3, 3)))
    0.5
    """
    return float(np.abs(defect(u, region, source)).max())


def jacobi_sweeps(
    values: np.ndarray, region: np.ndarray, source: np.ndarray, method: str = "slices"
) -> Iterator[np.ndarray]:
    """Jacobi iteration: every unknown becomes the average of its neighbours plus ``b / 4``.

    All pixels are updated from the previous iterate at once. Yields the
    iterate after each sweep, forever; it is one array updated in place, so
    copy it to keep it. ``method="slices"`` (the default) updates the whole
    region from four shifted slices of the previous iterate; ``"loop"`` is
    the same sweep pixel by pixel (slow: for reading and testing), with the
    same sums in the same order, so the iterates are equal bit for bit.

    Examples
    --------
    >>> values = np.zeros((1, 3, 4)); values[0, :, 0] = 1.0   # left edge white
    >>> region = np.zeros((3, 4), bool); region[1, 1:3] = True
    >>> sweeps = jacobi_sweeps(values, region, np.zeros((1, 3, 4)))
    >>> next(sweeps)[0, 1].copy(), next(sweeps)[0, 1]
    (array([1.  , 0.25, 0.  , 0.  ]), array([1.    , 0.25  , 0.0625, 0.    ]))
    """
    if as_choice(method, "method", JACOBI_SWEEPS_METHODS) == "loop":
        return _jacobi_sweeps_loop(values, region, source)
    return _jacobi_sweeps_slices(values, region, source)


def _jacobi_sweeps_slices(
    values: np.ndarray, region: np.ndarray, source: np.ndarray
) -> Iterator[np.ndarray]:
    u = values.copy()
    inner = u[:, 1:-1, 1:-1]  # a view: writing it writes u
    unknown = region[1:-1, 1:-1]
    guidance = source[:, 1:-1, 1:-1]
    while True:
        np.copyto(inner, (neighbour_sum(u) + guidance) * 0.25, where=unknown)
        yield u


def _jacobi_sweeps_loop(
    values: np.ndarray, region: np.ndarray, source: np.ndarray
) -> Iterator[np.ndarray]:
    """The per-pixel loop: each unknown from its four neighbours in the previous sweep."""
    u = values.copy()
    channels, height, width = u.shape
    while True:
        previous = u.copy()  # Jacobi reads only the previous iterate
        for c in range(channels):
            for y in range(1, height - 1):
                for x in range(1, width - 1):
                    if region[y, x]:
                        total = (
                            previous[c, y - 1, x]
                            + previous[c, y + 1, x]
                            + previous[c, y, x - 1]
                            + previous[c, y, x + 1]
                        )
                        u[c, y, x] = (total + source[c, y, x]) * 0.25
        yield u


def sor_sweeps(
    values: np.ndarray,
    region: np.ndarray,
    source: np.ndarray,
    omega: float = 1.0,
    method: str = "triangular_solve",
) -> Iterator[np.ndarray]:
    """Successive over-relaxation in row-by-row order; ``omega = 1`` is Gauss-Seidel.

    Pixels are visited row by row, left to right, and each update uses the
    values already updated in this sweep (its upper and left neighbours) and
    the previous sweep's values for the others, as the lab's in-place loop
    does. Each update moves a pixel ``omega`` times as far as Gauss-Seidel
    would: ``u <- (1 - omega) u + omega (sum_q u_q + b) / 4`` [2]_.

    ``method="loop"`` is that in-place loop, pixel by pixel (slow: for
    reading and testing; with ``omega = 1`` it is the lab's loop).
    ``"triangular_solve"`` (the default) sees that such a sweep is a
    triangular solve: with the unknowns numbered row by row, ``L`` and ``U``
    the links to earlier and later neighbours and ``c`` the right-hand side,
    ``(4 I - omega L) x_new = 4 (1 - omega) x + omega (U x + c)``. SuperLU
    solves it (the matrix is already triangular: no fill, no pivoting) in
    compiled code, which makes the row-by-row order fast without reordering
    it. The two agree to rounding. Yields the iterate after each sweep,
    forever; it is one array updated in place.

    Examples
    --------
    >>> values = np.zeros((1, 3, 4)); values[0, :, 0] = 1.0
    >>> region = np.zeros((3, 4), bool); region[1, 1:3] = True
    >>> next(sor_sweeps(values, region, np.zeros((1, 3, 4))))[0, 1]  # (1 + 0) / 4, then 0.25 / 4
    array([1.    , 0.25  , 0.0625, 0.    ])
    """
    if as_choice(method, "method", SOR_SWEEPS_METHODS) == "loop":
        return _sor_sweeps_loop(values, region, source, omega)
    return _sor_sweeps_triangular_solve(values, region, source, omega)


def _sor_sweeps_triangular_solve(
    values: np.ndarray, region: np.ndarray, source: np.ndarray, omega: float
) -> Iterator[np.ndarray]:
    system = PixelSystem(values, region, source)
    sweep = system.relaxation(omega)
    x = system.unknowns(values)
    u = values.copy()
    while True:
        x = sweep(x)
        system.scatter(x, u)
        yield u


def _sor_sweeps_loop(
    values: np.ndarray, region: np.ndarray, source: np.ndarray, omega: float
) -> Iterator[np.ndarray]:
    """The lab's in-place loop, relaxed by omega: up and left are already new."""
    u = values.copy()
    channels, height, width = u.shape
    while True:
        for c in range(channels):
            for y in range(1, height - 1):
                for x in range(1, width - 1):
                    if region[y, x]:  # in place: up and left are already new
                        total = u[c, y - 1, x] + u[c, y + 1, x] + u[c, y, x - 1] + u[c, y, x + 1]
                        average = (total + source[c, y, x]) * 0.25
                        u[c, y, x] = (1.0 - omega) * u[c, y, x] + omega * average
        yield u


def sweeps(
    values: np.ndarray, region: np.ndarray, source: np.ndarray, method: str, omega: float = 1.0
) -> Iterator[np.ndarray]:
    """:func:`jacobi_sweeps` for ``method="jacobi"``, else :func:`sor_sweeps`: the default forms.

    Examples
    --------
    >>> next(sweeps(np.eye(3)[None], np.pad([[True]], 1), np.zeros((1, 3, 3)), "sor", 1.5))[0, 1]
    array([ 0. , -0.5,  0. ])
    """
    if method == "jacobi":
        return _jacobi_sweeps_slices(values, region, source)
    return _sor_sweeps_triangular_solve(values, region, source, omega)


@with_limited_threads
def iterate(
    values: np.ndarray,
    region: np.ndarray,
    source: np.ndarray,
    method: str,
    iterations: int,
    omega: float = 1.0,
    tolerance: float | None = None,
) -> tuple[np.ndarray, int]:
    """Sweep ``"jacobi"`` or ``"sor"`` ``iterations`` times, or until the residual <= ``tolerance``.

    Returns the iterate and the number of sweeps done.

    Examples
    --------
    >>> values = np.zeros((1, 3, 4)); values[0, :, 0] = 1.0
    >>> region = np.zeros((3, 4), bool); region[1, 1:3] = True
    >>> u, done = iterate(values, region, np.zeros((1, 3, 4)), "sor", 100, tolerance=1e-9)
    >>> done, u[0, 1] * 15
    (8, array([15.,  4.,  1.,  0.]))
    """
    if method == "jacobi":
        sweeps = _jacobi_sweeps_slices(values, region, source)
        u = values
        for done in range(iterations):
            if tolerance is not None and residual(u, region, source) <= tolerance:
                return u.copy(), done
            u = next(sweeps)
        return u.copy(), iterations
    # SOR works on the unknowns only, and writes the image once at the end.
    system = PixelSystem(values, region, source)
    sweep = system.relaxation(omega)
    x = system.unknowns(values)
    done = 0
    while done < iterations and (tolerance is None or system.residual(x) > tolerance):
        x = sweep(x)
        done += 1
    return system.scatter(x, values.copy()), done


def optimal_omega(region: np.ndarray) -> float:
    """An estimate of the best SOR factor for a region.

    For an ``m x n`` rectangle of unknowns the Jacobi iteration shrinks the
    slowest error by ``rho = (cos(pi / (m + 1)) + cos(pi / (n + 1))) / 2`` per
    sweep, and ``omega = 2 / (1 + sqrt(1 - rho^2))`` is optimal for SOR [2]_.
    The slowest error is set mostly by the narrow side: a long 3-pixel
    scratch converges nearly as fast as a 3 x 3 square, whatever its bounding
    box. So for any region, ``m`` is its thickness (twice the largest
    chessboard distance from a region pixel to the outside, less one) and
    ``n`` the longer side of its bounding box; for a rectangle this is exact
    when its narrow side is odd, one pixel short when even.

    Examples
    --------
    >>> region = np.zeros((5, 5), bool); region[1:4, 1:4] = True
    >>> round(optimal_omega(region), 4)   # rho = cos(pi / 4)
    1.1716
    >>> scratch = np.zeros((5, 99), bool); scratch[1:4, 1:98] = True   # 3 wide
    >>> round(optimal_omega(scratch), 4)
    1.3146
    """
    import scipy.ndimage

    rows, columns = np.nonzero(region)
    height = rows.max() - rows.min() + 1
    width = columns.max() - columns.min() + 1
    depth = scipy.ndimage.distance_transform_cdt(region, metric="chessboard").max()
    thickness = min(2 * int(depth) - 1, height, width)
    rho = jacobi_rate((thickness, max(height, width)))
    return float(2.0 / (1.0 + np.sqrt(1.0 - rho**2)))


def jacobi_rate(shape: tuple[int, int]) -> float:
    """How much one Jacobi sweep shrinks the slowest error on a rectangle of ``shape = (H, W)``.

    Examples
    --------
    >>> round(jacobi_rate((109, 278)), 6)   # the lab's 280 x 111 plane, inside its ring
    0.999764
    """
    height, width = shape
    return float((np.cos(np.pi / (height + 1)) + np.cos(np.pi / (width + 1))) / 2)


class PixelSystem:
    """The region's equations as a sparse linear system ``(4 I - L - L^T) x = c``.

    Unknown number ``i`` is the ``i``-th region pixel in row-major order
    (``rows[i]``, ``columns[i]``); ``x`` has one column per channel. ``lower``
    holds a 1 for each pair of neighbouring unknowns, from the later pixel to
    the earlier one (its upper and left neighbours); ``constant`` is ``b`` plus
    the known values next to each unknown.
    """

    def __init__(self, values: np.ndarray, region: np.ndarray, source: np.ndarray) -> None:
        self.rows, self.columns = np.nonzero(region)
        self.flat = np.flatnonzero(region)  # the same pixels, as indices of a flat plane
        self.size = self.rows.size
        index = np.full(region.shape, -1)
        index[region] = np.arange(self.size)
        self.constant = source[:, self.rows, self.columns].T.copy()  # (size, C)
        later, earlier = [], []
        for dy, dx in NEIGHBOURS:
            ys, xs = self.rows + dy, self.columns + dx
            neighbour = index[ys, xs]
            known = neighbour < 0
            self.constant[known] += values[:, ys[known], xs[known]].T
            if dy < 0 or dx < 0:  # up or left: the earlier pixel of the pair
                linked = np.flatnonzero(~known)
                later.append(linked)
                earlier.append(neighbour[linked])
        later_index, earlier_index = np.concatenate(later), np.concatenate(earlier)
        self.lower = scipy.sparse.csr_matrix(
            (np.ones(later_index.size), (later_index, earlier_index)), shape=(self.size, self.size)
        )

    def unknowns(self, u: np.ndarray) -> np.ndarray:
        """The region's values of a ``(C, h, w)`` array as ``(size, C)``."""
        return u.reshape(u.shape[0], -1)[:, self.flat].T.copy()

    def scatter(self, x: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Write the unknowns ``x`` into the region of the ``(C, h, w)`` array ``u``; return it."""
        u.reshape(u.shape[0], -1)[:, self.flat] = x.T
        return u

    def residual(self, x: np.ndarray) -> float:
        """Largest ``|c + L x + L^T x - 4 x|``: :func:`residual` on the unknowns."""
        links = self.lower @ x + self.lower.T @ x
        return float(np.abs(self.constant + links - 4.0 * x).max(initial=0.0))

    def relaxation(self, omega: float) -> Callable[[np.ndarray], np.ndarray]:
        """One SOR sweep in row-major order, ``x -> x_new``: a triangular solve."""
        triangle = scipy.sparse.identity(self.size, format="csc") * 4.0 - omega * self.lower
        forward = scipy.sparse.linalg.splu(
            triangle.tocsc(),
            permc_spec="NATURAL",
            diag_pivot_thresh=0.0,
            options={"SymmetricMode": True},
        )
        upper = self.lower.T.tocsr()
        constant = omega * self.constant
        keep = 4.0 * (1.0 - omega)

        def sweep(x: np.ndarray) -> np.ndarray:
            right = omega * (upper @ x) + constant
            if keep:
                right += keep * x
            return forward.solve(right)

        return sweep

    def matrix(self) -> scipy.sparse.csc_matrix:
        """``4 I - L - L^T``: the five-point Laplacian restricted to the region, negated."""
        links = self.lower + self.lower.T
        return (scipy.sparse.identity(self.size) * 4.0 - links).tocsc()


@with_limited_threads
def solve_direct(values: np.ndarray, region: np.ndarray, source: np.ndarray) -> np.ndarray:
    """The exact solution for any region: a sparse factorisation (SuperLU).

    The matrix ``A = 4 I - N`` is the five-point Laplacian restricted to the
    region (``N`` links neighbouring unknowns); neighbours outside move to the
    right-hand side (:class:`PixelSystem`). Colour the pixels like a
    chessboard: a red pixel's neighbours are all black, so once the black
    values are known each red one is ``(c_r + N_rb x_b) / 4``. Eliminating the
    red half leaves ``(4 I - N_br N_rb / 4) x_b = c_b + N_br c_r / 4`` for the
    black half, which factorises about 1.4 times faster than the whole system.
    It is symmetric positive definite, so SuperLU runs in symmetric mode with
    a minimum-degree ordering of ``A + A^T`` and no pivoting, about twice as
    fast as its defaults here. One factorisation solves every channel.

    Examples
    --------
    >>> values = np.zeros((1, 3, 4)); values[0, :, 0] = 1.0
    >>> region = np.zeros((3, 4), bool); region[1, 1:3] = True
    >>> solve_direct(values, region, np.zeros((1, 3, 4)))[0, 1] * 15   # 4/15, 1/15
    array([15.,  4.,  1.,  0.])
    """
    system = PixelSystem(values, region, source)
    red = (system.rows + system.columns) % 2 == 0
    black = ~red
    links = (system.lower + system.lower.T).tocsr()
    black_to_red = links[black][:, red]
    schur = scipy.sparse.identity(int(black.sum())) * 4.0 - (black_to_red @ black_to_red.T) * 0.25
    factors = scipy.sparse.linalg.splu(
        schur.tocsc(),
        permc_spec="MMD_AT_PLUS_A",
        diag_pivot_thresh=0.0,
        options={"SymmetricMode": True},
    )
    constant_red, constant_black = system.constant[red], system.constant[black]
    x = np.empty_like(system.constant)
    x[black] = factors.solve(constant_black + (black_to_red @ constant_red) * 0.25)
    x[red] = (constant_red + black_to_red.T @ x[black]) * 0.25
    return system.scatter(x, values.copy())


@with_limited_threads
def solve_dst(values: np.ndarray, region: np.ndarray, source: np.ndarray) -> np.ndarray:
    """The exact solution for a rectangle: diagonalise the Laplacian with sine transforms.

    The region must be every pixel but the outer ring. On an ``m x n``
    rectangle with fixed values around it, the five-point Laplacian's
    eigenvectors are products of sines, ``sin(pi j k / (m + 1)) sin(pi i l /
    (n + 1))``, with eigenvalues ``4 - 2 cos(pi k / (m + 1)) - 2 cos(pi l /
    (n + 1))``. The known values around the rectangle move to the right-hand
    side; then the solve is a type-I discrete sine transform (DST) of it, a
    division by the eigenvalues, and the inverse transform
    (:func:`course.poisson.sine_transform.box_solve`): ``O(m n log(m n))``, no
    matrix, no iterations.

    Examples
    --------
    >>> values = np.zeros((1, 3, 4)); values[0, :, 0] = 1.0
    >>> region = np.zeros((3, 4), bool); region[1, 1:3] = True
    >>> solve_dst(values, region, np.zeros((1, 3, 4)))[0, 1] * 15
    array([15.,  4.,  1.,  0.])
    """
    rhs = source[:, 1:-1, 1:-1].copy()
    rhs[:, 0, :] += values[:, 0, 1:-1]
    rhs[:, -1, :] += values[:, -1, 1:-1]
    rhs[:, :, 0] += values[:, 1:-1, 0]
    rhs[:, :, -1] += values[:, 1:-1, -1]
    u = values.copy()
    u[:, 1:-1, 1:-1] = box_solve(rhs)
    return u
