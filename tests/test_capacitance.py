"""course.poisson.capacitance: box solves against the box's matrix, the method against "direct"."""

import numpy as np
import pytest
import scipy.ndimage
import scipy.sparse
import scipy.sparse.linalg
from hypothesis import given
from hypothesis import strategies as st
from test_poisson import assert_solves_poisson_with_background_boundary, scene

from course import images, poisson
from course.poisson import capacitance, solvers
from course.poisson.sine_transform import largest_prime_factor


def box_matrix(height, width):
    """The five-point operator 4 u_p - sum_q u_q on a height x width box, zero around it."""
    second = lambda size: scipy.sparse.diags_array(  # noqa: E731
        [-np.ones(size - 1), 2 * np.ones(size), -np.ones(size - 1)], offsets=[-1, 0, 1]
    )
    return (
        scipy.sparse.kron(second(height), scipy.sparse.eye_array(width))
        + scipy.sparse.kron(scipy.sparse.eye_array(height), second(width))
    ).tocsc()


# --- the pieces against the box's matrix --------------------------------------------


@pytest.mark.parametrize(
    "shape",
    [(1, 1), (1, 5), (2, 3), (5, 4), (7, 9), (600, 2), (2, 600), (300, 3)],
)
def test_box_green_is_the_inverse_of_the_box_matrix(shape):
    # 300 and 600 rows span two and three blocks of BLOCK_ROWS (256), whose
    # exponentials are factored around different centres.
    inverse = np.linalg.inv(box_matrix(*shape).toarray())
    rows, columns = np.divmod(np.arange(shape[0] * shape[1]), shape[1])
    order = np.random.default_rng(0).permutation(rows.size)  # any order of the pixels
    green = capacitance.box_green(rows[order], columns[order], shape)
    assert np.isfinite(green).all()
    assert np.abs(green - inverse[np.ix_(order, order)]).max() < 1e-13 * np.abs(inverse).max()


@pytest.mark.parametrize("shape", [(30, 20), (20, 30), (300, 3), (3, 300)])
def test_green_upper_is_the_upper_triangle_for_pixels_sorted_along_the_long_side(shape):
    # 600 and 900 pixels: several runs of RUN_PIXELS; 300 rows: two bands of BLOCK_ROWS.
    inverse = np.linalg.inv(box_matrix(*shape).toarray())
    rows, columns = np.divmod(np.arange(shape[0] * shape[1]), shape[1])
    shuffled = np.random.default_rng(5).permutation(rows.size)
    order = shuffled[capacitance.sorted_along_long_side(rows[shuffled], columns[shuffled], shape)]
    long_side = rows if shape[0] >= shape[1] else columns
    assert (np.diff(long_side[order]) >= 0).all()
    upper = np.triu(capacitance.green_upper(rows[order], columns[order], shape))
    assert np.isfinite(upper).all()
    expected = np.triu(inverse[np.ix_(order, order)])
    assert np.abs(upper - expected).max() < 1e-13 * np.abs(inverse).max()


@pytest.mark.parametrize("shape", [(1, 1), (4, 6), (31, 17), (161, 191)])
def test_box_solve_solves_the_box_equation(shape):
    rhs = np.random.default_rng(1).random((2, *shape))
    solution = capacitance.box_solve(rhs)
    matrix = box_matrix(*shape)
    flat = solution.reshape(2, -1).T
    # Rounding: the solution is up to 1e3 here, the matrix's condition number 1e4.
    assert np.abs(matrix @ flat - rhs.reshape(2, -1).T).max() < 1e-14 * np.abs(flat).max()
    expected = scipy.sparse.linalg.spsolve(matrix, rhs.reshape(2, -1).T)
    assert np.abs(flat - expected).max() < 1e-12 * np.abs(expected).max()


def test_charge_pixels_are_the_outside_neighbours_of_the_region():
    inside = np.random.default_rng(2).random((12, 15)) < 0.3
    cross = scipy.ndimage.generate_binary_structure(2, 1)
    expected = scipy.ndimage.binary_dilation(inside, cross) & ~inside
    rows, columns = capacitance.charge_pixels(inside)
    found = np.zeros_like(inside)
    found[rows, columns] = True
    assert np.array_equal(found, expected)


def test_the_box_has_fast_sizes_and_holds_the_region():
    for height, width in [(3, 3), (160, 190), (198, 198), (1000, 7)]:
        box = capacitance.box_shape((height, width))
        assert box[0] >= height and box[1] >= width
        # n + 1 has no prime factor above 11, so the sine transforms are FFTs.
        assert all(largest_prime_factor(side + 1) <= 11 for side in box)


# --- the method against the sparse factorisation, on many shapes ---------------------


def shapes(patch=(40, 48)):
    """Masks inside a patch's outer ring, named for what they test."""
    rows, columns = np.indices(patch)
    centre_y, centre_x = (patch[0] - 1) / 2, (patch[1] - 1) / 2
    radius = np.hypot(
        (rows - centre_y) / (patch[0] / 2 - 1), (columns - centre_x) / (patch[1] / 2 - 1)
    )
    ellipse = radius < 1
    ring = ellipse & (radius > 0.85)  # two or three pixels wide
    crescent = ellipse & (np.hypot(rows - centre_y, columns - centre_x - 12) > 14)
    plus = np.zeros(patch, bool)  # reaches the ring on all four sides
    plus[1:-1, 18:28] = True
    plus[15:25, 1:-1] = True
    bitten = np.zeros(patch, bool)  # the whole interior but a notch: nearly a rectangle
    bitten[1:-1, 1:-1] = True
    bitten[1:8, 20:26] = False
    islands = (np.hypot(rows - 10, columns - 10) < 6) | (np.hypot(rows - 28, columns - 35) < 8)
    single = np.zeros(patch, bool)
    single[patch[0] // 2, 3] = True
    blob = scipy.ndimage.gaussian_filter(np.random.default_rng(3).random(patch), 2) > 0.5
    blob[[0, -1], :] = False
    blob[:, [0, -1]] = False
    return {
        "ellipse": ellipse,
        "thin ring": ring,
        "crescent": crescent,
        "plus touching the ring": plus,
        "bitten rectangle": bitten,
        "two islands": islands,
        "single pixel": single,
        "blob with holes": blob,
    }


@pytest.mark.parametrize("rgb", [False, True])
@pytest.mark.parametrize("name", list(shapes()))
def test_capacitance_solves_the_equation_and_agrees_with_direct(name, rgb):
    mask = shapes()[name]
    background, foreground = scene(rgb, shape=(50, 60), patch=mask.shape)
    offset = (7, 4)
    result = poisson.seamless_clone(background, foreground, offset, mask, "capacitance", clip=False)
    assert_solves_poisson_with_background_boundary(result, background, foreground, offset, mask)
    direct = poisson.seamless_clone(background, foreground, offset, mask, "direct", clip=False)
    assert np.abs(result - direct).max() < 1e-10


@pytest.mark.parametrize("name", ["ellipse", "thin ring", "plus touching the ring"])
def test_capacitance_agrees_with_direct_for_mixed_guidance_and_inpainting(name):
    mask = shapes()[name]
    background, foreground = scene(shape=(50, 60), patch=mask.shape)
    offset = (7, 4)
    clones = [
        poisson.seamless_clone(background, foreground, offset, mask, method, "mixed")
        for method in ("capacitance", "direct")
    ]
    assert np.abs(clones[0] - clones[1]).max() < 1e-10
    hole = np.zeros(background.shape[:2], bool)
    hole[4 : 4 + mask.shape[0], 7 : 7 + mask.shape[1]] = mask
    fills = [poisson.inpaint(background, hole, method) for method in ("capacitance", "direct")]
    assert np.abs(fills[0] - fills[1]).max() < 1e-10


@given(
    height=st.integers(3, 18),
    width=st.integers(3, 18),
    density=st.floats(0.05, 1.0),
    seed=st.integers(0, 2**16),
)
def test_capacitance_equals_direct_on_random_masks(height, width, density, seed):
    rng = np.random.default_rng(seed)
    region = np.zeros((height, width), bool)
    region[1:-1, 1:-1] = rng.random((height - 2, width - 2)) < density
    region[height // 2, width // 2] = True
    values = rng.random((2, height, width))
    source = (rng.random((2, height, width)) - 0.5) * region
    exact = solvers.solve_direct(values, region, source)
    solution = capacitance.solve_capacitance(values, region, source)
    assert np.array_equal(solution[:, ~region], values[:, ~region])
    assert solvers.residual(solution, region, source) < 1e-12
    assert np.abs(solution - exact).max() < 1e-10


def test_a_long_region_spanning_many_blocks_of_rows():
    # 2000 rows: the Green's function is built in 8 blocks, far-apart ones underflow to 0.
    region = np.zeros((2000, 6), bool)
    region[1:-1, 1:-1] = True
    region[700:703, 2:4] = False
    rng = np.random.default_rng(4)
    values = rng.random((1, *region.shape))
    source = (rng.random((1, *region.shape)) - 0.5) * region
    solution = capacitance.solve_capacitance(values, region, source)
    assert solvers.residual(solution, region, source) < 1e-12
    assert np.abs(solution - solvers.solve_direct(values, region, source)).max() < 1e-10


def test_refinement_brings_a_ragged_region_to_rounding_level(monkeypatch):
    rng = np.random.default_rng(3)
    region = rng.random((60, 60)) < 0.3  # speckles: 1824 charges, C less well conditioned
    region[[0, -1], :] = False
    region[:, [0, -1]] = False
    values = rng.random((3, 60, 60))
    source = (rng.random((3, 60, 60)) - 0.5) * region
    refined = solvers.residual(
        capacitance.solve_capacitance(values, region, source), region, source
    )
    monkeypatch.setattr(capacitance, "REFINEMENTS", 0)
    single = solvers.residual(capacitance.solve_capacitance(values, region, source), region, source)
    assert single > 1e-12  # one pass is not at rounding level here...
    assert refined < 1e-14  # ...the refined solution is


# --- the default ----------------------------------------------------------------------


def test_auto_picks_the_faster_exact_method_for_the_shape():
    background, foreground = scene(shape=(50, 60), patch=(40, 48))
    masks = shapes()
    picks = {
        name: poisson.exact_method(poisson.clone_problem(background, foreground, (7, 4), mask))
        for name, mask in [("rectangle", None), *masks.items()]
    }
    assert picks["rectangle"] == "dst"
    assert picks["ellipse"] == "capacitance"  # short border for its area
    assert picks["thin ring"] == "direct"  # all border
    for name in masks:
        cloned = poisson.seamless_clone(background, foreground, (7, 4), masks[name], clip=False)
        direct = poisson.seamless_clone(background, foreground, (7, 4), masks[name], "direct")
        assert np.abs(np.clip(cloned, 0, 1) - direct).max() < 1e-10


def test_the_lesson_images_use_the_faster_method():
    # The plane's silhouette is ragged: "direct" wins there, and auto picks it.
    problem = poisson.clone_problem(images.lake(), images.plane(), (500, 300), images.plane_mask())
    assert poisson.exact_method(problem) == "direct"
    # The benchmark's ellipse in a 200 x 200 patch: capacitance.
    rows, columns = np.indices((200, 200))
    ellipse = ((columns - 99.5) / 95) ** 2 + ((rows - 99.5) / 80) ** 2 < 1
    problem = poisson.clone_problem(np.zeros((210, 210)), np.zeros((200, 200)), (5, 5), ellipse)
    assert poisson.exact_method(problem) == "capacitance"


def test_a_speckled_mask_is_refused_with_a_clear_message():
    background = np.zeros((260, 260))
    speckles = np.zeros((250, 250), bool)
    speckles[1:-1:2, 1:-1:2] = True  # every pixel isolated: 4 charges each
    with pytest.raises(ValueError, match="method='capacitance' needs a dense"):
        poisson.seamless_clone(background, np.ones((250, 250)), (5, 5), speckles, "capacitance")
    cloned = poisson.seamless_clone(background, np.ones((250, 250)), (5, 5), speckles)
    assert np.abs(cloned).max() < 1e-12  # auto: a flat patch in a black frame is black
