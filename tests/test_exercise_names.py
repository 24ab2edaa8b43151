"""One name per exercise: the student's function, its checker, its report and its hint key.

The course map tells a student that every exercise ends with ``check.name(name)``: the function
they write is checked by ``check.<name>``, the report opens with ``FAIL <name>:`` and the hint
is ``check.hint("<name>")``. A second name for any of them is one more thing to get wrong.
"""

import importlib
import re

import pytest

from course.check.exercises import declared
from course.check.hints import hint
from course.classroom.exercise_list import course_exercises

DECLARED = [exercise for chapter in course_exercises().values() for exercise in chapter]


def not_written_yet(*arguments):
    """The student edition's stub."""
    raise NotImplementedError("your code here")


def forgets_to_return(*arguments):
    """A first try: a wrong answer, whose report ends with a hint."""
    return None


@pytest.mark.parametrize("declaration", DECLARED, ids=lambda d: d.name)
def test_an_exercise_has_one_name(declaration):
    name = declaration.name
    module = importlib.import_module(declaration.module)
    assert getattr(module, name) is declaration.checker, f"check.{name} is not its checker"
    report = declaration.checker(forgets_to_return)
    assert report.exercise == name and str(report).startswith(f"FAIL {name}:"), str(report)
    asked = re.findall(r'check\.hint\("([^"]+)"', str(report))
    assert asked == [name], f"{name}: its report points to check.hint{tuple(asked)}"
    assert hint(name).exercise == name


RENAMED = {
    "l04_supersampling": ("supersample", "bilinear_sample"),
    "l05_antialiasing": ("splat",),
    "l06_dithering": ("dithering_ordered", "dithering_error_diffuse"),
    "l07_filtering": ("blur", "edge"),
    "l08_poisson": ("boundary_ring", "jacobi_solve"),
}


@pytest.mark.parametrize("chapter", sorted(RENAMED))
def test_the_renamed_exercises_answer_to_their_function_names_only(chapter):
    check = importlib.import_module(f"course.lessons.{chapter}.check")
    for name in RENAMED[chapter]:
        assert getattr(check, name).exercise.name == name
        assert str(getattr(check, name)(not_written_yet)).startswith(f"FAIL {name}:")
    # The second names they had are gone: no checker answers to them.
    for old in ("bilinear_splat", "blur_exercise", "Edge", "boundary_exercise", "jacobi_sweep"):
        with pytest.raises(LookupError):
            declared(old)


@pytest.mark.parametrize(
    ("handout_name", "name"),
    [
        ("DitheringOrdered", "dithering_ordered"),
        ("DitheringErrorDiffuse", "dithering_error_diffuse"),
        ("Blur", "blur"),
        ("Edge", "edge"),
    ],
)
def test_a_labs_own_name_still_finds_the_hint(handout_name, name):
    course_exercises()
    assert hint(handout_name).exercise == name


def test_the_course_map_tells_a_student_the_one_name():
    from course.classroom.course_map import EXERCISE_GUIDE

    assert "`check.name(name)`" in EXERCISE_GUIDE and '`check.hint("name")`' in EXERCISE_GUIDE


def test_a_notebook_without_the_answer_is_graded_under_the_one_name():
    from course.classroom.autograder import grade_exercise

    result, printed = grade_exercise({"cells": []}, "blur", seed=0)
    assert not result and printed == []
    assert str(result).startswith("FAIL blur:"), str(result)
    assert "no answer cell for blur" in str(result)
