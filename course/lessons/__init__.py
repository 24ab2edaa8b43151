"""One module per lesson: ``lNN_topic.py`` beside the notebook ``notebooks/NN_topic.ipynb``.

Each module defines ``LESSON``, a :class:`course.classroom.registry.Lesson`
(the handout task, what the lesson teaches, its key pictures, the slider
moves the browser tests make), and the picture and landmark functions the
entry names. :func:`course.classroom.registry.lessons` finds the modules by
their names; nothing lists them, so a new lesson is new files only
(``CONTRIBUTING.md``).
"""
