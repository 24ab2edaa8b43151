"""course.poisson: every solver against the equation it solves, and against each other."""

import inspect
import json
from pathlib import Path

import numpy as np
import pytest
import scipy.ndimage
from hypothesis import given
from hypothesis import strategies as st

from course import images, poisson
from course.poisson import solvers

LAPLACIAN = np.array([[0, 1, 0], [1, -4, 1], [0, 1, 0]], float)


def laplacian(image):
    """The five-point Laplacian of every pixel, per channel (independent of the library)."""
    kernel = LAPLACIAN if image.ndim == 2 else LAPLACIAN[..., None] * np.eye(3)[1][None, None]
    return scipy.ndimage.convolve(image, kernel, mode="nearest")


def scene(rgb=True, shape=(24, 30), patch=(11, 14), seed=0):
    """A smooth random background and a patch with gradients of its own, in [0, 1]."""
    rng = np.random.default_rng(seed)
    extra = (3,) if rgb else ()
    background = scipy.ndimage.gaussian_filter(rng.random((*shape, *extra)), 2) * 0.6 + 0.2
    foreground = rng.random((*patch, *extra)) * 0.5 + 0.25
    return background, foreground


def mask_for(patch, seed=1):
    """A blobby mask inside the patch's outer ring."""
    rng = np.random.default_rng(seed)
    blob = scipy.ndimage.gaussian_filter(rng.random(patch), 1.5) > 0.5
    blob[[0, -1], :] = False
    blob[:, [0, -1]] = False
    blob[patch[0] // 2, patch[1] // 2] = True
    return blob


def region_in_background(shape, offset, mask):
    region = np.zeros(shape[:2], bool)
    x, y = offset
    region[y : y + mask.shape[0], x : x + mask.shape[1]] = mask
    return region


def interior(patch):
    mask = np.zeros(patch, bool)
    mask[1:-1, 1:-1] = True
    return mask


# --- the exact solvers solve the discrete Poisson equation ------------------------


def assert_solves_poisson_with_background_boundary(result, background, foreground, offset, mask):
    """Inside the region the result's Laplacian is the foreground's; outside it, the background."""
    region = region_in_background(background.shape, offset, mask)
    wanted = np.zeros_like(background)
    x, y = offset
    h, w = foreground.shape[:2]
    wanted[y : y + h, x : x + w] = laplacian(foreground)
    assert np.abs(laplacian(result) - wanted)[region].max() < 1e-8
    # Everything outside the region, the ring included, is the background, exactly.
    assert np.array_equal(result[~region], background[~region])


@pytest.mark.parametrize("rgb", [False, True])
@pytest.mark.parametrize("method", ["direct", "dst", "capacitance"])
def test_exact_solvers_satisfy_the_poisson_equation_and_keep_the_boundary(method, rgb):
    background, foreground = scene(rgb)
    result = poisson.seamless_clone(background, foreground, (7, 5), method=method, clip=False)
    mask = interior(foreground.shape[:2])
    assert_solves_poisson_with_background_boundary(result, background, foreground, (7, 5), mask)


def test_exact_solvers_with_a_mask_solve_the_equation_on_the_mask_only():
    background, foreground = scene()
    mask = mask_for(foreground.shape[:2])
    result = poisson.seamless_clone(background, foreground, (4, 9), mask=mask, clip=False)
    assert_solves_poisson_with_background_boundary(result, background, foreground, (4, 9), mask)


@given(
    height=st.integers(3, 40),
    width=st.integers(3, 40),
    seed=st.integers(0, 2**16),
)
def test_dst_equals_the_sparse_factorisation_on_any_rectangle(height, width, seed):
    background, foreground = scene(rgb=False, shape=(height + 4, width + 4), patch=(height, width))
    problem = poisson.clone_problem(background, foreground, (2, 2))
    exact = poisson.solve(problem, "direct")
    assert np.abs(poisson.solve(problem, "dst") - exact).max() < 1e-12


@pytest.mark.parametrize("size", [197, 198, 199])  # dense sine matrix (198) and FFT paths
def test_dst_on_sizes_with_slow_and_fast_ffts(size):
    background, foreground = scene(rgb=True, shape=(size + 6, 12), patch=(size + 2, 7))
    problem = poisson.clone_problem(background, foreground, (3, 2))
    dst = poisson.solve(problem, "dst")
    assert problem.residual(dst) < 1e-12
    assert np.abs(dst - poisson.solve(problem, "direct")).max() < 1e-12


# --- properties of the solution ---------------------------------------------------


@pytest.mark.parametrize("mask", [None, "blob"])
def test_a_flat_foreground_gives_the_harmonic_fill_of_the_background(mask):
    background, foreground = scene()
    patch = foreground.shape[:2]
    mask = mask_for(patch) if mask else None
    flat = np.full_like(foreground, 0.3)
    offset = (6, 6)
    cloned = poisson.seamless_clone(background, flat, offset, mask=mask, clip=False)
    region = region_in_background(
        background.shape, offset, interior(patch) if mask is None else mask
    )
    # Harmonic: each region pixel is the mean of its four neighbours.
    mean = (
        np.roll(cloned, 1, 0)
        + np.roll(cloned, -1, 0)
        + np.roll(cloned, 1, 1)
        + np.roll(cloned, -1, 1)
    ) / 4
    assert np.abs(cloned - mean)[region].max() < 1e-12
    assert np.abs(cloned - poisson.inpaint(background, region)).max() < 1e-12


@pytest.mark.parametrize("guidance", ["plain", "mixed"])
@pytest.mark.parametrize("mask", [None, "blob"])
def test_adding_a_constant_to_the_foreground_changes_nothing(guidance, mask):
    background, foreground = scene()
    mask = mask_for(foreground.shape[:2]) if mask else None
    darker = poisson.seamless_clone(background, foreground * 0.5, (5, 5), mask, guidance=guidance)
    lighter = poisson.seamless_clone(
        background, foreground * 0.5 + 0.375, (5, 5), mask, guidance=guidance
    )
    assert np.abs(darker - lighter).max() < 1e-12


def test_mixed_guidance_keeps_the_background_where_the_foreground_is_flat():
    background, _ = scene()
    flat = np.full((11, 14, 3), 0.9)
    cloned = poisson.seamless_clone(background, flat, (5, 5), guidance="mixed", clip=False)
    assert np.abs(cloned - background).max() < 1e-12


def test_mixed_guidance_takes_the_larger_difference_on_each_edge():
    background = np.zeros((5, 5))
    background[:, 3:] = 0.25  # a background step of 0.25 between columns 2 and 3
    foreground = np.zeros((3, 3))
    foreground[:, 2] = 0.125  # a smaller foreground step at the same place
    problem = poisson.clone_problem(background, foreground, (1, 1), guidance="mixed")
    # The one unknown, (2, 2), sees the background's step to its right: b = 0 - 0.25.
    assert problem.source[1, 1] == -0.25
    plain = poisson.clone_problem(background, foreground, (1, 1))
    assert plain.source[1, 1] == -0.125


def test_clipping_only_clips():
    background, foreground = scene()
    foreground = foreground * 0 + 0.5
    foreground[5, 7] = 1.0  # a spike that overshoots
    background = background * 0 + 0.99
    raw = poisson.seamless_clone(background, foreground, (5, 5), clip=False)
    clipped = poisson.seamless_clone(background, foreground, (5, 5))
    assert raw.max() > 1
    # Two solves: the load may give them different BLAS thread counts (course.poisson._threads),
    # which may change the last bits, so compare to rounding (1e-12; see test__threads).
    np.testing.assert_allclose(clipped, np.clip(raw, 0, 1), rtol=0, atol=1e-12)


@pytest.mark.parametrize("rgb", [True, False])
def test_the_problem_and_the_paste_take_the_masked_pixels_of_every_channel(rgb):
    # The masked copies go a channel at a time (course.poisson._build): check them against
    # np.where with the mask broadcast over the channels, on a Fortran-ordered background.
    background, foreground = scene(rgb)
    background = np.asfortranarray(background)
    mask = mask_for(foreground.shape[:2])
    problem = poisson.clone_problem(background, foreground, (5, 4), mask=mask)
    x, y = problem.corner
    height, width = problem.region.shape
    window = (slice(y, y + height), slice(x, x + width))
    crop = (slice(y - 4, y - 4 + height), slice(x - 5, x - 5 + width))
    selected = problem.region if not rgb else problem.region[..., None]
    assert np.array_equal(problem.values, np.where(selected, foreground[crop], background[window]))
    solution = np.random.default_rng(2).random(problem.values.shape)
    expected = background.copy()
    expected[window] = np.where(selected, solution, background[window])
    assert np.array_equal(problem.paste(background, solution), expected)


def test_inputs_are_not_modified():
    background, foreground = scene()
    mask = mask_for(foreground.shape[:2])
    copies = background.copy(), foreground.copy(), mask.copy()
    for method in ("auto", "direct", "capacitance", "jacobi", "sor"):
        poisson.seamless_clone(background, foreground, (5, 5), mask=mask, method=method)
    poisson.inpaint(background, region_in_background(background.shape, (5, 5), mask))
    for before, after in zip(copies, (background, foreground, mask), strict=True):
        assert np.array_equal(before, after)


def test_inpaint_fills_a_scratch_with_the_laplace_solution():
    image = scipy.ndimage.gaussian_filter(np.random.default_rng(3).random((20, 30, 3)), 1)
    hole = np.zeros((20, 30), bool)
    hole[10, 3:27] = True
    hole[4:16, 15] = True
    filled = poisson.inpaint(image, hole)
    assert np.abs(laplacian(filled))[hole].max() < 1e-12
    assert np.array_equal(filled[~hole], image[~hole])
    # Maximum principle: a harmonic fill stays within its boundary's range.
    assert filled[hole].min() >= image[~hole].min() and filled[hole].max() <= image[~hole].max()


@pytest.mark.parametrize("method", ["jacobi", "gauss_seidel", "sor"])
def test_inpainting_iterations_reach_the_direct_fill(method):
    image = scipy.ndimage.gaussian_filter(np.random.default_rng(6).random((18, 22)), 1)
    hole = np.zeros((18, 22), bool)
    hole[4:14, 6] = True
    hole[9, 3:19] = True
    exact = poisson.inpaint(image, hole)
    iterative = poisson.inpaint(image, hole, method=method, iterations=5000, tolerance=1e-13)
    assert np.abs(iterative - exact).max() < 1e-11


# --- the iterations -----------------------------------------------------------------


@pytest.mark.parametrize("method", ["jacobi", "gauss_seidel", "sor"])
@pytest.mark.parametrize("mask", [None, "blob"])
def test_every_method_agrees_once_converged(method, mask):
    background, foreground = scene()
    mask = mask_for(foreground.shape[:2]) if mask else None
    exact = poisson.seamless_clone(background, foreground, (5, 5), mask, method="direct")
    iterative = poisson.seamless_clone(
        background, foreground, (5, 5), mask, method=method, iterations=20_000, tolerance=1e-12
    )
    # Error <= residual / smallest eigenvalue (> 0.1 for these regions): tiny.
    assert np.abs(iterative - exact).max() < 1e-10


def small_problem(rgb=True, mask=None):
    background, foreground = scene(rgb, shape=(10, 11), patch=(7, 8), seed=5)
    return poisson.clone_problem(background, foreground, (2, 1), mask=mask)


@pytest.mark.parametrize("mask", [None, "blob"])
def test_jacobi_loop_and_vectorised_jacobi_are_identical(mask):
    problem = small_problem(mask=mask_for((7, 8), seed=2) if mask else None)
    values, region, source = problem.planes()
    fast = solvers.jacobi_sweeps(values, region, source)
    slow = solvers.jacobi_sweeps(values, region, source, method="loop")
    for _ in range(6):
        assert np.array_equal(next(fast), next(slow))


@pytest.mark.parametrize("omega", [1.0, 1.5])
@pytest.mark.parametrize("mask", [None, "blob"])
def test_sor_loop_and_triangular_solve_sor_agree(omega, mask):
    problem = small_problem(mask=mask_for((7, 8), seed=2) if mask else None)
    values, region, source = problem.planes()
    fast_sweeps = solvers.sor_sweeps(values, region, source, omega)
    slow_sweeps = solvers.sor_sweeps(values, region, source, omega, method="loop")
    for _ in range(5):
        fast, slow = next(fast_sweeps), next(slow_sweeps)
        assert np.abs(fast - slow).max() < 1e-14
    assert not np.array_equal(fast, values)


@pytest.mark.parametrize("rgb", [False, True])
def test_the_lab_skeleton_is_gauss_seidel_on_the_correction(rgb):
    background, foreground = scene(rgb, shape=(12, 13), patch=(8, 9), seed=7)
    lab = poisson.lab_clone(background, foreground, (3, 2), iterations=7)
    ours = poisson.seamless_clone(
        background, foreground, (3, 2), method="gauss_seidel", iterations=7, clip=False
    )
    jacobi = poisson.seamless_clone(
        background, foreground, (3, 2), method="jacobi", iterations=7, clip=False
    )
    assert np.abs(lab - ours).max() < 1e-14
    assert np.abs(lab - jacobi).max() > 1e-3  # the comment says Jacobi; it is not


def test_correction_boundary_is_background_minus_foreground_on_the_ring():
    background, foreground = scene(shape=(12, 13), patch=(5, 6))
    g = poisson.correction_boundary(background, foreground, (4, 3))
    window = background[3:8, 4:10]
    ring = ~interior((5, 6))
    assert np.array_equal(g[ring], window[ring] - foreground[ring])
    assert not g[~ring].any()


def test_the_jacobi_rate_predicts_the_slowest_decay():
    background, foreground = scene(rgb=False, shape=(16, 24), patch=(12, 20))
    problem = poisson.clone_problem(background, foreground, (2, 2))
    history = poisson.convergence(problem, "jacobi", 600, every=100)
    measured = (history.residuals[-1] / history.residuals[-2]) ** (1 / 100)
    assert measured == pytest.approx(solvers.jacobi_rate((10, 18)), abs=1e-6)


def test_sweeps_to_residual_is_the_first_sweep_below_the_tolerance():
    problem = small_problem()
    for method in ("jacobi", "gauss_seidel", "sor"):
        count = poisson.sweeps_to_residual(problem, method, 1e-9)
        history = poisson.convergence(problem, method, count)
        assert history.residuals[-1] <= 1e-9 < history.residuals[-2]
    assert poisson.sweeps_to_residual(problem, "jacobi", 1e-9, max_iterations=3) is None


def test_gauss_seidel_takes_half_the_sweeps_of_jacobi_and_sor_far_fewer():
    background, foreground = scene(rgb=False, shape=(40, 50), patch=(34, 44))
    problem = poisson.clone_problem(background, foreground, (3, 3))
    jacobi, gauss_seidel, sor = (
        poisson.sweeps_to_residual(problem, m, 1e-8) for m in ("jacobi", "gauss_seidel", "sor")
    )
    assert gauss_seidel == pytest.approx(jacobi / 2, rel=0.05)
    assert sor < gauss_seidel / 8
    for omega in (1.5, 1.95):  # the optimal factor beats its neighbours
        assert poisson.sweeps_to_residual(problem, "sor", 1e-8, omega=omega) > sor


def test_convergence_records_error_against_the_exact_solution():
    problem = small_problem()
    exact = poisson.solve(problem)
    history = poisson.convergence(problem, "sor", 40, exact=exact, every=10)
    assert list(history.sweeps) == [0, 10, 20, 30, 40]
    assert np.all(np.diff(history.errors) < 0)
    start = np.abs(problem.values - exact)[problem.region].max()
    assert history.errors[0] == start


# --- scenes for the lesson --------------------------------------------------------


def test_the_lesson_images_are_deterministic_images():
    for make in (images.lake, images.plane, images.plane_mask):
        first, second = make(), make()
        assert np.array_equal(first, second)
    scratched, mask = images.scratched_photograph()
    again, _ = images.scratched_photograph()
    assert np.array_equal(scratched, again)
    assert np.array_equal(scratched[~mask], images.photograph()[~mask])
    for image in (images.lake(), images.plane(), scratched):
        assert image.min() >= 0 and image.max() <= 1


def test_a_naive_paste_shows_a_seam_that_seamless_cloning_removes():
    background, foreground = images.lake(), images.plane()
    problem = poisson.clone_problem(background, foreground, (500, 300))
    naive = poisson.naive_paste(background, foreground, (500, 300))
    cloned = poisson.seamless_clone(background, foreground, (500, 300))
    texture = problem.seam(background)
    assert problem.seam(naive) > 5 * texture
    assert problem.seam(cloned) < 2 * texture


# --- bad input ----------------------------------------------------------------------


BACKGROUND, FOREGROUND = scene(shape=(20, 20), patch=(6, 6))


@pytest.mark.parametrize(
    ("call", "error", "words"),
    [
        (lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (15, 0)), ValueError, "offset"),
        (lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (-1, 0)), ValueError, "columns -1"),
        (lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 17)), ValueError, "rows 17"),
        (lambda: poisson.seamless_clone(FOREGROUND, BACKGROUND, (0, 0)), ValueError, "fit inside"),
        (lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (1.5, 0)), TypeError, "offset[0]"),
        (lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, 3), ValueError, "offset"),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND[..., 0], (0, 0)),
            ValueError,
            "foreground is gray",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, (FOREGROUND * 255).astype(np.uint8), (0, 0)),
            TypeError,
            "foreground has dtype uint8",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND * np.nan, (0, 0)),
            ValueError,
            "foreground must be finite",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND * np.inf, FOREGROUND, (0, 0)),
            ValueError,
            "background must be finite",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), np.zeros((6, 6), bool)),
            ValueError,
            "mask is empty",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), np.ones((5, 5), bool)),
            ValueError,
            "mask must have shape (6, 6)",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), np.ones((6, 6), bool)),
            ValueError,
            "outer ring",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), np.full((6, 6), 0.5)),
            ValueError,
            "mask must be boolean",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND[:2], (0, 0)),
            ValueError,
            "at least 3 x 3",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), mask_for((6, 6)), "dst"),
            ValueError,
            "method='dst' needs a rectangular region",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), method="fft"),
            ValueError,
            "method must be one of",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), guidance="max"),
            ValueError,
            "guidance must be one of",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), iterations=10),
            ValueError,
            "iterations applies to the iterative methods",
        ),
        (
            lambda: poisson.seamless_clone(BACKGROUND, FOREGROUND, (0, 0), method="sor", omega=2.0),
            ValueError,
            "omega must lie in (0, 2)",
        ),
        (
            lambda: poisson.seamless_clone(
                BACKGROUND, FOREGROUND, (0, 0), method="jacobi", omega=1.5
            ),
            ValueError,
            "omega applies only to method='sor'",
        ),
        (
            lambda: poisson.seamless_clone(
                BACKGROUND, FOREGROUND, (0, 0), method="jacobi", iterations=-1
            ),
            ValueError,
            "iterations must be >= 0",
        ),
        (
            lambda: poisson.inpaint(BACKGROUND, np.eye(20, dtype=bool)),
            ValueError,
            "mask touches the image border",
        ),
        (
            lambda: poisson.inpaint(BACKGROUND, np.zeros((20, 20), bool)),
            ValueError,
            "mask is empty",
        ),
        (
            lambda: poisson.inpaint(BACKGROUND, np.zeros((20, 19), bool)),
            ValueError,
            "the image's (H, W)",
        ),
        (
            lambda: poisson.inpaint(BACKGROUND, np.where(np.eye(20), np.nan, 0)),
            ValueError,
            "mask must be finite",
        ),
    ],
)
def test_bad_input_is_rejected_with_a_message_naming_the_parameter(call, error, words):
    with pytest.raises(error) as raised:
        call()
    assert words in str(raised.value)


@pytest.mark.parametrize(
    ("value", "words"),
    [
        (np.nan, "background must be finite; got nan at index (3, 4, 1)"),
        (np.inf, "background must be finite; got inf at index (3, 4, 1)"),
        (-np.inf, "background must be finite; got -inf at index (3, 4, 1)"),
        (1.5, "background values must lie in [0, 1]; got values from 0 to 1.5"),
        (-0.25, "background values must lie in [0, 1]; got values from -0.25 to 1"),
    ],
)
def test_one_bad_pixel_of_a_float64_image_is_found_without_a_copy(value, words):
    # Float64 images are checked where they lie (min and max); one bad value
    # among good ones still gets the general check's message.
    background = BACKGROUND.copy()
    background[0, 0] = 0.0
    background[-1, -1] = 1.0
    background[3, 4, 1] = value
    with pytest.raises(ValueError) as raised:
        poisson.seamless_clone(background, FOREGROUND, (0, 0))
    assert words in str(raised.value)


def test_the_result_is_a_new_image_for_any_input_kind():
    for kind in (np.float64, np.float32):
        background, foreground = BACKGROUND.astype(kind), FOREGROUND.astype(kind)
        result = poisson.seamless_clone(background, foreground, (2, 3))
        assert result.dtype == np.float64
        assert not np.shares_memory(result, background)
        assert np.array_equal(result[:3], background[:3].astype(float))  # above the patch
    listed = poisson.seamless_clone(BACKGROUND.tolist(), FOREGROUND.tolist(), (2, 3))
    arrays = poisson.seamless_clone(BACKGROUND, FOREGROUND, (2, 3))
    np.testing.assert_allclose(listed, arrays, rtol=0, atol=1e-12)  # two solves: to rounding


# --- the exercise -------------------------------------------------------------------


def test_the_history_ends_with_the_iterate_solve_returns():
    problem = small_problem()
    history = poisson.convergence(problem, "gauss_seidel", 12, every=5)
    assert list(history.sweeps) == [0, 5, 10, 12]
    solved = poisson.solve(problem, "gauss_seidel", iterations=12)
    assert np.abs(history.solution - solved).max() < 1e-15


# --- the window helpers of course.poisson.problem: public, so checked ---------------------


@given(
    x=st.integers(-6, 10),
    y=st.integers(-6, 10),
    height=st.integers(1, 8),
    width=st.integers(1, 8),
)
def test_window_at_clips_a_window_off_the_image_and_never_wraps(x, y, height, width):
    from course.poisson.windows import window_at

    image = np.arange(48.0).reshape(6, 8)
    window = window_at(image, (x, y), (height, width))
    rows = [r for r in range(y, y + height) if 0 <= r < 6]
    columns = [c for c in range(x, x + width) if 0 <= c < 8]
    expected = image[np.ix_(rows, columns)] if rows and columns else np.zeros((0, 0))
    assert window.size == expected.size
    if expected.size:
        np.testing.assert_array_equal(window, expected)


def test_window_at_with_a_negative_corner_keeps_the_part_on_the_image():
    from course.poisson.windows import window_at

    assert window_at(np.zeros((8, 8)), (-1, -1), (3, 3)).shape == (2, 2)
    assert window_at(np.ones((8, 8)), (-2, 1), (3, 4)).shape == (3, 2)


@pytest.mark.parametrize(
    ("shape", "said"),
    [
        ((0, 0), "non-empty"),
        ((0, 5), "non-empty"),
        ((8, 8, 0), "non-empty"),
        ((1, 8, 8), r"at most 4 channels \(its last axis\); got shape \(1, 8, 8\): an extra axis"),
        ((1, 8, 8, 3), "non-empty"),
    ],
)
def test_window_at_refuses_an_empty_image_or_an_extra_axis_by_name(shape, said):
    from course.poisson.windows import window_at

    with pytest.raises(ValueError, match=f"^image must .*{said}"):
        window_at(np.zeros(shape), (1, 1), (3, 3))
    assert window_at(np.zeros((8, 8, 4)), (1, 1), (3, 3)).shape == (3, 3, 4)  # RGBA


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_the_window_helpers_reject_non_finite_pixels(bad):
    from course.poisson.problem import clone_problem, paste_window
    from course.poisson.windows import image_of, planes_of, window_at, window_in

    image = np.zeros((6, 6))
    image[1, 1] = bad
    problem = clone_problem(np.zeros((6, 6)), np.zeros((3, 3)), (0, 0))
    with pytest.raises(ValueError, match="image must be finite"):
        planes_of(image)
    with pytest.raises(ValueError, match="planes must be finite"):
        image_of(image[None], np.zeros((6, 6)))
    with pytest.raises(ValueError, match="image must be finite"):
        paste_window(problem, image, np.zeros((3, 3)))
    with pytest.raises(ValueError, match="window must be finite"):
        paste_window(problem, np.zeros((6, 6)), image[:3, :3])
    with pytest.raises(ValueError, match="image must be finite"):
        window_in(problem, image, (0, 0))
    with pytest.raises(ValueError, match="image must be finite"):
        window_at(image, (0, 0), (3, 3))
    for method in (problem.seam, problem.texture):
        with pytest.raises(ValueError, match="image must be finite"):
            method(image)
    with pytest.raises(ValueError, match="image must be finite"):
        problem.paste(image, np.zeros((3, 3)))


def test_the_window_helpers_name_what_is_wrong():
    from course.poisson.problem import build_clone_problem, clone_problem, paste_window
    from course.poisson.windows import image_of, planes_of, window_in

    problem = clone_problem(np.zeros((6, 6)), np.zeros((4, 4)), (1, 1))
    with pytest.raises(TypeError, match="problem must be a PoissonProblem"):
        paste_window(None, np.zeros((6, 6)), np.zeros((4, 4)))
    with pytest.raises(TypeError, match="problem must be a PoissonProblem"):
        window_in(None, np.zeros((4, 4)), (1, 1))
    with pytest.raises(ValueError, match="does not hold the problem's window"):
        window_in(problem, np.zeros((4, 4)), (2, 2))
    with pytest.raises(TypeError, match="like must be"):
        image_of(np.zeros((1, 2, 2)), None)
    with pytest.raises(ValueError, match=r"planes must have shape \(3, 2, 2\)"):
        image_of(np.zeros((1, 2, 2)), np.zeros((2, 2, 3)))
    with pytest.raises(TypeError, match="image must hold real numbers"):
        planes_of(None)
    with pytest.raises(TypeError, match="foreground"):
        build_clone_problem(np.zeros((6, 6)), None, (1, 1), None, "plain")
    for method in (problem.seam, problem.texture):
        with pytest.raises(ValueError, match="must hold the problem's window"):
            method(np.zeros((2, 2)))


def test_the_checked_helpers_give_what_the_solvers_use():
    from course.poisson.problem import build_clone_problem, clone_problem, paste_window
    from course.poisson.windows import image_of, planes_of, window_in

    rng = np.random.default_rng(5)
    background, foreground = rng.uniform(0, 1, (9, 10, 3)), rng.uniform(0, 1, (5, 6, 3))
    problem = clone_problem(background, foreground, (3, 2))
    built = build_clone_problem(background, foreground, (3, 2), None, "plain")
    for field in ("values", "region", "source"):
        np.testing.assert_array_equal(getattr(built, field), getattr(problem, field))
    planes = planes_of(problem.values)
    np.testing.assert_array_equal(planes[1], problem.values[..., 1])
    np.testing.assert_array_equal(image_of(planes, problem.values), problem.values)
    window = window_in(problem, foreground, (3, 2))
    np.testing.assert_array_equal(window, foreground)
    pasted = paste_window(problem, background, window)
    np.testing.assert_array_equal(pasted[3:6, 4:8], foreground[1:-1, 1:-1])
    np.testing.assert_array_equal(pasted, problem.paste(background, window))


def test_lesson_08_quotes_the_sweep_of_lab_clone_as_it_is():
    """Going further shows lab_clone's loop as a code block: it must stay the code's own."""
    notebook = Path(__file__).resolve().parent.parent / "notebooks" / "08_poisson.ipynb"
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    quoted = next(
        "".join(cell["source"]).split("```python\n")[1].split("```")[0]
        for cell in cells
        if cell["cell_type"] == "markdown" and "```python" in "".join(cell["source"])
    )
    source = inspect.getsource(poisson.lab_clone)
    lines = [line.strip() for line in quoted.strip().splitlines()]
    code = [line.strip() for line in source.splitlines()]
    start = code.index(lines[0])
    assert code[start : start + len(lines)] == lines
