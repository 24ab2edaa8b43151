"""Lesson 04: supersampling 2500 x 2500 to 320 x 320 at rate 12, as the lab does.

The anchor is Pillow's ``Image.resize(..., Image.Resampling.BOX)`` on the
same sizes: one area-weighted average per output pixel in compiled code, on
uint8, which does much less than 144 bilinear samples per pixel in float64.
The per-pixel Python loop (``method="loop"``, the handout's form) is timed
on a 125 x 125 -> 16 x 16 block (the same ratio, the same work per output
pixel) and scaled by the number of output pixels, so this stays quick.
"""

from __future__ import annotations

import numpy as np
from PIL import Image
from timing import best_time

from course.sampling.resample import supersample

SIZE, OUT, RATE = 2500, 320, 12
BLOCK, BLOCK_OUT = 125, 16


def main() -> None:
    rng = np.random.default_rng(5)
    image = rng.random((SIZE, SIZE, 3))
    pillow_image = Image.fromarray((image * 255).astype(np.uint8))
    pillow = best_time(lambda: pillow_image.resize((OUT, OUT), Image.Resampling.BOX))
    ours = best_time(lambda: supersample(image, (OUT, OUT), RATE))
    ratio = ours / pillow
    print(
        f"supersample {SIZE}x{SIZE} RGB -> {OUT}x{OUT}, rate {RATE}: {ratio:.1f}x Pillow "
        f"Image.resize BOX ({pillow * 1e3:.1f} ms; ours {ours * 1e3:.1f} ms) "
        f"(goal <= 10x, {'met' if ratio <= 10 else 'NOT met'})"
    )
    gray = np.ascontiguousarray(image[..., 0])
    pillow_gray = Image.fromarray(gray.astype(np.float32), mode="F")
    pillow = best_time(lambda: pillow_gray.resize((OUT, OUT), Image.Resampling.BOX))
    ours = best_time(lambda: supersample(gray, (OUT, OUT), RATE))
    print(
        f"supersample {SIZE}x{SIZE} gray -> {OUT}x{OUT}, rate {RATE}: {ours / pillow:.1f}x Pillow "
        f"Image.resize BOX on float32 mode F ({pillow * 1e3:.1f} ms) (no goal)"
    )

    block = image[:BLOCK, :BLOCK]
    loop_block = best_time(
        lambda: supersample(block, (BLOCK_OUT, BLOCK_OUT), RATE, method="loop"), rounds=1
    )
    loop = loop_block * (OUT / BLOCK_OUT) ** 2
    fast = best_time(lambda: supersample(image, (OUT, OUT), RATE))
    speedup = loop / fast
    print(
        f"supersample {SIZE}x{SIZE} RGB -> {OUT}x{OUT}, rate {RATE}: {speedup:.0f}x faster than "
        f"the per-pixel Python loop (loop {loop:.0f} s, scaled from {BLOCK}x{BLOCK} -> "
        f"{BLOCK_OUT}x{BLOCK_OUT}) (goal >= 50x, {'met' if speedup >= 50 else 'NOT met'})"
    )


if __name__ == "__main__":
    main()
