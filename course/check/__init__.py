"""Exercise checkers, one module per lesson: ``check.<exercise>(student_fn)``.

A lesson's notebook imports its own module, ``from course.check import
de_casteljau as check``, so a new lesson adds its module and edits nothing
here. Each checker returns a :class:`~course.check.base.CheckResult`, truthy
when every case passes; otherwise its message names the first failing case,
its inputs, the expected value and the value given.
"""
