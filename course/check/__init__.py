"""The checkers' shared machinery: the base, the sandbox, answers, comparisons, pictures, hints.

Each lesson's checkers live in its chapter (``course/lessons/lNN_topic/check.py``); a
notebook imports them as ``from course.lessons.l01_de_casteljau import check``. Each
checker returns a :class:`~course.check.base.CheckResult`, truthy when every case passes;
otherwise its message names the first failing case, its inputs, the expected value and the
value given.
"""
