"""course.check.views: the checker works with numpy as imported, and hides no warning twice."""

import math
import warnings

import numpy as np

from course.check import views


def test_quiet_hides_warnings_without_making_python_show_a_students_again():
    def students_line():
        return np.float64(1.0) / 0.0  # a RuntimeWarning, shown once per line

    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("default")
        students_line()
        with views.quiet():
            warnings.warn("the checker's own", stacklevel=1)
            np.float64(1.0) / 0.0
        students_line()
        views.CheckersView().__enter__().__exit__(None, None, None)
        students_line()
    assert [str(w.message) for w in shown] == ["divide by zero encountered in scalar divide"]


def test_the_checkers_view_puts_numpy_math_and_builtins_back_and_the_students_after():
    import builtins

    saved = (np.allclose, np.array_equal, math.isclose, builtins.abs)
    np.allclose = lambda *args, **kwargs: True
    math.isclose = lambda *args, **kwargs: True
    builtins.abs = lambda value: 0
    seen = []
    try:
        view = views.CheckersView()
        with view:
            seen.append((np.allclose(0.0, 1.0), math.isclose(0.0, 1.0), abs(-2)))
            with view.students([]):
                seen.append((np.allclose(0.0, 1.0), math.isclose(0.0, 1.0), abs(-2)))
                np.array_equal = lambda *args, **kwargs: True  # patched during the call
            seen.append(np.array_equal([0], [1]))
        seen.append((np.allclose(0.0, 1.0), np.array_equal([0], [1]), abs(-2)))
    finally:
        np.allclose, np.array_equal, math.isclose, builtins.abs = saved
    assert seen == [(False, False, 2), (True, True, 0), False, (True, True, 0)]


def test_a_students_warning_is_kept_as_text_not_printed(capfd):
    kept: list[str] = []
    view = views.CheckersView()
    with view, view.students(kept):
        warnings.warn("look at this", UserWarning, stacklevel=1)
    assert kept and kept[0].startswith("UserWarning: look at this (line ")
    assert capfd.readouterr().err == ""
