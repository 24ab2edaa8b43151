"""Lesson 04's figures: the photograph figure's caption in English, its numbers from the run.

The Chinese of every figure is scanned with the rest of the edition
(``tests/test_chinese_review.py``).
"""

import re

from course.lessons.l04_supersampling import figures as sampling_figures


def test_the_photograph_figure_keeps_its_english():
    still = sampling_figures.photograph_figure((1, 2), 2)
    assert re.fullmatch(r"RMS against rate 2: rate 1 [\d.]+, rate 2 0\.0000", still.caption)
