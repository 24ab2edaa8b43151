"""Rasterization: from geometry to pixel coordinates.

Rasterizers return pixels, they do not draw: an int array ``(K, 2)`` of
(x, y), optionally clipped to a canvas with ``shape=(H, W)``.
:func:`course.canvas.paint` writes them. Pixel (row r, column c) is the unit
square ``[c, c+1) x [r, r+1)``, with its centre at ``(c + 0.5, r + 0.5)``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import as_choice, as_points, as_shape
from course.canvas import inside

__all__ = ["ROUNDING", "nearest_pixels"]

ROUNDING = ("floor", "round", "trunc")


def nearest_pixels(points: Any, rounding: str = "floor", shape: Any = None) -> np.ndarray:
    """The pixel of each point: one (x, y) per sample, in order, repeats kept.

    Parameters
    ----------
    points : array_like, shape (K, 2)
        Continuous image-space points (x right, y down).
    rounding : {"floor", "round", "trunc"}
        ``"floor"``: the pixel whose square contains the point (this package's
        convention). ``"round"``: the nearest integer, as OpenCV's
        ``cv::Point(Point2f)`` does (seed 000's ``window.at<cv::Vec3b>(point)``),
        which is off by half a pixel when pixel centres are at +0.5.
        ``"trunc"``: toward zero, as C++'s float-to-int conversion in
        ``window.at<cv::Vec3b>(point.y, point.x)`` (seeds 002-004); it equals
        floor on the canvas but folds x in (-1, 0) onto column 0.
    shape : (H, W), optional
        Drop pixels off a canvas of this shape.

    Examples
    --------
    >>> nearest_pixels([[0.4, 0.6], [1.5, 2.5], [-0.5, 1.0]])
    array([[ 0,  0],
           [ 1,  2],
           [-1,  1]])
    >>> nearest_pixels([[0.4, 0.6], [1.5, 2.5], [-0.5, 1.0]], rounding="trunc")
    array([[0, 0],
           [1, 2],
           [0, 1]])
    >>> nearest_pixels([[0.4, 0.6], [1.5, 2.5], [-0.5, 1.0]], shape=(2, 2))
    array([[0, 0]])
    """
    samples = as_points(points)
    if samples.shape[1] != 2:
        raise ValueError(f"points must have shape (K, 2) for image space; got {samples.shape}")
    rounding = as_choice(rounding, "rounding", ROUNDING)
    if rounding == "floor":
        pixels = np.floor(samples)
    elif rounding == "round":
        # cvRound rounds halves to even, like numpy.
        pixels = np.rint(samples)
    else:
        pixels = np.trunc(samples)
    pixels = pixels.astype(np.int64)
    if shape is not None:
        pixels = pixels[inside(pixels, as_shape(shape))]
    return pixels
