"""Lesson 01's drag steps drawn from arrays (ArrayStep) send what the usual step sends."""

from __future__ import annotations

import json

import numpy as np
import pytest

from course.lessons.l01_de_casteljau.apps import DeCasteljauApp
from course.widgets import array_step


class Twins:
    """Two apps driven alike: one draws its steps from arrays, one the usual way."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch) -> None:
        self.quick, self.usual = DeCasteljauApp(), DeCasteljauApp()
        self.usual.drag_step = lambda *args: False
        self.sent: dict[DeCasteljauApp, list] = {}
        for app in (self.quick, self.usual):
            app.refresh()
            self.sent[app] = messages = []
            app.view.image.send = lambda content, buffers=None, to=messages: to.append(
                (content, [bytes(buffer) for buffer in buffers or []])
            )
        self.quick_steps = 0
        send = array_step.ArrayStep.send

        def counted(step: array_step.ArrayStep) -> None:
            self.quick_steps += 1
            send(step)

        monkeypatch.setattr(array_step.ArrayStep, "send", counted)

    def pointer(self, kind: str, x: float, y: float) -> None:
        for app in (self.quick, self.usual):
            app.view.awaited = True
            app.pointer(kind, x, y)
        assert np.array_equal(self.quick.points, self.usual.points)
        assert self.sent[self.quick][-1] == self.sent[self.usual][-1]

    def press(self, index: int) -> tuple[float, float]:
        handle = self.quick.handles()[index]
        x, y = self.quick.picture_point(handle.axes, handle.at)
        self.pointer("down", x + 1.5, y - 2.0)
        return float(x), float(y)


def test_a_drag_s_steps_from_arrays_send_the_usual_messages(monkeypatch):
    twins = Twins(monkeypatch)
    rng = np.random.default_rng(7)
    moves = 0
    for index in (1, 0, 3, 2):
        x, y = twins.press(index)
        # Near and far, past the picture's edges too (the point stops at the view's).
        for dx, dy in rng.normal(0, 150, size=(25, 2)):
            twins.pointer("move", x + dx, y + dy)
            moves += 1
        twins.pointer("up", x + dx, y + dy)
        assert twins.quick.value("points") == twins.usual.value("points")
        assert twins.quick.axes.get_xlim() == twins.usual.axes.get_xlim()
    assert twins.quick_steps == moves  # every move was drawn from arrays


def test_a_step_that_arrays_cannot_draw_is_drawn_the_usual_way(monkeypatch):
    twins = Twins(monkeypatch)
    x, y = twins.press(1)
    twins.pointer("move", x + 10, y + 5)
    assert twins.quick_steps == 1
    # A level's new colour: its recorded paints no longer hold.
    for app in (twins.quick, twins.usual):
        app.level_lines[1].set_color("red")
    twins.pointer("move", x + 20, y + 5)
    assert twins.quick_steps == 1
    strokes = [command.get("stroke") for command in json.loads(twins.sent[twins.quick][-1][1][1])]
    assert [1.0, 0.0, 0.0, 1.0] in strokes
    twins.pointer("move", x + 25, y + 5)  # recorded again by the usual step: arrays again
    assert twins.quick_steps == 2
    # A moving artist the arrays do not draw, shown: the title.
    for app in (twins.quick, twins.usual):
        app.title.set_visible(True)
    twins.pointer("move", x + 30, y + 8)
    assert twins.quick_steps == 2
    for app in (twins.quick, twins.usual):
        app.title.set_visible(False)
    twins.pointer("move", x + 35, y + 8)
    assert twins.quick_steps == 3
    # A new t, set by code during the drag: the title's start changes with it.
    for app in (twins.quick, twins.usual):
        app.controls["t"].value = 0.3
    twins.pointer("move", x + 40, y + 8)
    assert twins.quick_steps == 3
    twins.pointer("up", x + 40, y + 8)
    assert twins.quick.value("points") == twins.usual.value("points")


def test_a_step_from_arrays_keeps_the_titles_and_the_release_brings_the_artists_up(
    monkeypatch,
):
    twins = Twins(monkeypatch)
    x, y = twins.press(2)
    twins.pointer("move", x - 30, y + 12)
    quick = twins.quick
    assert quick.title_numbers.get_text() == twins.usual.title_numbers.get_text()
    assert quick.title.get_text() == twins.usual.title.get_text()
    twins.pointer("up", x - 30, y + 12)
    for mine, theirs in zip(quick.level_lines, twins.usual.level_lines, strict=True):
        np.testing.assert_array_equal(mine.get_xydata(), theirs.get_xydata())
    np.testing.assert_array_equal(
        quick.full_curve.get_xydata(), twins.usual.full_curve.get_xydata()
    )
    assert quick.labels[2].xy == twins.usual.labels[2].xy
    assert np.array_equal(quick.view.pixels(), twins.usual.view.pixels())
