"""One chapter per lesson: ``lNN_topic/`` beside the notebook ``notebooks/NN_topic.ipynb``.

A chapter holds everything that teaches its lesson: ``lesson.py`` (the registry entry
``LESSON``, a :class:`course.classroom.registry.Lesson`, with the picture, landmark and
printing helpers it names), ``check.py`` (the exercises' checkers), ``apps.py`` (the
interactive apps) and ``figures.py`` (the still pictures). The shared machinery stays
shared: :mod:`course.check` (the checker base and sandbox), :mod:`course.widgets` (the
picture widget and the app base) and :mod:`course.classroom`.
:func:`course.classroom.registry.lessons` finds the chapters by their names; nothing lists
them, so a new lesson is new files only (``CONTRIBUTING.md``).
"""
