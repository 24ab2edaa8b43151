"""course.antialias.curve_quality: each measure against a case whose answer is known."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course.antialias import RENDER_METHODS, SPLATS, render
from course.antialias._reference import _beyond_reach
from course.antialias.coverage import reference
from course.antialias.curve_quality import (
    AGG,
    ARC_LENGTH,
    REFERENCE,
    centroid_offsets,
    intensity_along,
    position_error,
    quality_table,
    uniformity,
    variants,
)
from course.antialias.near_pixels import segment_distance
from course.antialias.windows import render_window
from course.images import SEED_000_CUBIC
from course.raster.canvas import crop

SEED_CURVE = SEED_000_CUBIC / 5
SHAPE = (140, 140)


@pytest.mark.parametrize("width", [1.0, 2.0])
def test_an_exact_stroke_has_its_width_per_unit_length_everywhere(width):
    exact = reference(SEED_CURVE, SHAPE, width, k=32)
    _, density = intensity_along(exact, SEED_CURVE)
    np.testing.assert_allclose(density, width, rtol=0.01)
    assert uniformity(exact, SEED_CURVE) <= 0.005


def test_the_handouts_count_bands_and_the_arc_length_fix_does_not():
    counted = render(SEED_CURVE, SHAPE, "bilinear_centres", step=0.002)
    fixed = render(SEED_CURVE, SHAPE, "bilinear_centres", weighting="arc_length")
    assert uniformity(counted, SEED_CURVE) > 0.1
    assert uniformity(fixed, SEED_CURVE) < 0.01


def test_intensity_along_follows_a_dimmer_stretch():
    # A straight line whose right half is drawn at half intensity.
    line = [[2.0, 4.5], [62.0, 4.5]]
    image = reference(line, (9, 64), 1.0, k=16)
    image[:, 32:] *= 0.5
    positions, density = intensity_along(image, line, piece_length=4)
    np.testing.assert_allclose(density[positions < 28], 1.0, atol=1e-9)
    np.testing.assert_allclose(density[positions > 32], 0.5, atol=1e-9)


def test_uniformity_rejects_an_empty_drawing():
    with pytest.raises(ValueError, match="nothing is drawn"):
        uniformity(np.zeros(SHAPE), SEED_CURVE)


def test_centroid_offsets_see_the_half_pixel_shift_of_corner_splats():
    # A horizontal line: corner-based splats centre it half a pixel low, the
    # centre-based ones on it.
    line = [[3.0, 8.3], [40.0, 8.3]]
    corners = render(line, (16, 44), "bilinear_corners", weighting="arc_length")
    centres = render(line, (16, 44), "bilinear_centres", weighting="arc_length")
    inner = slice(3, -3)  # away from the ends
    np.testing.assert_allclose(centroid_offsets(corners, line).offset[inner], 0.5, atol=1e-6)
    np.testing.assert_allclose(centroid_offsets(centres, line).offset[inner], 0.0, atol=1e-6)


def test_steep_parts_are_measured_along_rows():
    line = [[8.3, 2.0], [8.3, 30.0]]
    image = render(line, (32, 16), "bilinear_corners", weighting="arc_length")
    offsets = centroid_offsets(image, line)
    assert not offsets.along_columns.any()
    np.testing.assert_allclose(offsets.offset[3:-3], 0.5, atol=1e-6)


def test_the_reference_sits_on_the_curve():
    exact = reference(SEED_CURVE, SHAPE, 1.0, k=32)
    assert position_error(exact, SEED_CURVE) <= 0.02
    offsets = centroid_offsets(exact, SEED_CURVE)
    # Every column of the S is crossed once; the steep middle is read by rows.
    assert offsets.along_columns.any() and (~offsets.along_columns).any()
    assert len(offsets.offset) >= 100


def test_variants_and_the_quality_table():
    images = variants(SEED_CURVE, SHAPE)
    assert list(images) == [*RENDER_METHODS, *(m + ARC_LENGTH for m in SPLATS), AGG]
    exact = reference(SEED_CURVE, SHAPE, 1.0, k=32)
    table = {row["name"]: row for row in quality_table(images, SEED_CURVE, exact)}
    # The claims the lesson makes, at this smaller scale.
    assert table["bilinear_zero_offset"]["rmse"] == table["nearest_round"]["rmse"]
    assert table["stroke_area"]["rmse"] < table[AGG]["rmse"]
    assert table["stroke_area"]["cv"] <= 0.05
    assert table["bilinear_centres" + ARC_LENGTH]["cv"] < table["bilinear_centres"]["cv"]


def test_variants_refuses_a_degree_agg_cannot_draw_before_rendering_anything(monkeypatch):
    from course.antialias import curve_quality

    drawn = []
    original = curve_quality.variant_coverage

    def counting(name, *args, **kwargs):
        drawn.append(name)
        return original(name, *args, **kwargs)

    monkeypatch.setattr(curve_quality, "variant_coverage", counting)
    curve = np.column_stack([np.linspace(1, 30, 201), np.full(201, 5.0)])
    with pytest.raises(ValueError, match="degree 1 to 3"):
        curve_quality.variants(curve, (10, 32))
    assert drawn == [curve_quality.AGG]


coordinates = st.floats(0, 120, allow_nan=False)


@settings(max_examples=30, deadline=None)
@given(
    points=st.lists(st.tuples(coordinates, coordinates), min_size=2, max_size=4),
    centre=st.tuples(coordinates, coordinates),
    width=st.sampled_from([0.5, 1.0, 3.0]),
)
def test_a_window_of_the_reference_is_the_crop_of_the_whole_reference(points, centre, width):
    # The window looks only at the segments that pass within reach of it: the same
    # numbers as the whole canvas's reference, cropped.
    window, _extent = render_window(REFERENCE, points, (120, 120), centre, 12, width, k=4)
    whole = reference(points, (120, 120), width, k=4)
    np.testing.assert_array_equal(window, crop(whole, centre, 12)[0])


@settings(max_examples=50, deadline=None)
@given(
    line=st.lists(
        st.tuples(st.floats(-20, 40, allow_nan=False), st.floats(-20, 40, allow_nan=False)),
        min_size=2,
        max_size=12,
    ),
    reach=st.floats(0.8, 3.0),
)
def test_the_reference_skips_only_segments_no_pixel_centre_is_within_reach_of(line, reach):
    line = np.array(line)
    skipped = _beyond_reach(line, None, (12, 20), reach)
    rows, columns = np.mgrid[0:12, 0:20]
    centres_x, centres_y = columns.ravel() + 0.5, rows.ravel() + 0.5
    for index in np.flatnonzero(skipped):
        distance, _along, _across = segment_distance(
            centres_x, centres_y, line[index], line[index + 1]
        )
        assert distance.min() > reach


def test_windows_drawn_together_are_each_window_drawn_alone_in_any_order():
    from course.antialias.windows import render_windows

    names = ["bilinear_centres", "nearest_round", "bilinear_corners + arc length", AGG, REFERENCE]
    names += ["stroke_area", "bilinear_zero_offset", "bilinear_centres"]
    centre = (328.2, 156.9)  # on the curve
    alone = [render_window(name, SEED_000_CUBIC, (700, 700), centre, 12, k=8)[0] for name in names]
    for order in (names, names[::-1]):
        windows, extent = render_windows(order, SEED_000_CUBIC, (700, 700), centre, 12, k=8)
        expected = alone if order is names else alone[::-1]
        assert all(np.array_equal(a, b) for a, b in zip(windows, expected, strict=True))
        assert extent == render_window(AGG, SEED_000_CUBIC, (700, 700), centre, 12)[1]
    assert any(window.any() for window in windows)


@pytest.mark.parametrize(
    "names, error, message",
    [
        ("bilinear_centres", TypeError, "names must be a non-empty list of variant names; got"),
        ([], TypeError, "names must be a non-empty list"),
        (["bilinear_centres", "blur"], ValueError, "names must be one of"),
    ],
)
def test_windows_drawn_together_refuse_names_that_are_not_a_list_of_variants(names, error, message):
    from course.antialias.windows import render_windows

    with pytest.raises(error, match=message):
        render_windows(names, SEED_000_CUBIC, (140, 140), (63.0, 40.0), 12)
