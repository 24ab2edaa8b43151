"""Dithering speed against its anchors; one line per measurement, goal beside it.

    python benchmarks/bench_dither.py

- error_diffusion (Floyd-Steinberg) on a 512 x 512 gray photograph against
  Pillow's Image.convert("1") (Floyd-Steinberg in C), goal within 10x on a
  quiet machine and within 10x with two busy processes beside it (both
  timed alike, interleaved: ``timing.py``), with
  the output equal to the handout's loop form, which is timed on 128 x 128
  and scaled by the pixel count (it is linear in it).
- blue_noise_mask(64): goal under 2 s.
"""

from __future__ import annotations

import time

import numpy as np
from PIL import Image
from timing import BUSY_PROCESSES, best_time, best_times, busy_processes, named_best_times

from course.halftone.dither import blue_noise_mask, error_diffusion
from course.images import photograph, to_gray

# Batches of this many seconds under load: both sides then share the cores alike.
LOADED_BATCH_SECONDS = 0.3


def main() -> None:
    gray = to_gray(photograph())[:512, :512]
    # Pillow works on 8-bit pixels; feed both the same levels.
    gray = np.round(gray * 255) / 255
    pillow_input = Image.fromarray(np.round(gray * 255).astype(np.uint8), mode="L")
    small = gray[:128, :128]
    scale = gray.size / small.size

    times = named_best_times(
        {"wavefront": lambda: error_diffusion(gray), "pillow": lambda: pillow_input.convert("1")},
        rounds=21,
    )
    times["rows"] = best_time(lambda: error_diffusion(gray, method="rows"), rounds=3)
    loop_small = best_time(lambda: error_diffusion(small, method="loop"), rounds=3)
    pillow = times["pillow"]

    fast = error_diffusion(gray)
    equal = np.array_equal(fast, error_diffusion(gray, method="loop"))
    agreement = np.mean(fast == (np.asarray(pillow_input.convert("1")) > 0))
    print(
        f"error_diffusion 512x512 (wavefront): {times['wavefront'] / pillow:.1f}x "
        f'Pillow convert("1") (goal <= 10x); output equal to the loop form: '
        f"{'yes' if equal else 'NO'}"
    )
    with busy_processes():
        loaded, loaded_pillow = best_times(
            lambda: error_diffusion(gray),
            lambda: pillow_input.convert("1"),
            rounds=9,
            batch_seconds=LOADED_BATCH_SECONDS,
        )
    print(
        f"error_diffusion 512x512 (wavefront), {BUSY_PROCESSES} busy processes beside it: "
        f'{loaded / loaded_pillow:.1f}x Pillow convert("1") (goal <= 10x) '
        f"({loaded * 1e3:.1f} ms vs {loaded_pillow * 1e3:.2f} ms)"
    )
    print(
        f"error_diffusion 512x512 (rows): {times['rows'] / pillow:.0f}x Pillow "
        f"(no goal: the serpentine default)"
    )
    print(
        f"error_diffusion 512x512 (loop, timed on 128x128 x {scale:.0f}): "
        f"{loop_small * scale / pillow:.0f}x Pillow (no goal: the readable form)"
    )
    print(
        f"  (Pillow's own Floyd-Steinberg, on 8-bit integers, agrees on {agreement:.1%} "
        f"of the pixels; absolute: wavefront {times['wavefront'] * 1e3:.1f} ms, "
        f"Pillow {pillow * 1e3:.2f} ms)"
    )

    start = time.perf_counter()
    blue_noise_mask(64, np.random.default_rng(0))
    elapsed = time.perf_counter() - start  # wall time: what a notebook waits
    print(f"blue_noise_mask(64): {elapsed:.2f} s (goal < 2 s)")


if __name__ == "__main__":
    main()
