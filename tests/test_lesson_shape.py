"""course.classroom.lesson_shape: every lesson keeps the budgets of teaching.md."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from course.classroom.lesson_shape import AT_LEAST, AT_MOST, misses, shape

ROOT = Path(__file__).resolve().parents[1]
LESSONS = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
# The steering team's own measure, beside a checkout as ../shared (CI has it).
SHARED_TOOL = ROOT.parent / "shared" / "tools" / "lesson_shape.py"


@pytest.mark.parametrize("path", [p for p in LESSONS if not p.name.startswith("00")], ids=str)
def test_every_lesson_keeps_the_budgets_of_its_main_path(path):
    assert misses(shape(path)) == [], f"{path.name} misses a budget of teaching.md"


def test_a_missed_budget_is_named_with_its_number():
    row = dict.fromkeys([*AT_MOST, *AT_LEAST], 0) | {"pictures": 3, "apps": 1, "exercises": 2}
    assert misses(row) == []
    assert misses(row | {"words": 1001, "exercises": 1}) == ["words 1001 > 1000", "exercises 1 < 2"]


@pytest.mark.skipif(not SHARED_TOOL.exists(), reason="no ../shared/tools beside this checkout")
@pytest.mark.parametrize("path", LESSONS, ids=str)
def test_the_measure_agrees_with_the_steering_team_s_tool(path):
    spec = importlib.util.spec_from_file_location("shared_lesson_shape", SHARED_TOOL)
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    assert tool.BUDGET == AT_MOST | AT_LEAST
    assert tool.shape(str(path)) == shape(path)
