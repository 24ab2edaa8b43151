"""Filtering with 3 x 3 kernels: box blur, Sobel edges, general convolution.

Every function takes a gray ``(H, W)`` or RGB ``(H, W, 3)`` float image with
values in [0, 1] (colour is filtered per channel) and returns a new float
array of the same shape.

A 3 x 3 window at the image's edge reaches one pixel past it; the *border
rule* says what is there:

- ``"handout"``: nothing: use only the in-image neighbours and rescale the
  kernel to its in-image weights. For the box blur this is the lab report's
  rule, the mean of the in-image neighbours.
- ``"zero"``: black. The report calls this the standard way; it darkens a
  blurred image's frame.
- ``"replicate"``: the nearest edge pixel (scipy.ndimage ``"nearest"``,
  OpenCV ``BORDER_REPLICATE``).
- ``"reflect"``: the mirror image about the edge pixel (scipy.ndimage
  ``"mirror"``, numpy.pad ``"reflect"``, OpenCV ``BORDER_REFLECT_101``, the
  default of ``cv2.filter2D``). The other mirror convention, which repeats
  the edge pixel, is the same as ``"replicate"`` for a 3 x 3 kernel.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import as_choice, as_image, as_kernel
from course.i18n import _

__all__ = [
    "BLUR_METHODS",
    "BORDERS",
    "BOX",
    "SOBEL_METHODS",
    "SOBEL_X",
    "SOBEL_Y",
    "blur",
    "convolve",
    "sobel",
]

BORDERS = ("handout", "zero", "replicate", "reflect")
BLUR_METHODS = ("shifted_sums", "loop")
SOBEL_METHODS = ("separable", "loop")

#: The box kernel: every neighbour weighs 1/9.
BOX = np.full((3, 3), 1 / 9)
#: Sobel kernels, applied as the handout does, by a dot product with the
#: window (correlation): Gx grows to the right, Gy downwards.
SOBEL_X = np.array([[-1, 0, 1], [-2, 0, 2], [-1, 0, 1]])
SOBEL_Y = SOBEL_X.T

_PAD_MODES = {"zero": "constant", "replicate": "edge", "reflect": "reflect"}


def _neighbour_counts(length: int) -> np.ndarray:
    """How many of the positions i - 1, i, i + 1 lie in 0 .. length - 1."""
    counts = np.full(length, 3.0)
    counts[0] -= 1
    counts[-1] -= 1
    return counts


def _box_sum(image: np.ndarray) -> np.ndarray:
    """Sum of the in-image 3 x 3 neighbours, rows then columns, no padding copy."""
    rows = image.copy()
    rows[:, 1:] += image[:, :-1]
    rows[:, :-1] += image[:, 1:]
    total = rows.copy()
    total[1:] += rows[:-1]
    total[:-1] += rows[1:]
    return total


def blur(image: Any, method: str = "shifted_sums") -> np.ndarray:
    """3 x 3 box blur; at the border, the mean of the in-image neighbours.

    Inside, each pixel becomes the mean of its 3 x 3 neighbourhood, as
    ``scipy.ndimage.uniform_filter(image, 3)``. On the border the window has
    6 (edge) or 4 (corner) pixels in the image, and their mean is taken: the
    lab report's rule, which keeps a flat image flat.

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3), values in [0, 1]
    method : {"shifted_sums", "loop"}
        ``"loop"`` is the handout's form: for each pixel, add up the in-image
        neighbours and count them. ``"shifted_sums"`` adds shifted copies of
        the whole image, along rows then columns, and divides by the counts. The
        two agree to rounding, and exactly when the sums are exact (e.g. for
        multiples of 1/256).

    Examples
    --------
    >>> blur([[0.0, 0.0, 0.0], [0.0, 0.9, 0.0], [0.0, 0.0, 0.0]])
    array([[0.225, 0.15 , 0.225],
           [0.15 , 0.1  , 0.15 ],
           [0.225, 0.15 , 0.225]])
    """
    array = as_image(image, "image")
    method = as_choice(method, "method", BLUR_METHODS)
    if method == "loop":
        return _blur_loop(array)
    return _blur_shifted_sums(array)


def _blur_loop(array: np.ndarray) -> np.ndarray:
    """The handout's loop: each pixel's in-image neighbours, added up and counted."""
    height, width = array.shape[:2]
    output = np.empty_like(array)
    for y in range(height):
        for x in range(width):
            total, count = 0.0, 0
            for dy in (-1, 0, 1):
                for dx in (-1, 0, 1):
                    if 0 <= y + dy < height and 0 <= x + dx < width:
                        total = total + array[y + dy, x + dx]
                        count += 1
            output[y, x] = total / count
    return output


def _blur_shifted_sums(array: np.ndarray) -> np.ndarray:
    """Shifted copies added along rows then columns, divided by the neighbour counts."""
    height, width = array.shape[:2]
    counts = np.outer(_neighbour_counts(height), _neighbour_counts(width))
    if array.ndim == 3:
        counts = counts[:, :, None]
    total = _box_sum(array)
    total /= counts
    return total


def _correlate(array: np.ndarray, weights: np.ndarray, border: str) -> np.ndarray:
    """Sum over the 3 x 3 window of weights[i, j] * pixel, on a padded copy."""
    height, width = array.shape[:2]
    pad = ((1, 1), (1, 1)) + ((0, 0),) * (array.ndim - 2)
    padded = np.pad(array, pad, mode=_PAD_MODES.get(border, "constant"))
    output = np.zeros_like(array)
    for i in range(3):
        for j in range(3):
            if weights[i, j]:
                output += weights[i, j] * padded[i : i + height, j : j + width]
    if border == "handout":
        # Rescale by the in-image share of the weights, as the mean of the
        # in-image neighbours rescales the box by 9 / count.
        inside = _correlate(np.ones((height, width)), weights, "zero")
        if np.any(np.abs(inside) < 1e-12 * np.abs(weights).sum()):
            raise ValueError(
                _(
                    "border='handout' rescales the kernel to its in-image weights, but this "
                    "kernel's weights cancel out on part of the border (sum {total:g}); use "
                    "border='zero', 'replicate' or 'reflect'"
                ).format(total=weights.sum())
            )
        scale = weights.sum() / inside
        output *= scale[:, :, None] if array.ndim == 3 else scale
    return output


def convolve(image: Any, kernel: Any, border: str = "handout") -> np.ndarray:
    """Convolve with a 3 x 3 kernel, with a choice of border rule.

    A true convolution: the kernel is flipped, as in
    ``scipy.ndimage.convolve``, so ``output[y, x] = sum kernel[i, j] *
    image[y + 1 - i, x + 1 - j]``. The handout's dot product of kernel and
    window is a correlation: pass ``kernel[::-1, ::-1]`` to get it. (For the
    box it makes no difference; for Sobel it flips the gradient's sign.)
    A kernel of non-negative weights summing to at most 1 (a weighted mean)
    gives values in [0, 1], and the result is clipped to that range to undo
    rounding; any other kernel's result is returned as computed (a kernel
    with negative weights can leave [0, 1]).

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3), values in [0, 1]
    kernel : array_like, (3, 3)
    border : {"handout", "zero", "replicate", "reflect"}
        See the module docstring. ``"handout"`` needs a kernel whose in-image
        weights never sum to zero (a blur, not a derivative).

    Examples
    --------
    A single 1 right of the centre moves the image one pixel to the right
    (a correlation would move it left):

    >>> image = [[0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]
    >>> convolve(image, [[0, 0, 0], [0, 0, 1], [0, 0, 0]], border="zero")
    array([[0., 0., 0., 0.],
           [0., 0., 0., 1.]])
    >>> np.round(convolve(np.full((2, 3), 0.5), BOX, border="zero"), 3)
    array([[0.222, 0.333, 0.222],
           [0.222, 0.333, 0.222]])
    >>> convolve(np.full((2, 3), 0.5), BOX, border="handout")
    array([[0.5, 0.5, 0.5],
           [0.5, 0.5, 0.5]])
    """
    array = as_image(image, "image")
    weights = as_kernel(kernel)
    border = as_choice(border, "border", BORDERS)
    output = _correlate(array, weights[::-1, ::-1], border)
    if weights.min() >= 0 and weights.sum() <= 1 + 1e-12:
        # A weighted mean stays in [0, 1]; nine roundings of 1/9 can leave it
        # one ulp above 1, which the next filter would reject.
        np.clip(output, 0.0, 1.0, out=output)
    return output


def sobel(image: Any, border: str = "replicate", method: str = "separable") -> np.ndarray:
    """Gradient magnitude ``sqrt(Gx**2 + Gy**2)`` with the Sobel kernels.

    ``Gx`` is the dot product of ``SOBEL_X`` with each 3 x 3 window (the
    handout's form), ``Gy`` that of ``SOBEL_Y``. The result lies in
    [0, sqrt(20)] (about 4.47) for an image in [0, 1]; clip it to [0, 1] to show it as
    the lab does. Inside it equals ``numpy.hypot(scipy.ndimage.sobel(image,
    0), scipy.ndimage.sobel(image, 1))``.

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3), values in [0, 1]
    border : {"replicate", "reflect", "zero"}
        The handout leaves the border open. ``"replicate"`` (the default) and
        ``"reflect"`` keep a flat image at zero gradient; ``"zero"`` makes the
        image's edge an edge. (``"handout"`` does not apply: Sobel's weights
        sum to zero, there is nothing to rescale.)
    method : {"separable", "loop"}
        ``"loop"``: the handout's two dot products per pixel. ``"separable"``:
        the kernels are separable, ``SOBEL_X = [1, 2, 1]^T [-1, 0, 1]``, so each
        is a difference of shifted copies, then a weighted sum of shifted
        copies. Equal to rounding; exactly for multiples of 1/256.

    References
    ----------
    I. Sobel and G. Feldman, "A 3x3 isotropic gradient operator for image
    processing", talk at the Stanford Artificial Intelligence Project, 1968.

    Examples
    --------
    >>> sobel([[0.0, 0.0, 1.0, 1.0]] * 3)
    array([[0., 4., 4., 0.],
           [0., 4., 4., 0.],
           [0., 4., 4., 0.]])
    """
    array = as_image(image, "image")
    border = as_choice(border, "border", ("replicate", "reflect", "zero"))
    method = as_choice(method, "method", SOBEL_METHODS)
    if method == "loop":
        return _sobel_loop(array, border)
    return _sobel_separable(array, border)


def _sobel_separable(array: np.ndarray, border: str) -> np.ndarray:
    """Each kernel as a difference of shifted copies, then a [1, 2, 1] sum of shifted copies."""
    pad = ((1, 1), (1, 1)) + ((0, 0),) * (array.ndim - 2)
    padded = np.pad(array, pad, mode=_PAD_MODES[border])
    across = padded[:, 2:] - padded[:, :-2]  # [-1, 0, 1] along each row
    gx = across[:-2] + across[2:]  # then [1, 2, 1] down each column
    gx += across[1:-1]
    gx += across[1:-1]
    down = padded[2:] - padded[:-2]
    gy = down[:, :-2] + down[:, 2:]
    gy += down[:, 1:-1]
    gy += down[:, 1:-1]
    return np.hypot(gx, gy, out=gx)


def _sobel_loop(array: np.ndarray, border: str) -> np.ndarray:
    height, width = array.shape[:2]
    output = np.empty_like(array)
    for y in range(height):
        for x in range(width):
            gx = gy = 0.0
            for i in range(3):
                for j in range(3):
                    pixel = _border_pixel(array, y + i - 1, x + j - 1, border)
                    gx = gx + SOBEL_X[i, j] * pixel
                    gy = gy + SOBEL_Y[i, j] * pixel
            output[y, x] = np.hypot(gx, gy)
    return output


def _border_pixel(array: np.ndarray, y: int, x: int, border: str) -> Any:
    """The pixel at (x, y), or what the border rule puts there if it is outside."""
    height, width = array.shape[:2]
    if border == "zero" and not (0 <= y < height and 0 <= x < width):
        return 0.0 * array[0, 0]
    if border == "reflect":
        y = -y if y < 0 else 2 * (height - 1) - y if y >= height else y
        x = -x if x < 0 else 2 * (width - 1) - x if x >= width else x
    # replicate, and the mirror of a 1-pixel-wide image
    return array[min(max(y, 0), height - 1), min(max(x, 0), width - 1)]
