"""The checkers' shared machinery: the base, the sandbox, answers, comparisons, pictures, hints.

Each lesson's checkers live in its chapter (``course/lessons/lNN_topic/check.py``); a
notebook imports them as ``from course.lessons.l01_de_casteljau import check``. Each
checker returns a :class:`~course.check.results.CheckResult`, truthy when every case passes;
otherwise its message names the first failing case, its inputs, the expected value and the
value given.

By concept: :mod:`~course.check.base` (``run_cases``: a checker's loop over its cases),
:mod:`~course.check.results` (a result and the handouts' mistakes),
:mod:`~course.check.exercises` (an exercise declared once),
:mod:`~course.check.sandbox` (running the student's code: copies, arity, their line),
:mod:`~course.check.budget` (a case's time and memory budget in the student's kernel),
:mod:`~course.check.views` (the originals of what a student may patch: numpy, math, the
builtins; their warnings as text), :mod:`~course.check.answers`,
:mod:`~course.check.comparisons`, :mod:`~course.check.references` (reading and comparing an
answer, the library's answers refused), :mod:`~course.check.shown` (a value in a report's
line), :mod:`~course.check.hints`,
:mod:`~course.check.pictures`; and for grading, :mod:`~course.check.grading` (cases drawn
per submission) and :mod:`~course.check.outside` (the student's function run in a child
process, under the operating system's limits).
"""
