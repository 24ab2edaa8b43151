"""Lesson 08's convergence: how far the lab's sweeps get, how slowly Jacobi's error decays,
and the sweeps app's questions answered.

The lab skeleton's 8000 Gauss-Seidel sweeps take about nine seconds, too long for a
lesson that runs in fifteen, so their record (residual and error every 50
sweeps, for Jacobi, Gauss-Seidel and SOR) is stored in
``course/lessons/l08_poisson/lab_sweeps.json``; :func:`compute_lab_sweeps` makes it
again, and a test compares the two. :func:`convergence_figure` draws it;
:func:`strip_and_square` gives Jacobi's slowest decay per sweep on small regions;
:func:`residual_scale` and :func:`sweep_study` answer the questions of
:class:`~course.lessons.l08_poisson.apps.PoissonIterationApp` on its own problem.
The clone's still pictures and the lab's scene are in :mod:`.figures`.
"""

from __future__ import annotations

import json
import os
import secrets
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from course import poisson
from course.i18n import N_, _
from course.lessons.l08_poisson.apps import METHOD_NAMES
from course.lessons.l08_poisson.figures import BLUE, GREEN, LAB_OFFSET, VERMILLION, lab_scene
from course.poisson import solvers
from course.widgets.picture import Still

__all__ = [
    "LAB_SWEEPS_FILE",
    "compute_lab_sweeps",
    "convergence_figure",
    "lab_sweeps",
    "residual_scale",
    "strip_and_square",
    "sweep_study",
    "write_lab_sweeps",
]

LAB_SWEEPS_FILE = Path(__file__).resolve().parent / "lab_sweeps.json"


def compute_lab_sweeps() -> dict[str, Any]:
    """Residual and error of Jacobi and Gauss-Seidel (8000 sweeps) and SOR (600) on the lab's
    scene, every 50 (SOR: 5) sweeps, and how far the lab's result is from the exact one.

    About nine seconds: the lesson reads :func:`lab_sweeps` instead.
    """
    lake, plane = lab_scene()
    problem = poisson.clone_problem(lake, plane, LAB_OFFSET)
    exact = poisson.solve(problem)
    record: dict[str, Any] = {"region": list(problem.region.shape)}
    for method, sweeps, every in (
        ("jacobi", 8000, 50),
        ("gauss_seidel", 8000, 50),
        ("sor", 600, 5),
    ):
        history = poisson.convergence(problem, method, sweeps, exact=exact, every=every)
        record[method] = {
            "sweeps": history.sweeps.tolist(),
            "residuals": history.residuals.tolist(),
            "errors": history.errors.tolist(),
        }
        if method == "gauss_seidel":
            error = np.abs(history.solution - exact).max(axis=2)[problem.region] * 255
            record["lab_result"] = {
                "mean_error": float(error.mean()),
                "share_above_one_grey_level": float((error > 1).mean()),
            }
    return record


def lab_sweeps() -> dict[str, Any]:
    """The stored record of :func:`compute_lab_sweeps`."""
    return json.loads(LAB_SWEEPS_FILE.read_text())


def write_lab_sweeps(path: str | os.PathLike[str] = LAB_SWEEPS_FILE) -> None:
    """Compute the record again and store it (the maintainers' step; a test compares).

    ``path`` is a file path, a ``str`` or a ``Path``. Everything that could refuse it is
    checked before the seconds of solving, by creating the temporary file it is written to:
    a folder, a file where a folder should be, a name too long, a folder that cannot be
    written. The record replaces ``path`` whole (the temporary file moved into place).
    """
    if isinstance(path, bool) or not isinstance(path, (str, os.PathLike)):
        raise TypeError(
            _("path must be a file path (str or pathlib.Path); got {path_type} {path}").format(
                path_type=type(path).__name__, path=repr(path)
            )
        )
    path = Path(path)
    if "\0" in str(path) or path.name == ".." or len(os.fsencode(path.name)) > _NAME_MAX:
        raise ValueError(
            _(
                "path must name a file, not '..', without NUL, of at most {most} bytes; got {start}"
            ).format(most=_NAME_MAX, start=repr(str(path)[:60]))
        )
    try:
        if path.is_dir():
            raise ValueError(
                _("path must name a file; {path} is a folder").format(path=repr(str(path)))
            )
        temporary = path.with_name(f".lab_sweeps-{secrets.token_hex(4)}.writing")
        existing = path.parent
        while not existing.exists() and existing != existing.parent:
            existing = existing.parent
        if not existing.is_dir():
            raise ValueError(
                _("path: {existing}, a parent of {path}, is a file, not a folder").format(
                    existing=existing, path=path
                )
            )
        path.parent.mkdir(parents=True, exist_ok=True)
        flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
        descriptor = os.open(temporary, flags, 0o666)
    except OSError as error:
        raise ValueError(
            _("path: cannot write into {folder} ({reason})").format(
                folder=path.parent, reason=error.strerror or error
            )
        ) from None
    try:
        with open(descriptor, "w", encoding="utf-8") as file:
            file.write(json.dumps(compute_lab_sweeps(), indent=1) + "\n")
        os.replace(temporary, path)
    finally:
        temporary.unlink(missing_ok=True)


# The longest file name most file systems take (NAME_MAX).
_NAME_MAX = 255

_NAMES = {**METHOD_NAMES, "gauss_seidel": N_("Gauss-Seidel (the lab's loop)")}


def convergence_figure() -> Still:
    """Error against the exact solution after each sweep, on the lab's scene.

    Examples
    --------
    >>> convergence_figure()  # doctest: +NORMALIZE_WHITESPACE
    rho = 0.99976 per Jacobi sweep; after the lab skeleton's 8000 sweeps: Jacobi up to 46 grey
    levels off, Gauss-Seidel up to 7.3; SOR up to 7.5e-07 after 600; the lab's result is 3.0
    grey levels off on average, 77% of its pixels by more than one
    """
    record = lab_sweeps()
    height, width = record["region"]
    rho = solvers.jacobi_rate((height - 2, width - 2))  # the unknowns: inside the ring
    figure = Figure(figsize=(8.0, 3.0), dpi=100)
    axes = figure.add_subplot()
    axes.set_title(
        _("the lab's scene; a Jacobi sweep leaves ρ = {rho:.5f} of the slowest error").format(
            rho=rho
        ),
        fontsize=9,
    )
    for method, colour, dashes in (
        ("jacobi", BLUE, "-"),
        ("gauss_seidel", VERMILLION, "--"),
        ("sor", GREEN, ":"),
    ):
        history = record[method]
        errors = np.maximum(np.array(history["errors"]) * 255, 1e-9)
        axes.semilogy(
            history["sweeps"], errors, color=colour, ls=dashes, lw=1.8, label=_(_NAMES[method])
        )
    axes.axvline(8000, color="0.3", ls=":", lw=1)
    axes.annotate(
        _("the lab skeleton's 8000"),
        (8000, 1e2),
        xytext=(-4, 0),
        textcoords="offset points",
        ha="right",
        fontsize=8,
    )
    axes.axhline(1.0, color="0.5", lw=0.8, ls="--")
    # Past SOR's last sweep (600), where only Jacobi and Gauss-Seidel run, far above the line.
    axes.annotate(
        _("one grey level"),
        (4000, 1.0),
        xytext=(0, 3),
        textcoords="offset points",
        ha="center",
        fontsize=8,
    )
    axes.set_xlabel(_("sweeps"), fontsize=8)
    axes.set_ylabel(_("largest error (grey levels)"), fontsize=8)
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=7, loc="lower left")
    figure.tight_layout()
    final = {method: record[method]["errors"][-1] * 255 for method in _NAMES}
    lab = record["lab_result"]
    caption = _(
        "rho = {rho:.5f} per Jacobi sweep; "
        "after the lab skeleton's 8000 sweeps: Jacobi up to {jacobi:.2g} grey levels off, "
        "Gauss-Seidel up to {gauss_seidel:.2g}; SOR up to {sor:.2g} after "
        "{sor_sweeps}; the lab's result is {mean:.1f} grey "
        "levels off on average, {share:.0%} of its pixels by "
        "more than one"
    ).format(
        rho=rho,
        jacobi=final["jacobi"],
        gauss_seidel=final["gauss_seidel"],
        sor=final["sor"],
        sor_sweeps=record["sor"]["sweeps"][-1],
        mean=lab["mean_error"],
        share=lab["share_above_one_grey_level"],
    )
    return Still.of(figure, caption)


def strip_and_square() -> str:
    """Jacobi's slowest decay per sweep on a 3 x 3 square and on ever longer 3-wide strips.

    Examples
    --------
    >>> print(strip_and_square())
    3 x 3 square: 0.7071; 3 x 30 strip: 0.8510; 3 x 300 strip: 0.8535; 3 x infinity: 0.8536
    """
    parts = [_("3 x 3 square: {rate:.4f}").format(rate=solvers.jacobi_rate((3, 3)))]
    parts += [
        _("3 x {length} strip: {rate:.4f}").format(length=n, rate=solvers.jacobi_rate((3, n)))
        for n in (30, 300)
    ]
    parts.append(_("3 x infinity: {rate:.4f}").format(rate=(np.cos(np.pi / 4) + 1) / 2))
    return _("; ").join(parts)


def residual_scale(app: Any) -> str:
    """How large an error a residual can hide, on the app's region, at the app's current sweep.

    The error e of an iterate solves (the negative Laplacian) e = residual;
    its smallest eigenvalue is 4 (1 - rho), so an error can be as large as
    the residual divided by it.
    """
    height, width = app.problem.region.shape
    rho = solvers.jacobi_rate((height - 2, width - 2))
    method, sweeps = app.value("method"), app.value("sweeps")
    solution = app.iterate(method, sweeps)
    residual = app.problem.residual(solution)
    factor = 1 / (4 * (1 - rho))
    measured = float(np.abs(solution - app.exact)[app.problem.region].max() * 255)
    return _(
        "rho = {rho:.5f}, so a residual r can hide an error of about r / (4 (1 - rho)) = "
        "{factor:.0f} r. {method} after {sweeps} sweeps: r = {residual:.2g}, an error "
        "of about {error:.0f} grey levels; measured, up to {measured:.0f}"
    ).format(
        rho=rho,
        factor=factor,
        method=_(_NAMES[method]),
        sweeps=sweeps,
        residual=residual,
        error=factor * residual * 255,
        measured=measured,
    )


def sweep_study(app: Any) -> str:
    """The sweeps app's two questions, answered on its own problem.

    Where Jacobi's error is after 10, 100 and 1000 sweeps: its mean, in grey
    levels, within 5 px of the ring and more than 40 px from it; and how
    many sweeps SOR needs to be within one grey level everywhere.
    """
    from scipy import ndimage

    region = app.problem.region
    distance = ndimage.distance_transform_cdt(region, metric="chessboard")
    near, far = region & (distance <= 5), region & (distance > 40)
    lines = []
    for sweeps in (10, 100, 1000):
        error = np.abs(app.iterate("jacobi", sweeps) - app.exact).max(axis=2) * 255
        lines.append(
            _(
                "Jacobi, {sweeps:4d} sweeps: mean error {near:6.1f} grey levels "
                "near the ring, {far:6.1f} more than 40 px from it"
            ).format(sweeps=sweeps, near=error[near].mean(), far=error[far].mean())
        )
    for sweeps in app.stops:
        error = np.abs(app.iterate("sor", sweeps) - app.exact).max(axis=2)[region] * 255
        if error.max() < 1:
            lines.append(
                _("SOR: within one grey level everywhere after {sweeps} sweeps").format(
                    sweeps=sweeps
                )
            )
            break
    return "\n".join(lines)
