"""course: Jupyter lessons for an introductory computer-graphics course.

One module per concept; the notebooks in ``notebooks/`` import them.
"""

__version__ = "0.1.0"
