"""One name per exercise: the student's function, its checker, its report and its hint key.

The course map tells a student that every exercise ends with ``check.name(name)``: the function
they write is checked by ``check.<name>``, the report opens with ``FAIL <name>:`` and the hint
is ``check.hint("<name>")``. A second name for any of them is one more thing to get wrong.
"""

import importlib
import re

import pytest

from course.check.exercises import Exercise
from course.check.hints import hint
from course.classroom.exercise_list import course_exercises

#: Exercises whose chapters still give them a second name (function=, reported_as= or a report
#: under another name), with the change that gives them one; each chapter's own helper renames
#: it. A renamed exercise passes and, the mark being strict, fails here until it leaves the list.
STILL_TO_RENAME = {
    "bilinear_splat": "lesson 05: the checker becomes check.splat, as the function splat",
    "dithering_ordered": "lesson 06: reports say dithering_ordered, not DitheringOrdered",
    "dithering_error_diffuse": "lesson 06: reports say dithering_error_diffuse",
    "blur": "lesson 07: checker, function and report share one name (now blur, blur_exercise, "
    "Blur)",
    "edge": "lesson 07: checker, function and report share one name (now edge, edge_exercise, "
    "Edge)",
    "poisson_boundary": "lesson 08: checker and function share one name (now poisson_boundary, "
    "boundary_exercise)",
    "jacobi_sweep": "lesson 08: checker and function share one name (now jacobi_sweep, "
    "jacobi_exercise)",
}

DECLARED = [exercise for chapter in course_exercises().values() for exercise in chapter]


def not_written_yet(*arguments):
    """The student edition's stub."""
    raise NotImplementedError("your code here")


def forgets_to_return(*arguments):
    """A first try: a wrong answer, whose report ends with a hint."""
    return None


def marked(declaration: Exercise):
    if declaration.name in STILL_TO_RENAME:
        reason = STILL_TO_RENAME[declaration.name]
        return pytest.param(declaration, marks=pytest.mark.xfail(strict=True, reason=reason))
    return declaration


@pytest.mark.parametrize("declaration", [marked(d) for d in DECLARED], ids=lambda d: d.name)
def test_an_exercise_has_one_name(declaration):
    name = declaration.name
    module = importlib.import_module(declaration.module)
    assert getattr(module, name) is declaration.checker, f"check.{name} is not its checker"
    assert declaration.names == (name,), f"{name} has more names: {declaration.names}"
    report = declaration.checker(forgets_to_return)
    assert report.exercise == name and str(report).startswith(f"FAIL {name}:"), str(report)
    asked = re.findall(r'check\.hint\("([^"]+)"', str(report))
    assert asked == [name], f"{name}: its report points to check.hint{tuple(asked)}"
    assert hint(name).exercise == name


def test_the_exercises_still_to_rename_are_declared():
    # A renamed exercise's old name leaves STILL_TO_RENAME with it.
    names = {declaration.name for declaration in DECLARED}
    assert set(STILL_TO_RENAME) <= names, set(STILL_TO_RENAME) - names


def test_lesson_04s_exercises_answer_to_their_function_names():
    from course.lessons.l04_supersampling import check

    for name in ("supersample", "bilinear_sample"):
        assert getattr(check, name).exercise.names == (name,)
        assert str(getattr(check, name)(not_written_yet)).startswith(f"FAIL {name}:")


def test_the_course_map_tells_a_student_the_one_name():
    from course.classroom.course_map import EXERCISE_GUIDE

    assert "`check.name(name)`" in EXERCISE_GUIDE and '`check.hint("name")`' in EXERCISE_GUIDE
