"""3 x 3 filter speed against scipy.ndimage; one line per measurement, goal beside it.

    python benchmarks/bench_filters.py

blur and sobel on 1024 x 1024 images, gray and RGB, against
scipy.ndimage.uniform_filter and numpy.hypot of two scipy.ndimage.sobel
calls: goal within 2x. The handout's loop forms are timed on 64 x 64 and
scaled by the pixel count.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

# The same interleaved best-of timer as the dithering benchmark (same folder).
from timing import named_best_times

from course.filters import blur, sobel


def scipy_sobel(image: np.ndarray) -> np.ndarray:
    return np.hypot(
        ndimage.sobel(image, 0, mode="nearest"), ndimage.sobel(image, 1, mode="nearest")
    )


def main() -> None:
    rng = np.random.default_rng(0)
    images = {"gray": rng.random((1024, 1024)), "RGB": rng.random((1024, 1024, 3))}
    for kind, image in images.items():
        size = (3, 3) if image.ndim == 2 else (3, 3, 1)
        times = named_best_times(
            {
                "blur": lambda image=image: blur(image),
                "uniform_filter": lambda image=image, size=size: ndimage.uniform_filter(
                    image, size
                ),
                "sobel": lambda image=image: sobel(image),
                "scipy_sobel": lambda image=image: scipy_sobel(image),
            },
            rounds=7 if kind == "gray" else 3,
        )
        print(
            f"blur 1024x1024 {kind}: {times['blur'] / times['uniform_filter']:.2f}x "
            f"scipy.ndimage.uniform_filter (goal <= 2x)"
        )
        print(
            f"sobel 1024x1024 {kind}: {times['sobel'] / times['scipy_sobel']:.2f}x "
            f"hypot of scipy.ndimage.sobel (goal <= 2x)"
        )

    small = images["gray"][:64, :64]
    scale = images["gray"].size / small.size
    loops = named_best_times(
        {
            "blur": lambda: blur(small, method="loop"),
            "sobel": lambda: sobel(small, method="loop"),
        },
        rounds=2,
    )
    anchors = named_best_times(
        {
            "blur": lambda: ndimage.uniform_filter(images["gray"], 3),
            "sobel": lambda: scipy_sobel(images["gray"]),
        },
        rounds=3,
    )
    for name in ("blur", "sobel"):
        print(
            f"{name} 1024x1024 gray (loop, timed on 64x64 x {scale:.0f}): "
            f"{loops[name] * scale / anchors[name]:.0f}x scipy.ndimage (no goal: the readable form)"
        )


if __name__ == "__main__":
    main()
