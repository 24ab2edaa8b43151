"""Every public callable answers every input: a clear error or a right result, in bounded time.

The callables are discovered by walking the package, so a new public function or
app is fuzzed without editing this file. Public means: in a module whose name has
no leading underscore and which does not declare ``UNCHECKED = True`` (a kernel
module documented as unchecked, like dhermes/bezier's ``hazmat``), listed in the
module's ``__all__`` (or, without one, defined there under a name without a
leading underscore). Frozen dataclasses without checks of their own are records
the library fills, not inputs, and are left out, as are callables without
parameters (no input to fuzz) and the few in :data:`LEFT_OUT`, each with its
reason.

Each callable is called once with a generated valid input (from the parameter's
name and type hint, or the small :data:`VALID` table), then with bad variants of
each argument, one at a time: NaN, inf, huge finite values (1e200), empty
arrays, a wrong ndim, object dtype, negative and zero sizes, bogus choices, and
hypothesis-drawn variants of these. Each call runs under a bound on the processor
time it spends (a profiling timer, which the machine's load does not stretch, with a
wall-clock backstop) and an address-space limit. It must raise ValueError or TypeError, or
return a finite result, and must leave its inputs as they were (:data:`MODIFIES`
and :data:`NON_FINITE` list the documented exceptions).

``COURSE_FUZZ=long`` (``make fuzz``) runs a longer campaign (more drawn variants
per callable) and prints the counts by outcome and the slowest calls at the end;
any other value of ``COURSE_FUZZ`` prints them after the default campaign.
``COURSE_FUZZ_LOG=file`` appends every finding to ``file``; ``COURSE_FUZZ_ALL=1``
fuzzes the unchecked modules too, to see what they would do.
"""

from __future__ import annotations

import collections
import contextlib
import copy
import dataclasses
import importlib
import inspect
import io
import itertools
import math
import os
import pkgutil
import resource
import signal
import sys
import time
import types
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

import course

LONG = os.environ.get("COURSE_FUZZ", "") == "long"
# COURSE_FUZZ_ALL=1 fuzzes the modules documented as unchecked too, to see what they do.
EVERYTHING = bool(os.environ.get("COURSE_FUZZ_ALL"))
# The bound counts the processor time the call itself spends (ITIMER_PROF: user and system,
# every thread), which the machine's load does not stretch: a call past it does too much work,
# on a busy laptop as on a quiet one. Sizes are bounded so that every call stays far below
# it (SLOWEST reports the largest); the wall-clock bound only catches a call that waits.
BOUND = 10.0  # seconds of processor time per call
WALL_BOUND = 600.0  # seconds of wall-clock time per call, for a call that waits
EXAMPLES = 40 if LONG else 1  # hypothesis-drawn variants per callable, beyond the fixed ones
MEMORY = 6 * 2**30  # bytes a single call may add to the address space

OUTCOMES = (
    "accepted",  # returned a finite result
    "rejected",  # ValueError or TypeError
    "other exception",
    "non-finite",  # returned NaN or inf silently
    "past the bound",
    "modified input",
)
COUNTS: collections.Counter[str] = collections.Counter()
SLOWEST: list[tuple[float, str]] = []  # (processor seconds, call) of the slowest calls
UNCLEAR: collections.Counter[str] = collections.Counter()  # rejections not naming the parameter

# Callables left out, each with the reason; everything else public is fuzzed.
LEFT_OUT = {
    "course.lessons.l01_de_casteljau.check.curve_pass_picture": (
        "makes a checker's pass picture from the checker's own reference; no student input"
    ),
    "course.lessons.l01_de_casteljau.check.point_picture": (
        "makes a checker's failure picture from the checker's own reference; no student input"
    ),
    "course.classroom.cli.main": "runs whole commands; its argument parsing is argparse's",
    "course.check.references.call_budget": "a context manager for checkers; no data input",
    "course.lessons.l05_antialiasing.measurements.Table": "a str subclass: str's own constructor",
    "course.widgets.base.SliderApp.still": "the abstract base draws nothing: its apps' do",
    **{
        f"course.limits.{name}": (
            "bounds the work a call asks for, on values its callers have already checked "
            "(course._validate); fuzzed through every public function that calls it"
        )
        for name in (
            "require_bounded_evaluation",
            "require_bounded_flattening",
            "require_step_samples",
        )
    },
    "course.lessons.l08_poisson.convergence.write_lab_sweeps": (
        "the maintainers' step, minutes of solving; its path is checked first "
        "(tests/test_poisson_figures.py)"
    ),
}

# --------------------------------------------------------------------------
# Discovery


def _public_modules() -> list[types.ModuleType]:
    modules = []
    for info in pkgutil.walk_packages(course.__path__, "course."):
        if any(part.startswith("_") for part in info.name.split(".")[1:]):
            continue
        module = importlib.import_module(info.name)
        if getattr(module, "UNCHECKED", False) and not EVERYTHING:
            continue
        modules.append(module)
    return modules


def _record(value: Any) -> bool:
    """A frozen dataclass without checks of its own: a record the library fills, not an input."""
    return (
        inspect.isclass(value)
        and dataclasses.is_dataclass(value)
        and value.__dataclass_params__.frozen
        and not hasattr(value, "__post_init__")
    )


def _defined_here(module: types.ModuleType) -> dict[str, Any]:
    """The public callables a module defines: every name without a leading underscore.

    Not only ``__all__``: a name public by its spelling is public, so a helper
    missing from ``__all__`` is fuzzed all the same (and
    :func:`test_every_public_name_is_in_all` asks for it to be listed or renamed).
    """
    found = {}
    for name, value in vars(module).items():
        if name.startswith("_") or not callable(value):
            continue
        if getattr(value, "__module__", None) != module.__name__:
            continue  # re-exports are fuzzed where they are defined
        if inspect.isclass(value) and issubclass(value, BaseException):
            continue
        found[name] = value
    return found


class Method:
    """A public method of a public class: fuzzed on an instance built from valid input."""

    def __init__(self, owner: type, name: str) -> None:
        self.owner = owner
        self.name = name

    def __repr__(self) -> str:
        return f"Method({self.owner.__qualname__}.{self.name})"


def _own_methods(owner: type) -> list[str]:
    """Public methods a class defines in its own module (inherited app machinery aside).

    A mixin's methods count as its direct subclass's own: the mixin's module is unchecked
    (it cannot be built alone), so they are fuzzed on the class that mixes them in
    (``SliderApp`` for the pointer's ``axes_at`` and ``handle_at``).
    """
    mixed_in = {
        base.__module__
        for base in owner.__bases__
        if getattr(sys.modules.get(base.__module__), "UNCHECKED", False)
        and base.__module__.startswith("course.")
    }
    names = []
    for name in dir(owner):
        if name.startswith("_"):
            continue
        raw = inspect.getattr_static(owner, name)
        function = raw.__func__ if isinstance(raw, (staticmethod, classmethod)) else raw
        if not inspect.isfunction(function):
            continue
        if function.__module__ != owner.__module__ and function.__module__ not in mixed_in:
            continue
        names.append(name)
    return names


def _public_callables() -> dict[str, Any]:
    found: dict[str, Any] = {}
    for module in _public_modules():
        for name, value in _defined_here(module).items():
            if _record(value):
                continue
            found[f"{module.__name__}.{name}"] = value
            if inspect.isclass(value):
                for method in _own_methods(value):
                    found[f"{module.__name__}.{name}.{method}"] = Method(value, method)
    return found


def _takes_input(function: Any) -> bool:
    """Whether a callable has a parameter: one without any takes no input to fuzz."""
    if isinstance(function, Method):
        function = getattr(function.owner, function.name)
        parameters = list(inspect.signature(function).parameters)
        return len(parameters) > (0 if parameters[:1] != ["self"] else 1)
    try:
        return bool(inspect.signature(function).parameters)
    except (TypeError, ValueError):
        return True


CALLABLES = _public_callables()
TARGETS = sorted(name for name in set(CALLABLES) - set(LEFT_OUT) if _takes_input(CALLABLES[name]))

# --------------------------------------------------------------------------
# Valid inputs

RNG = np.random.default_rng(0)
CURVE = np.array([[2.0, 3.0], [14.0, 1.0], [3.0, 13.0], [13.0, 14.0]])
GRAY = np.random.default_rng(1).uniform(0, 1, (12, 14))
RGB = np.random.default_rng(2).uniform(0, 1, (12, 14, 3))
MASK = np.zeros((6, 7), dtype=bool)
MASK[2:4, 2:5] = True


def _student(*args: Any, **kwargs: Any) -> Any:
    return 0


def _valid_by_name(name: str, annotation: str, qualified: str) -> Any:
    """A valid value for a parameter without a default, or ``NotImplemented``."""
    key = f"{qualified}:{name}"
    if key in VALID:
        return VALID[key]()
    if name in VALID:
        return VALID[name]()
    if "Callable" in annotation:
        return _student
    if annotation.startswith("int"):
        return 3
    if annotation.startswith("float"):
        return 0.5
    return NotImplemented


VALID: dict[str, Any] = {
    # by parameter name
    "course.classroom.stubs.solution_bodies:source": lambda: "def f(x):\n    return 2 * x\n",
    "course.classroom.cli.app_command:notebooks": lambda: Path("notebooks") / "zh-CN",
    "course.classroom.cli.app_command:port": lambda: 8866,
    "course.classroom.cli.app_command:extra": lambda: ["--show_tracebacks=True"],
    "course.classroom.cli.lab_command:notebooks": lambda: Path("notebooks"),
    "course.classroom.cli.lab_command:teacher": lambda: False,
    "course.classroom.cli.lab_command:extra": lambda: [],
    "course.classroom.cli.lab_command:language": lambda: "zh-CN",
    "course.classroom.notebooks.language_folder:language": lambda: "zh-CN",
    "course.classroom.edition.translated:message": lambda: "RMS error",
    "course.classroom.edition.translated:language": lambda: "zh-CN",
    "course.classroom.edition.hidden_note:language": lambda: "zh-CN",
    "course.classroom.edition.notebook_language:notebook": lambda: {"cells": [], "metadata": {}},
    "points": lambda: CURVE.copy(),
    "control": lambda: CURVE.copy(),
    "polyline": lambda: CURVE.copy(),
    "samples": lambda: CURVE.copy(),
    "curve": lambda: CURVE.copy(),
    "t": lambda: 0.3,
    "p0": lambda: (2.0, 3.0),
    "p1": lambda: (11.0, 5.0),
    "p2": lambda: (4.0, 10.0),
    "image": lambda: GRAY.copy(),
    "gray": lambda: GRAY.copy(),
    "pattern": lambda: (GRAY > 0.5).astype(float),
    "halftone": lambda: (GRAY > 0.5).astype(float),
    "noise": lambda: GRAY.copy(),
    "background": lambda: RGB.copy(),
    "foreground": lambda: RGB[:6, :7].copy(),
    "mask": lambda: MASK.copy(),
    "offset": lambda: (3, 2),
    "shape": lambda: (12, 14),
    "out_shape": lambda: (6, 7),
    "rng": lambda: np.random.default_rng(0),
    "tolerance": lambda: 0.5,
    "step": lambda: 0.1,
    "width": lambda: 1.0,
    "rate": lambda: 2,
    "n": lambda: 4,
    "k": lambda: 2,
    "m": lambda: 5,
    "size": lambda: 8,
    "segments": lambda: 4,
    "degrees": lambda: [1, 2, 3],
    "x": lambda: np.array([1.5, 3.2]),
    "y": lambda: np.array([2.5, 0.7]),
    "frequency": lambda: 0.3,
    "count": lambda: 8,
    "centre": lambda: (6.0, 5.0),
    "reference": lambda: GRAY.copy(),
    "expected": lambda: np.array([[1, 2], [3, 4]]),
    "given": lambda: np.array([[1, 2], [3, 5]]),
    "pixels": lambda: np.array([[1, 2], [3, 4]]),
    "weights": lambda: np.array([0.5, 0.25]),
    "color": lambda: 1.0,
    "kernel": lambda: np.ones((3, 3)) / 9,
    "values": lambda: np.array([0.1, 0.5, 0.9]),
    "pixel_sets": lambda: [np.array([[1, 2], [3, 4]])],
    "text": lambda: "1, 2; 3, 4",
    "source": lambda: "x = 1\n",
    "computed": lambda: CURVE[:1].copy(),
    "max_calls": lambda: 10,
    "factor": lambda: 2,
    "in_size": lambda: 16,
    "out_size": lambda: 8,
    "resampler": lambda: _resampler(),
    "loop": lambda: _handout_loop(),
    "problem": lambda: _problem(),
    "path": lambda: _matplotlib_path(),
    "curves": lambda: _curves(),
    "force": lambda: False,
    # by qualified name
    "course.antialias.coverage.path_polyline:path": lambda: _curves(),
    "course.curves.paths.canvas_for:curves": lambda: [CURVE.copy()],
    "course.poisson.problem.PoissonProblem:values": lambda: _problem().values,
    "course.poisson.problem.PoissonProblem:region": lambda: _problem().region,
    "course.poisson.problem.PoissonProblem:source": lambda: _problem().source,
    "course.poisson.problem.PoissonProblem:corner": lambda: _problem().corner,
    "course.classroom.folders.inside_folder:name": lambda: "picture",
    "course.classroom.folders.inside_folder:suffix": lambda: ".png",
    "course.classroom.folders.loads_json:text": lambda: '{"cells": [], "nbformat": 4}',
    "course.lessons.l01_de_casteljau.check.as_point:value": lambda: (1.0, 2.0),
    "course.check.pictures.figure_png:figure": lambda: _figure(),
    "course.lessons.l03_lines_and_triangles.grid.pixel_grid:axes": lambda: _figure().add_subplot(),
    "course.lessons.l03_lines_and_triangles.apps.shared_edge_centres:a": lambda: np.array(
        [0.5, 0.5]
    ),
    "course.lessons.l03_lines_and_triangles.apps.shared_edge_centres:c": lambda: np.array(
        [3.5, 3.5]
    ),
    "course.lessons.l03_lines_and_triangles.apps.shared_edge_centres:shape": lambda: (4, 4),
    "course.widgets.base.SliderApp:controls": lambda: _controls(),
    "course.antialias.curve_quality.quality_table:images": lambda: {"a": GRAY.copy()},
    "course.curves.drawable_paths.flatten_each:flatten_one": lambda: lambda control: control,
    "course.curves.drawable_paths.wang_counts:control": lambda: CURVE[None].copy(),
    "course.poisson.methods.convergence:exact": lambda: _problem().values.copy(),
    "course.halftone.blue_noise_masks.cluster_energy:pattern": lambda: (GRAY[:8, :8] > 0.5).astype(
        float
    ),
    "course.raster.canvas.yellow_fraction:image": lambda: RGB.copy(),
    "course.poisson.editing.inpaint:mask": lambda: np.pad(MASK, ((3, 3), (3, 4))),
    "course.poisson.problem.inpaint_problem:mask": lambda: np.pad(MASK, ((3, 3), (3, 4))),
    "course.poisson.inputs.inpaint_inputs:mask": lambda: np.pad(MASK, ((3, 3), (3, 4))),
    "course.sampling.aliasing.spectrum:samples": lambda: np.cos(np.arange(16) * 0.7),
    "course.widgets.picture.png_bytes:pixels": lambda: np.zeros((4, 5, 3), dtype=np.uint8),
    "course.classroom.stubs.exercise_stub:source": lambda: "def f(x):\n    return x\n",
    "course.antialias.rendering.render:method": lambda: "bilinear_centres",
    "course.antialias.curve_quality.render_variant:name": lambda: "bilinear_centres",
    "course.antialias.windows.render_window:name": lambda: "bilinear_centres",
    "course.antialias.windows.render_window:size": lambda: 6,
    "course.antialias.windows.render_windows:names": lambda: [
        "bilinear_centres",
        "exact reference",
    ],
    "course.antialias.windows.render_windows:size": lambda: 6,
    "course.antialias.splats.splat:kind": lambda: "bilinear_centres",
    "course.poisson.methods.sweeps_to_residual:method": lambda: "jacobi",
    "course.poisson.methods.convergence:method": lambda: "jacobi",
    "course.poisson.methods.iterates:method": lambda: "jacobi",
    "course.lessons.l07_filtering.apps.blurred:border": lambda: "replicate",
    "course.lessons.l05_antialiasing.apps.label_of:name": lambda: "bilinear_centres",
    "course.widgets.base.parse_points:text": lambda: "1, 2; 3, 4",
    "course.widgets.base.pad:width": lambda: 12,
    "course.lessons.l07_filtering.apps.parse_kernel:text": lambda: "1 1 1; 1 1 1; 1 1 1",
    "course.lessons.l07_filtering.apps.format_kernel:kernel": lambda: np.ones((3, 3)),
    "course.lessons.l06_dithering.figures.methods_figure:images": lambda: {"a": GRAY.copy()},
    "course.lessons.l06_dithering.figures.methods_figure:centre": lambda: (6.0, 5.0),
    "course.lessons.l05_antialiasing.zoom_panel.zoom_figure:images": lambda: {"a": GRAY.copy()},
    "course.lessons.l06_dithering.figures.wraparound_figure:centre": lambda: (6.0, 5.0),
    "course.lessons.l01_de_casteljau.figures.yellow_check_figure:seed": lambda: "000",
    "course.lessons.l01_de_casteljau.check.curve_cases:max_points": lambda: 4,
    "course.classroom.edition.reveals:cell": lambda: {"cell_type": "code", "source": "x = 1"},
    "course.classroom.edition.solution_cells:notebook": lambda: {"cells": []},
    "course.classroom.release.student_notebook:notebook": lambda: {"cells": [], "metadata": {}},
    "course.classroom.gallery.ProgressBar:total": lambda: 3,
    "course.classroom.gallery.ProgressBar:stream": lambda: io.StringIO(),
    "course.classroom.gallery.write_gallery:stream": lambda: io.StringIO(),
    "course.classroom.gallery.write_gallery:pictures": lambda: [],
    "course.classroom.gallery.named_pictures:pictures": lambda: [],
    "course.classroom.gallery.named_pictures:names": lambda: [],
    "course.classroom.pictures.gray_color:value": lambda: 0.5,
    "course.classroom.pictures.rgb_color:value": lambda: (0.5, 0.2, 1.0),
    "course.classroom.pictures.colormap_color:name": lambda: "viridis",
    "course.classroom.pictures.colormap_color:value": lambda: 0.5,
    "course.classroom.pictures.png_of_gray:image": lambda: GRAY.copy(),
    "course.classroom.pictures.segments_of:polyline": lambda: CURVE.copy(),
    "course.classroom.pictures.read_only:array": lambda: GRAY.copy(),
    "course.curves.bezier_handouts.bresenham_curve:segments": lambda: 4,
    "course.curves.bezier_handouts.segments_report:segments": lambda: 4,
    "course.curves.bezier_handouts.trace_recursive:t": lambda: 0.3,
    "course.halftone.dither.bayer_matrix:size": lambda: 4,
    "course.sampling.aliasing.cosine_samples:count": lambda: 8,
    "course.metrics.rmse:reference": lambda: GRAY.copy(),
    "course.metrics.max_error:reference": lambda: GRAY.copy(),
    "course.lessons.l06_dithering.figures.block_mean:image": lambda: GRAY.copy(),
    "course.lessons.l06_dithering.figures.block_mean:factor": lambda: 2,
    "course.lessons.l06_dithering.apps.DitherComparisonApp:gray": lambda: np.tile(GRAY, (3, 3)),
    "course.lessons.l07_filtering.apps.RepeatedBlurApp:image": lambda: np.tile(GRAY, (6, 6)),
    "course.lessons.l08_poisson.apps.as_pixels_uint8:image": lambda: GRAY.copy(),
    "course.lessons.l08_poisson.apps.half_size:image": lambda: GRAY.copy(),
    "course.lessons.l03_lines_and_triangles.apps.octant:dx": lambda: 3,
    "course.lessons.l03_lines_and_triangles.apps.octant:dy": lambda: 1,
    "course.check.comparisons.same_pixels:expected": lambda: np.array([[1, 2]]),
    "course.check.comparisons.same_pixels:given": lambda: np.array([[1, 2]]),
    "course.check.pictures.pixel_picture:expected": lambda: np.array([[1, 2], [3, 4]]),
    "course.check.pictures.pixel_picture:given": lambda: np.array([[1, 2], [3, 5]]),
    "course.check.pictures.image_picture:expected": lambda: GRAY.copy(),
    "course.check.pictures.image_picture:given": lambda: GRAY.copy(),
    "course.check.pictures.curve_picture:expected": lambda: CURVE.copy(),
    "course.check.pictures.curve_picture:given": lambda: CURVE.copy(),
    "course.lessons.l01_de_casteljau.lesson.de_casteljau_picture:t": lambda: 0.3,
    "course.lessons.l02_bernstein.lesson.bernstein_picture:degree": lambda: 3,
    "course.lessons.l03_lines_and_triangles.lesson.triangle_picture:rule": lambda: "top-left",
    "course.lessons.l05_antialiasing.lesson.step_app_picture:weighting": lambda: "count",
    "course.poisson.problem.build_clone_problem:background": lambda: GRAY.copy(),
    "course.poisson.problem.build_clone_problem:foreground": lambda: GRAY[:6, :7].copy(),
    "course.poisson.problem.build_clone_problem:corner": lambda: (3, 2),
    "course.poisson.problem.build_clone_problem:mask": lambda: None,
    "course.poisson.problem.build_clone_problem:guidance": lambda: "plain",
    "course.poisson.windows.image_of:planes": lambda: GRAY[None].copy(),
    "course.poisson.windows.image_of:like": lambda: GRAY.copy(),
    "course.poisson.problem.paste_window:window": lambda: GRAY[:6, :7].copy(),
    "course.poisson.windows.window_at:corner": lambda: (3, 2),
    "course.poisson.windows.window_at:shape": lambda: (6, 7),
    "course.poisson.windows.window_in:image": lambda: GRAY[:6, :7].copy(),
    "course.poisson.windows.window_in:corner": lambda: (3, 2),
    "course.poisson.problem.PoissonProblem.paste:solution": lambda: GRAY[:6, :7].copy(),
    "course.poisson.problem.PoissonProblem.residual:solution": lambda: GRAY[:6, :7].copy(),
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel:axes": lambda: _figure().add_subplot(),
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel:curve": lambda: CURVE.copy(),
    "course.lessons.l01_de_casteljau.check.curve_picture_of:function": lambda: _de_casteljau(),
    "course.lessons.l01_de_casteljau.check.curve_picture_of:reference": lambda: _de_casteljau(),
    "course.lessons.l01_de_casteljau.check.curve_picture_of:title": lambda: "curve",
    "course.check.base.run_cases:exercise": lambda: "exercise",
    "course.check.base.run_cases:student": lambda: _de_casteljau(),
    "course.check.base.run_cases:reference": lambda: _de_casteljau(),
    "course.check.base.run_cases:cases": lambda: [{"points": CURVE.copy(), "t": 0.5}],
    "course.check.base.run_cases:compare": lambda: _close,
    "course.check.base.run_cases:hint": lambda: "look at t",
    "course.lessons.l04_supersampling.apps.SupersampleApp.error_curves:image": lambda: "zone plate",
    "course.lessons.l04_supersampling.apps.SupersampleApp.resample:image": lambda: "zone plate",
    "course.lessons.l04_supersampling.apps.SupersampleApp.resample:version": lambda: "centred",
    "course.lessons.l04_supersampling.apps.SupersampleApp.resample:rate": lambda: 2,
    "course.lessons.l05_antialiasing.figures.text_figure:text": lambda: "l",
    "course.lessons.l05_antialiasing.figures.text_figure:size": lambda: 12.0,
    "course.lessons.l05_antialiasing.figures.text_figure:zoom": lambda: 2,
    "course.lessons.l05_antialiasing.figures.brightness_figure:steps": lambda: (0.02, 0.01),
    "course.curves.paths.Curves:points": lambda: CURVE.copy(),
    "course.curves.paths.Curves:sizes": lambda: np.array([4]),
    "course.curves.paths.Curves.moved:offset": lambda: (1.0, 2.0),
    "course.lessons.l07_filtering.apps.KernelApp.filtered:kernel": lambda: np.ones((3, 3)) / 9,
    "course.lessons.l07_filtering.apps.KernelApp.filtered:border": lambda: "replicate",
    "course.classroom.gallery.ProgressBar.advance:label": lambda: "lesson",
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel.show:centre": lambda: (6.0, 5.0),
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel.show:size": lambda: 8,
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel.show:title": lambda: "zoom",
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel.show_window:window": lambda: GRAY[
        :4, :4
    ].copy(),
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel.show_window:extent": lambda: (0, 4, 4, 0),
    "course.lessons.l05_antialiasing.zoom_panel.ZoomPanel.show_window:title": lambda: "zoom",
    "course.lessons.l08_poisson.apps.PoissonIterationApp.iterate:method": lambda: "jacobi",
    "course.lessons.l08_poisson.apps.PoissonIterationApp.iterate:sweeps": lambda: 0,
}


def _de_casteljau() -> Any:
    from course.curves.bezier import de_casteljau

    return de_casteljau


def _close(expected: Any, given: Any) -> bool:
    return bool(np.allclose(expected, given))


def _resampler() -> Any:
    from course.sampling import resample

    return resample.supersample


def _handout_loop() -> Any:
    from course.curves import handout_loops

    loops = [v for v in vars(handout_loops).values() if isinstance(v, handout_loops.HandoutLoop)]
    return loops[0] if loops else NotImplemented


_PATH_NUMBERS = itertools.count()

# Parameters given a fresh temporary path, so that no call writes into the repository.
PATHS = {"out", "folder", "readme"}

# Non-finite results a callable documents.
NON_FINITE = {
    "course.lessons.l01_de_casteljau.check.as_point": (
        "converts a student's answer as given, NaN included"
    ),
}

# Exceptions other than ValueError and TypeError that a callable documents, with the reason.
RAISES: dict[str, tuple[tuple[type[BaseException], ...], str]] = {
    "course.curves.bezier.de_casteljau_recursive": (
        (RecursionError,),
        "the handouts' recursion: it raises RecursionError up front, naming the degree and "
        "the limit, and lesson 01 shows that error",
    ),
    **{
        f"course.classroom.folders.{name}": (
            (OSError,),
            "reads a file: OSError as the system raises it (a missing file, a folder); its "
            "callers, the commands, say it in one line naming the file",
        )
        for name in ("read_json_file", "read_text_file")
    },
}

# Inputs a callable modifies by design, as its name and docstring say.
MODIFIES = {"course.raster.canvas.paint": {"image"}}

README = (
    "# readme\n<!-- lesson table: generated by `python -m course map --readme README.md` -->\n"
    "<!-- end of the lesson table -->\n"
)


def _problem() -> Any:
    from course.poisson.problem import clone_problem

    return clone_problem(GRAY.copy(), GRAY[:6, :7].copy(), (3, 2))


def _figure() -> Any:
    from matplotlib.figure import Figure

    return Figure(figsize=(2, 2))


def _controls() -> Any:
    import ipywidgets

    return {"t": ipywidgets.FloatSlider(value=0.5, min=0.0, max=1.0)}


def _matplotlib_path() -> Any:
    from matplotlib.path import Path as MatplotlibPath

    return MatplotlibPath(CURVE, [1, 4, 4, 4])


def _curves() -> Any:
    from course.curves.paths import as_path

    return as_path(CURVE)


def valid_arguments(qualified: str, function: Any, tmp: Path) -> dict[str, Any] | None:
    """Keyword arguments that form a valid call, or None when one cannot be made."""
    try:
        parameters = inspect.signature(function).parameters
    except (TypeError, ValueError):
        return None
    arguments = {}
    for name, parameter in parameters.items():
        if parameter.kind in (parameter.VAR_POSITIONAL, parameter.VAR_KEYWORD):
            continue
        annotation = str(parameter.annotation)
        if name in PATHS or (name == "path" and isinstance(parameter.default, Path)):
            arguments[name] = tmp / f"{name}-{next(_PATH_NUMBERS)}"
            if name == "readme":
                arguments[name].write_text(README)
            elif name == "folder":
                arguments[name].mkdir()
            continue
        if name == "path" and qualified in (
            "course.classroom.edition.read_notebook",
            "course.classroom.folders.read_json_file",
            "course.classroom.folders.read_text_file",
        ):
            arguments[name] = tmp / f"lesson-{next(_PATH_NUMBERS)}.ipynb"
            arguments[name].write_text('{"cells": [], "metadata": {}, "nbformat": 4}')
            continue
        key = f"{qualified}:{name}"
        if parameter.default is not parameter.empty and key not in VALID:
            arguments[name] = parameter.default
            continue
        value = _valid_by_name(name, annotation, qualified)
        if value is NotImplemented:
            return None
        arguments[name] = value
    return arguments


# --------------------------------------------------------------------------
# Bad variants


def _kind(name: str, value: Any) -> str:
    if name in PATHS:
        return "path"
    if name == "rng":
        return "rng"
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, (int, np.integer)):
        return "int"
    if isinstance(value, (float, np.floating)):
        return "float"
    if isinstance(value, str):
        return "choice"
    if isinstance(value, np.random.Generator):
        return "rng"
    if name in ("shape", "out_shape") or (
        isinstance(value, tuple)
        and len(value) == 2
        and all(isinstance(v, (int, np.integer)) for v in value)
        and name not in ("offset", "p0", "p1", "p2", "pixel", "entry", "window")
    ):
        return "shape"
    if isinstance(value, (np.ndarray, list, tuple)):
        try:
            array = np.asarray(value)
        except ValueError:
            return "other"
        if array.dtype.kind in "biuf" and array.size:
            return "array"
    if callable(value):
        return "callable"
    return "other"


def _with_entry(array: np.ndarray, value: float) -> np.ndarray:
    bad = np.array(array, dtype=float, copy=True)
    bad.flat[bad.size // 2] = value
    return bad


def fixed_variants(kind: str, value: Any) -> list[Any]:
    """The bad variants every argument of this kind is given, in every run."""
    if kind == "int":
        # 2**14 and 10**6 lie under MAX_COUNT: sizes that must be bounded by what they cost.
        return [-1, 0, 2**14, 10**6, 10**9, 10**30, 2.5, "3", None]
    if kind == "float":
        # 1e-9 and 1e-15: steps and tolerances too fine for any bound on samples.
        return [math.nan, math.inf, -math.inf, 1e200, -1.0, 0.0, 1e-9, 1e-15, 1e-300, "0.5", None]
    if kind == "bool":
        return ["yes", None]
    if kind == "choice":
        return ["bogus", "", "W" * 200, 3, None]
    if kind == "rng":
        return [0, "seed"]
    if kind == "shape":
        return [(10**6, 10**6), (0, 5), (-1, 5), (5,), (2.5, 3), "ab", None]
    if kind == "path":
        return [3, None]
    if kind == "callable":
        return [3, None, _returns_nan, _returns_wrong_shape]
    if kind == "array":
        array = np.asarray(value)
        return [
            _with_entry(array, math.nan),
            _with_entry(array, math.inf),
            np.asarray(array, dtype=float) * 1e200 + 1e200,
            np.zeros((0, *array.shape[1:])),
            np.zeros(()),
            np.zeros((2, 2, 2, 2)),
            np.array(array, dtype=object),
            _long(array),
            "abc",
            None,
        ]
    return [None, "abc", math.nan]


def _long(array: np.ndarray) -> np.ndarray:
    """1501 rows of ``array``'s kind: a degree-1500 curve, a 1501-row image."""
    return np.resize(np.asarray(array, dtype=float), (1501, *np.shape(array)[1:]))


def _returns_nan(*args: Any, **kwargs: Any) -> Any:
    """A callback that answers NaN: the library must check what it is given back."""
    return math.nan


def _returns_wrong_shape(*args: Any, **kwargs: Any) -> Any:
    return np.zeros((2, 3, 4))


def drawn_variants(kind: str, value: Any) -> st.SearchStrategy[Any]:
    """Hypothesis-drawn bad variants of an argument of this kind."""
    huge = st.floats(min_value=1e15, max_value=1e300) | st.floats(min_value=-1e300, max_value=-1e15)
    non_finite = st.sampled_from([math.nan, math.inf, -math.inf])
    if kind == "int":
        return st.integers(max_value=0) | st.integers(min_value=10**8, max_value=10**40)
    if kind == "float":
        return non_finite | huge | st.floats(max_value=0.0, allow_nan=False)
    if kind == "shape":
        side = st.integers(min_value=-(10**7), max_value=0) | st.integers(10**6, 10**12)
        return st.tuples(side, st.integers(1, 10**9)) | st.tuples(st.integers(1, 10**9), side)
    if kind == "array":
        array = np.asarray(value, dtype=float)
        return st.builds(
            lambda where, bad: _put(array, where, bad),
            st.integers(0, max(array.size - 1, 0)),
            non_finite | huge,
        )
    return st.sampled_from(fixed_variants(kind, value))


def _put(array: np.ndarray, where: int, value: float) -> np.ndarray:
    bad = np.array(array, dtype=float, copy=True)
    if bad.size:
        bad.flat[where] = value
    return bad


# --------------------------------------------------------------------------
# One bounded call


class PastTheBound(BaseException):
    """Raised by the alarm; a BaseException, so no ``except Exception`` swallows it."""


def _alarm(signum: int, frame: Any) -> None:
    signal.setitimer(signal.ITIMER_PROF, 0.25)  # again, should something swallow this one
    raise PastTheBound


def _snapshot(value: Any) -> Any:
    try:
        return copy.deepcopy(value)
    except Exception:
        return value


def _same(before: Any, after: Any) -> bool:
    if isinstance(before, np.ndarray):
        if not isinstance(after, np.ndarray) or before.shape != after.shape:
            return False
        if before.dtype.kind in "fc":
            return bool(np.array_equal(before, after, equal_nan=True))
        try:
            return bool(np.array_equal(before, after))
        except Exception:
            return True
    if isinstance(before, (list, tuple)):
        return (
            type(before) is type(after)
            and len(before) == len(after)
            and all(_same(b, a) for b, a in zip(before, after, strict=True))
        )
    if isinstance(before, dict):
        return before.keys() == after.keys() and all(_same(before[k], after[k]) for k in before)
    return True


def _finite(value: Any, depth: int = 0) -> bool:
    if depth > 4:
        return True
    if isinstance(value, (bool, int, str, bytes)) or value is None:
        return True
    if isinstance(value, (float, complex, np.number)):
        return bool(np.isfinite(value))
    if isinstance(value, np.ndarray):
        return value.dtype.kind not in "fc" or bool(np.isfinite(value).all())
    if isinstance(value, (list, tuple)):
        return all(_finite(v, depth + 1) for v in value[:1000])
    if isinstance(value, dict):
        return all(_finite(v, depth + 1) for v in list(value.values())[:1000])
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return all(_finite(getattr(value, f.name), depth + 1) for f in dataclasses.fields(value))
    return True


@contextlib.contextmanager
def _bounded():
    """A time bound (a signal alarm) and an address-space bound around one call."""
    limits = resource.getrlimit(resource.RLIMIT_AS)
    used = _address_space()
    if used and (limits[1] == resource.RLIM_INFINITY or used + MEMORY < limits[1]):
        resource.setrlimit(resource.RLIMIT_AS, (used + MEMORY, limits[1]))
    previous = signal.signal(signal.SIGPROF, _alarm)
    previous_real = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_PROF, BOUND)
    signal.setitimer(signal.ITIMER_REAL, WALL_BOUND)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGPROF, previous)
        signal.signal(signal.SIGALRM, previous_real)
        resource.setrlimit(resource.RLIMIT_AS, limits)


@dataclasses.dataclass
class Outcome:
    kind: str
    detail: str = ""
    seconds: float = 0.0


def _brief(value: Any) -> str:
    """The start of a result's repr; a repr may fail (an exact Fraction of 5000 digits)."""
    try:
        return repr(value)[:120]
    except ValueError:
        return f"<{type(value).__name__} whose repr is too long>"


def _note_time(seconds: float, name: str, bad: str | None) -> None:
    SLOWEST.append((seconds, f"{name}({bad or 'valid input'})"))
    SLOWEST.sort(reverse=True)
    del SLOWEST[5:]


def _name_of(function: Any) -> str:
    return f"{getattr(function, '__module__', '')}.{getattr(function, '__qualname__', '')}"


def call(function: Any, arguments: dict[str, Any], bad: str | None = None) -> Outcome:
    """Call ``function(**arguments)`` under the bounds; classify what happened."""
    before = {name: _snapshot(value) for name, value in arguments.items()}
    start = time.process_time()
    try:
        with _bounded(), contextlib.redirect_stdout(io.StringIO()):
            result = function(**arguments)
            if isinstance(result, types.GeneratorType) or inspect.isgenerator(result):
                result = [next(result, None), next(result, None)]
    except PastTheBound:
        spent = time.process_time() - start
        return Outcome(
            "past the bound", f"{spent:.1f} s of processor time (bound {BOUND:g} s)", spent
        )
    except (ValueError, TypeError) as error:
        if bad is not None and bad not in str(error):
            UNCLEAR[_name_of(function)] += 1
        outcome = Outcome("rejected", f"{type(error).__name__}: {error}")
    except Exception as error:  # any other type is the finding, unless documented
        documented = RAISES.get(_name_of(function), ((), ""))[0]
        kind = "rejected" if isinstance(error, documented) else "other exception"
        outcome = Outcome(kind, f"{type(error).__name__}: {str(error)[:200]}")
    else:
        finite = _finite(result) or _name_of(function) in NON_FINITE
        outcome = Outcome("accepted" if finite else "non-finite", _brief(result))
    outcome.seconds = time.process_time() - start
    _note_time(outcome.seconds, _name_of(function), bad)
    changed = [name for name in arguments if not _same(before[name], arguments[name])]
    changed = [name for name in changed if name not in MODIFIES.get(_name_of(function), ())]
    if changed:
        return Outcome("modified input", f"modified {changed}", outcome.seconds)
    return outcome


# --------------------------------------------------------------------------
# The test


@pytest.fixture(scope="module", autouse=True)
def _limits_and_counts():
    """Print the counts by outcome at the end, when asked."""
    start = time.perf_counter()
    yield
    if os.environ.get("COURSE_FUZZ"):
        total = sum(COUNTS.values())
        print(
            f"\nfuzz: {len(TARGETS)} callables, {total} calls, {time.perf_counter() - start:.1f} s"
        )
        for kind in (*OUTCOMES, "no valid input", "valid input failed"):
            print(f"  {kind:>20}: {COUNTS[kind]}")
        print(f"  slowest calls, in processor seconds (the bound is {BOUND:g} s):")
        for seconds, name in SLOWEST:
            print(f"    {seconds:6.2f} {name}")
        print(f"  rejections whose message does not name the parameter: {sum(UNCLEAR.values())}")
        for name, count in UNCLEAR.most_common(10):
            print(f"    {count:4d} {name}")


def _address_space() -> int:
    try:
        fields = Path("/proc/self/statm").read_text().split()
    except OSError:
        return 0
    return int(fields[0]) * os.sysconf("SC_PAGE_SIZE")


@pytest.mark.parametrize("qualified", TARGETS)
def test_every_public_callable_answers_bad_input(qualified, tmp_path):
    function = CALLABLES[qualified]
    if isinstance(function, Method):
        function = _bound_method(qualified, function, tmp_path)
        if function is None:
            COUNTS["no valid input"] += 1
            pytest.skip("no valid instance known: add its arguments to VALID")
    valid = valid_arguments(qualified, function, tmp_path)
    if valid is None:
        COUNTS["no valid input"] += 1
        pytest.skip("no valid input known: add one to VALID")
    first = call(function, valid)
    if first.kind != "accepted":
        COUNTS["valid input failed"] += 1
        if os.environ.get("COURSE_FUZZ_LOG"):
            with open(os.environ["COURSE_FUZZ_LOG"], "a", encoding="utf-8") as log:
                log.write(f"{qualified} VALID {first.kind}: {first.detail[:200]}\n")
        pytest.fail(f"the valid call gave {first.kind}: {first.detail}")
    findings = []
    serial = itertools.count()

    def record(name: str, value: Any) -> None:
        fresh = {
            key: tmp_path / f"fresh-{key}-{next(serial)}"
            for key in valid
            if key in ("out", "folder")
        }
        for key in fresh:
            if key == "folder":
                fresh[key].mkdir()
        outcome = call(function, {**valid, **fresh, name: value}, bad=name)
        COUNTS[outcome.kind] += 1
        if outcome.kind not in ("accepted", "rejected"):
            findings.append(f"{name}={_short(value)}: {outcome.kind}: {outcome.detail}")

    kinds = {name: _kind(name, value) for name, value in valid.items()}
    parameters = inspect.signature(function).parameters
    for name, kind in kinds.items():
        for value in fixed_variants(kind, valid[name]):
            if value is None and parameters[name].default is None:
                continue  # None is this parameter's documented default, not a bad value
            record(name, value)

    if kinds and EXAMPLES:

        @settings(
            max_examples=EXAMPLES,
            database=None,
            deadline=None,
            phases=[Phase.generate],
            suppress_health_check=list(HealthCheck),
        )
        @given(data=st.data())
        def drawn(data):
            name = data.draw(st.sampled_from(sorted(kinds)))
            value = data.draw(drawn_variants(kinds[name], valid[name]))
            if not (value is None and parameters[name].default is None):
                record(name, value)

        drawn()
    _close_figures()
    if findings and os.environ.get("COURSE_FUZZ_LOG"):
        with open(os.environ["COURSE_FUZZ_LOG"], "a", encoding="utf-8") as log:
            log.writelines(f"{qualified} {line}\n" for line in findings)
    assert not findings, "\n".join(findings[:20])


def _bound_method(qualified: str, method: Method, tmp: Path) -> Any:
    """The method bound to an instance built from valid input, or None."""
    owner_name = qualified.rsplit(".", 1)[0]
    arguments = valid_arguments(owner_name, method.owner, tmp)
    if arguments is None:
        return None
    with contextlib.redirect_stdout(io.StringIO()):
        instance = method.owner(**arguments)
    return getattr(instance, method.name)


def _short(value: Any) -> str:
    if isinstance(value, np.ndarray):
        return f"array{value.shape}:{value.dtype}"
    return repr(value)[:60]


def _close_figures() -> None:
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")


def test_every_public_name_is_in_all():
    """A name public by its spelling is listed in ``__all__``, or renamed with an underscore."""
    missing = []
    for module in _public_modules():
        listed = set(getattr(module, "__all__", ()))
        missing += [f"{module.__name__}.{n}" for n in _defined_here(module) if n not in listed]
    missing = [name for name in missing if name not in LEFT_OUT]
    assert not missing, f"public by name but not in __all__: {missing}"


def test_discovery_finds_the_public_surface():
    assert "course.curves.flattening.flatten" in CALLABLES
    assert "course.lessons.l04_supersampling.apps.SupersampleApp" in CALLABLES
    # Methods of public classes, and names public by spelling whatever __all__ says.
    assert isinstance(CALLABLES["course.curves.paths.Curves.moved"], Method)
    assert isinstance(CALLABLES["course.poisson.problem.PoissonProblem.seam"], Method)
    assert "course.poisson.windows.window_at" in CALLABLES
    assert not any(name.split(".")[-1].startswith("_") for name in CALLABLES)
    assert set(LEFT_OUT) <= set(CALLABLES)


FAR = (1e18 + 0.5, 2.0**62, -(2.0**63), 1e200)


@pytest.mark.parametrize("far", FAR)
def test_no_far_away_sample_lands_on_the_canvas(far):
    """No wrap-around: a sample far off the canvas is rejected or dropped, never drawn."""
    from course import antialias, raster
    from course.antialias import splats

    samples = np.array([[far, 2.5], [2.5, far], [3.5, 3.5]])
    calls = {
        f"splat {kind}": lambda kind=kind: splats.splat(samples, kind, shape=(8, 8))
        for kind in splats.SPLATS
    }
    calls["nearest_pixels"] = lambda: (raster.nearest_pixels(samples, shape=(8, 8)), None)
    for name, make in calls.items():
        try:
            pixels, _ = make()
        except ValueError:
            continue
        assert np.all(np.abs(pixels - 3) <= 2), f"{name} put a far sample at {pixels.tolist()}"
    with pytest.raises(ValueError, match="points"):
        antialias.render([[far, 2.5], [3.5, 3.5]], (8, 8), "bilinear_centres")


def _spin(x: Any) -> None:
    while True:
        x = x + 1


def test_the_harness_classifies_what_it_sees(monkeypatch):
    """Each kind of finding is recognised: the campaign's counts mean what they say."""
    monkeypatch.setattr(sys.modules[__name__], "BOUND", 0.3)
    assert call(lambda x: x + 1, {"x": 1}).kind == "accepted"
    assert call(lambda x: float(x), {"x": "abc"}).kind == "rejected"
    assert call(lambda x: math.nan, {"x": 1}).kind == "non-finite"
    assert call(lambda x: {}[x], {"x": 1}).kind == "other exception"
    assert call(lambda x: x.append(1), {"x": [0]}).kind == "modified input"
    spun = call(_spin, {"x": 0})
    assert spun.kind == "past the bound"
    assert spun.seconds >= 0.2  # processor time, to the timer's tick
