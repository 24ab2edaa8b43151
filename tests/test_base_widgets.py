"""course.widgets.base: a control or a drag redraws the picture; the text repr is stable."""

import base64
import types

import ipywidgets as widgets
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from course.i18n import language
from course.widgets.base import Handle, SliderApp, format_points, pad, parse_points


class LineApp(SliderApp):
    """A minimal app: a horizontal line at height y."""

    def __init__(self) -> None:
        super().__init__({"y": widgets.FloatSlider(value=0.5, min=0, max=1)}, shape=(100, 200))
        axes = self.figure.add_axes((0, 0, 1, 1))
        axes.set_xlim(0, 1)
        axes.set_ylim(0, 1)
        axes.set_axis_off()
        (self.line,) = axes.plot([0, 1], [0.5, 0.5], color="black", linewidth=4)

    def update(self) -> None:
        y = self.value("y")
        self.line.set_ydata([y, y])


def dark_rows(app: LineApp) -> np.ndarray:
    rgba = app.view.pixels()
    return np.flatnonzero((rgba[..., :3] < 100).all(axis=2).any(axis=1))


def test_moving_a_slider_redraws_the_picture_where_the_value_says():
    app = LineApp()
    app.refresh()
    before = app.view.image.value
    rows = dark_rows(app)
    assert abs(rows.mean() - 50) < 2
    app.controls["y"].value = 0.9
    assert app.renders == 2
    assert app.view.image.value != before
    assert abs(dark_rows(app).mean() - 10) < 2


def test_repr_is_stable_text_plus_a_still_picture():
    app = LineApp()
    bundle = app._repr_mimebundle_()
    assert bundle["text/plain"] == "LineApp(y=0.5)"
    assert base64.b64decode(bundle["image/png"]).startswith(b"\x89PNG")
    assert "application/vnd.jupyter.widget-view+json" in bundle


class BoxApp(LineApp):
    """The line, a draggable point on it, and a draggable box: the base machinery alone."""

    def __init__(self) -> None:
        super().__init__()
        self.axes = self.line.axes
        self.point = np.array([0.25, 0.5])
        self.box = np.array([0.6, 0.3])  # lower-left corner of a 0.2 x 0.2 box
        self.clicks = []
        self.doubles = []

    def handles(self):
        x, y = self.box
        return [
            Handle("point", self.axes, tuple(self.point)),
            Handle("box", self.axes, (x, y), box=(x, y, x + 0.2, y + 0.2)),
        ]

    def drag(self, name, point):
        if name == "point":
            self.point = point
        else:
            self.box = point
        self.controls["y"].value = float(np.clip(point[1], 0, 1))

    def click(self, axes, point):
        self.clicks.append(tuple(np.round(point, 3)))
        return True

    def double_click(self, name):
        self.doubles.append(name)
        return True


def test_the_pointer_maps_picture_pixels_through_the_axes_both_ways():
    app = BoxApp()
    app.refresh()
    # Picture 200 x 100, axes filling it, data 0..1 both ways, y up in data.
    np.testing.assert_allclose(app.picture_point(app.axes, (0.25, 0.5)), [50, 50])
    np.testing.assert_allclose(app.data_point(app.axes, 50, 50), [0.25, 0.5])
    np.testing.assert_allclose(app.data_point(app.axes, 0, 100), [0, 0])
    assert app.axes_at(10, 10) is app.axes and app.axes_at(-5, 10) is None


def test_a_drag_keeps_the_grab_offset_and_redraws_once_per_move():
    app = BoxApp()
    app.refresh()
    app.pointer("down", 53, 50)  # 3 px right of the point, within the grab radius
    assert app.grabbed == "point" and app.renders == 2  # the highlight
    app.pointer("move", 103, 30)
    assert app.renders == 3  # one redraw, though drag() changed a control
    np.testing.assert_allclose(app.point, [0.5, 0.7])  # the point, not the pointer
    app.pointer("up", 403, -170)  # far outside the picture: data beyond the axes
    np.testing.assert_allclose(app.point, [2.0, 2.7])
    assert app.grabbed is None and app.value("y") == 1.0
    assert app.highlight_ring(app.axes)[0].get_xydata().size == 0


def test_boxes_are_grabbed_inside_points_win_ties_and_clicks_hit_empty_space():
    app = BoxApp()
    app.refresh()
    assert app.handle_at(140, 60).name == "box"  # inside (0.6..0.8, 0.3..0.5)
    assert app.handle_at(50 + app.GRAB_RADIUS + 1, 50) is None
    app.pointer("down", 150, 55)
    assert app.grabbed == "box"
    _, outline = app.highlight_ring(app.axes)
    assert outline.get_visible() and tuple(outline.get_xy()) == (0.6, 0.3)
    app.pointer("up", 150, 55)
    assert not outline.get_visible()
    app.pointer("down", 20, 80)
    app.pointer("up", 20 + app.CLICK_SLOP, 80)
    assert app.clicks == [(0.12, 0.2)]
    app.pointer("down", 20, 80)
    app.pointer("up", 40, 80)  # moved too far: not a click
    assert len(app.clicks) == 1
    app.pointer("double", 50, 50)
    app.pointer("double", 20, 80)  # on nothing: ignored
    assert app.doubles == ["point"]


def test_bad_pointer_events_are_refused_by_name_and_messages_are_answered():
    app = BoxApp()
    app.refresh()
    with pytest.raises(ValueError, match="kind must be one of 'down', 'move', 'up', 'double'"):
        app.pointer("hover", 1, 1)
    with pytest.raises(ValueError, match="x and y must be finite"):
        app.pointer("down", float("nan"), 1)
    sent = []
    app.view.image.send = sent.append
    app._on_message(app.view.image, {"kind": "down", "x": "oops"}, [])
    assert "Ignored a pointer message" in app.status.value
    app._on_message(app.view.image, {"kind": "down", "x": 50, "y": 50}, [])
    assert sent == [{"kind": "drawn"}, {"kind": "drawn"}] and app.grabbed == "point"


def test_the_browser_learns_where_the_handles_are():
    app = BoxApp()
    app.refresh()
    point, box = app.view.image.handles
    assert point == [50.0, 50.0, app.GRAB_RADIUS, 0, 0, 0, 0]
    assert box == [0, 0, 0, 120.0, 50.0, 160.0, 70.0]
    with pytest.raises(KeyError, match=r"expected one of the handles \['box', 'point'\]"):
        app.handle_named("P7")


def test_drag_along_presses_moves_and_releases_like_the_browser():
    app = BoxApp()
    app.refresh()
    start = app.drag_along("box", [(10, 0), (20, -10)])
    np.testing.assert_allclose(start, [140, 60])
    np.testing.assert_allclose(app.box, [0.7, 0.4])
    assert app.grabbed is None


def test_points_as_text_both_ways():
    points = parse_points("(1, 2.5); 3,4 ; [-5e-1, 6]\n7, +8;")
    np.testing.assert_array_equal(points, [[1, 2.5], [3, 4], [-0.5, 6], [7, 8]])
    assert parse_points(format_points(points)).tolist() == points.tolist()


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("90,5 610,5; 170 130", "decimal comma"),  # read as 3 points before
        ("90,5, 610,5", "decimal comma"),
        ("0x10, 0b1", "decimal"),  # read as (0, 10), (0, 1) before
        ("0o7, 1", "decimal"),
        ("1, 2, 3", "two numbers; got 3"),
        ("3 4", "comma between them"),
        ("1, 2; -5e-1 6", "point 2"),
        ("nan, 1", "decimal numbers"),
        ("1, 2; x", "point 2"),
        ("(1, 2", "point 1"),
        ("", "expected text such as"),
        (" ; \n ", "expected text such as"),
    ],
)
def test_points_text_that_could_be_read_two_ways_is_refused_with_a_reason(text, reason):
    with pytest.raises(ValueError, match=reason):
        parse_points(text)


def test_points_text_must_be_finite_and_on_the_canvas_range():
    with pytest.raises(ValueError, match="finite"):
        parse_points("1e400, 0")
    with pytest.raises(ValueError, match="within"):
        parse_points("1e9, 0")
    with pytest.raises(TypeError, match="text must be a string"):
        parse_points(None)


@pytest.mark.parametrize(
    "message",
    [
        {"kind": "down", "x": None, "y": 10},  # a TypeError escaped before
        {"kind": "down", "x": 10, "y": "10"},
        {"kind": "move", "x": float("nan"), "y": 1},
        {"kind": "down", "x": True, "y": 1},
        {"kind": "down", "x": [1], "y": 1},
        {"kind": None, "x": 1, "y": 1},
        {"kind": ["down"], "x": 1, "y": 1},
        {"kind": "jump", "x": 1, "y": 1},
        {"x": 1, "y": 1},
        {"kind": "down", "y": 1},
        {},
        None,
        "down",
    ],
)
def test_a_malformed_pointer_message_is_reported_never_raised(message):
    app = BoxApp()
    app.refresh()
    sent = []
    app.view.image.send = sent.append
    app._on_message(app.view.image, message, [])
    assert app.status.value.startswith("Ignored a pointer message: ")
    assert sent == [{"kind": "drawn"}]  # the browser may send its next move
    assert app.grabbed is None and app.renders == 1


def test_a_slider_set_to_nan_from_code_is_refused_and_the_last_value_kept():
    app = LineApp()
    app.refresh()
    app.controls["y"].value = 0.8
    before = app.view.image.value
    app.controls["y"].value = float("nan")  # ipywidgets lets NaN through
    assert app.value("y") == 0.8
    assert app.status.value == "Refused y = nan: expected a finite number; kept 0.8"
    assert app.view.image.value == before  # the picture shows the value kept
    app.controls["y"].value = 0.2
    assert app.status.value == ""
    assert abs(dark_rows(app).mean() - 80) < 2


class PickyApp(LineApp):
    """An app whose update refuses some values its control can hold."""

    def update(self) -> None:
        if self.value("y") > 0.9:
            raise ValueError("y above 0.9 is not drawn")
        super().update()


def test_a_value_the_update_refuses_is_put_back_with_the_reason():
    app = PickyApp()
    app.refresh()
    app.controls["y"].value = 0.95
    assert app.value("y") == 0.5
    assert app.status.value == "Refused y = 0.95: y above 0.9 is not drawn; kept 0.5"
    assert abs(dark_rows(app).mean() - 50) < 2


def small_apps():
    """Every app of the lessons, each built small: name -> a function that builds it."""
    from course.images import SEED_000_CUBIC
    from course.lessons.l01_de_casteljau import apps as de_casteljau
    from course.lessons.l02_bernstein import apps as bernstein
    from course.lessons.l03_lines_and_triangles import apps as lines_and_triangles
    from course.lessons.l04_supersampling import apps as supersampling
    from course.lessons.l05_antialiasing import apps as antialiasing
    from course.lessons.l06_dithering import apps as dithering
    from course.lessons.l07_filtering import apps as filtering
    from course.lessons.l08_poisson import apps as poisson

    gray = np.linspace(0, 1, 48 * 48).reshape(48, 48)
    background = np.full((40, 60, 3), 0.5)
    foreground = np.full((12, 16, 3), 0.8)
    curve = SEED_000_CUBIC / 5
    return {
        "ZoomApp": lambda: antialiasing.ZoomApp(curve, (140, 140), k=8),
        "StepApp": lambda: antialiasing.StepApp(curve, (140, 140)),
        "BernsteinBasisApp": bernstein.BernsteinBasisApp,
        "DeCasteljauApp": de_casteljau.DeCasteljauApp,
        "DitherComparisonApp": lambda: dithering.DitherComparisonApp(gray, size=8),
        "GrayLevelApp": lambda: dithering.GrayLevelApp(size=12),
        "VoidAndClusterApp": lambda: dithering.VoidAndClusterApp(size=16, dots=10),
        "RepeatedBlurApp": lambda: filtering.RepeatedBlurApp(gray, repeats=1, corner=6),
        "KernelApp": lambda: filtering.KernelApp(gray, window=(0, 0)),
        "LineApp": lines_and_triangles.LineApp,
        "TriangleApp": lines_and_triangles.TriangleApp,
        "CurveSegmentsApp": lambda: lines_and_triangles.CurveSegmentsApp(segments=4),
        "PoissonIterationApp": lambda: poisson.PoissonIterationApp(
            background, foreground, (20, 10), stops=(0, 1)
        ),
        "CloneApp": lambda: poisson.CloneApp(background, foreground, (20, 10)),
        "SupersampleApp": lambda: supersampling.SupersampleApp(
            size=500, out_size=64, max_rate=6, reference_rate=8
        ),
    }


def test_small_apps_lists_every_app_of_the_lessons():
    import importlib
    import inspect
    import pkgutil

    import course.lessons

    found = set()
    for chapter in pkgutil.iter_modules(course.lessons.__path__):
        if not chapter.ispkg:
            continue
        loaded = importlib.import_module(f"course.lessons.{chapter.name}.apps")
        for name, value in vars(loaded).items():
            if inspect.isclass(value) and issubclass(value, SliderApp) and value is not SliderApp:
                found.add(name)
    assert found == set(small_apps())


@pytest.mark.parametrize("name", sorted(small_apps()))
def test_every_app_survives_malformed_pointer_messages_and_nan_sliders(name):
    app = small_apps()[name]()
    app.refresh()
    app.view.image.send = lambda content: None
    for message in ({"kind": "down", "x": None, "y": 3}, {"kind": "up"}, [1, 2], {"x": "1"}):
        app.status.value = ""
        app._on_message(app.view.image, message, [])
        assert app.status.value.startswith("Ignored a pointer message: ")
    numbers = [key for key, control in app.controls.items() if isinstance(control.value, float)]
    for key in numbers:
        before = app.value(key)
        app.controls[key].value = float("nan")
        assert app.value(key) == before
        assert app.status.value.startswith(f"Refused {key} = nan: expected a finite number")


#: What a student typed into the apps' boxes (issue 34), and what the app must answer: runs of
#: 16,000 and 32,000 digits froze eight apps for 7 to 37 s, 1e10000000 froze the kernel app
#: for 10 s, and Arabic-Indic and full-width digits were read as numbers.
TYPED_POINTS = [
    ("1" * 16_000, "expected at most 4000 characters; got 16000"),
    ("1" * 32_000 + ", 1", "expected at most 4000 characters; got 32003"),
    ("1" * 3999, "is not x, y"),
    ("1e10000000, 5", "points must be finite numbers"),
    ("١٢, ٣٤", "digits 0-9"),
    ("１２, ３４", "digits 0-9"),
]
TYPED_KERNEL = [
    ("1" * 16_000, "expected at most 4000 characters; got 16000"),
    ("1 1 1; 1 1 1; 1 1 " + "1" * 3900 + "/", "decimal number like 2, -0.5 or 1/9; got '111"),
    ("1e10000000 0 0; 0 1 0; 0 0 0", "every entry must lie within"),
    ("١ ٢ ١; ٢ ٤ ٢; ١ ٢ ١", "decimal number like 2, -0.5 or 1/9; got '١'"),
    ("１ ２ １; ２ ４ ２; １ ２ １", "decimal number like 2, -0.5 or 1/9; got '１'"),
]


@pytest.mark.parametrize("name", sorted(small_apps()))
def test_every_apps_text_boxes_answer_the_issues_texts_with_a_reason(name):
    app = small_apps()[name]()
    app.refresh()
    boxes = [key for key, control in app.controls.items() if isinstance(control, widgets.Text)]
    boxes += [key for key, control in app.controls.items() if isinstance(control, widgets.Textarea)]
    if not boxes:
        pytest.skip("no text box")
    for box in boxes:
        before = app.view.pixels().copy()
        typed = TYPED_KERNEL if box == "kernel" else TYPED_POINTS
        for text, reason in typed:
            app.controls[box].value = text
            assert app.status.value.startswith("Kept the last"), (box, text[:20])
            assert reason in app.status.value, (box, text[:20], app.status.value[:200])
            np.testing.assert_array_equal(app.view.pixels(), before)


def test_typed_text_beyond_the_limit_is_refused_before_it_is_parsed(monkeypatch):
    """The parser's work is bounded: too long a text never reaches the patterns."""
    from course import limits
    from course.lessons.l07_filtering import apps as filtering

    limit = limits.MAX_TYPED_TEXT
    at_limit = "1, 2;" + " " * (limit - 5)
    assert parse_points(at_limit).tolist() == [[1, 2]]
    kernel_at_limit = "0 0 0; 0 1 0; 0 0 0" + " " * (limit - 19)
    assert filtering.parse_kernel(kernel_at_limit).sum() == 1

    def never(*args):
        raise AssertionError("parsed")

    monkeypatch.setattr("course.widgets.base._POINT", types.SimpleNamespace(fullmatch=never))
    monkeypatch.setattr(filtering, "_kernel_row", never)
    with pytest.raises(ValueError, match=f"points: expected at most {limit} characters"):
        parse_points(at_limit + " ")
    with pytest.raises(ValueError, match=f"kernel: expected at most {limit} characters"):
        filtering.parse_kernel(kernel_at_limit + "\n")


@pytest.mark.parametrize("digits", ["١٢", "۱۲", "１２", "𝟑𝟒"])  # float() reads them all
def test_only_the_digits_0_to_9_are_numbers(digits):
    from course.lessons.l07_filtering.apps import parse_kernel

    with pytest.raises(ValueError, match=f"digits 0-9 and the ASCII comma.*got '{digits[0]}'"):
        parse_points(f"3, {digits}")
    with pytest.raises(ValueError, match=f"a decimal number like 2, -0.5 or 1/9; got '{digits}'"):
        parse_kernel(f"1 1 1; 1 {digits} 1; 1 1 1")


def test_a_full_width_comma_is_named_as_the_character_to_retype():
    with pytest.raises(ValueError, match="got '，'"):
        parse_points("10，10")


tenths = st.integers(-99_999, 99_999).map(lambda n: n / 10)


@given(st.lists(st.tuples(tenths, tenths), min_size=1, max_size=12))
def test_points_read_back_what_format_points_wrote(points):
    np.testing.assert_array_equal(parse_points(format_points(points)), points)


@given(st.lists(st.tuples(tenths, tenths), min_size=1, max_size=6), st.data())
def test_points_written_with_decimal_commas_are_refused_not_misread(points, data):
    # A locale's way of writing them: decimal commas, points split by spaces or ';'.
    def localised(value):
        return f"{value:.1f}".replace(".", ",")

    separator = data.draw(st.sampled_from([" ", "; ", "\n"]))
    text = separator.join(f"{localised(x)} {localised(y)}" for x, y in points)
    with pytest.raises(ValueError, match="point 1"):
        parse_points(text)


def test_an_apps_model_id_is_counted_per_class_not_random():
    from course.lessons.l01_de_casteljau.apps import DeCasteljauApp
    from course.lessons.l02_bernstein.apps import BernsteinBasisApp

    first, second = DeCasteljauApp().widget.model_id, DeCasteljauApp().widget.model_id
    assert first.startswith("course-DeCasteljauApp-") and second != first
    assert int(second.rsplit("-", 1)[1]) == int(first.rsplit("-", 1)[1]) + 1
    assert BernsteinBasisApp().widget.model_id.startswith("course-BernsteinBasisApp-")


def test_a_table_pads_chinese_by_the_columns_it_takes():
    assert pad("lit", 6, ">") == f"{'lit':>6s}" and pad("lit", 6) == f"{'lit':6s}"
    assert pad("点亮", 6, ">") == "  点亮" and pad("（像素）", 9) == "（像素） "
    assert pad("过长的名字", 4) == "过长的名字"
    with pytest.raises(ValueError, match="align"):
        pad("lit", 6, "^")


class _OneSlider(SliderApp):
    def __init__(self):
        super().__init__({"t": widgets.FloatSlider(value=0.5)}, shape=(40, 40), dpi=40)

    def update(self):
        pass


def test_the_status_line_speaks_the_language_and_clears_after_a_refused_value():
    with language("zh-CN"):
        app = _OneSlider()
        app.controls["t"].value = float("nan")
        assert app.status.value == "拒绝了 t = nan：应为有限的数；保留 0.5"
        app.controls["t"].value = 0.25
        assert app.status.value == ""
        app._on_message(None, {"kind": "down"}, [])
        assert app.status.value == "忽略了一条指针消息：缺少 x, y"
        with pytest.raises(ValueError, match="小数点不能写成逗号") as error:
            parse_points("90,5 610,5")
        assert "第 1 个点" in str(error.value)
    app.controls["t"].value = float("nan")
    assert app.status.value == "Refused t = nan: expected a finite number; kept 0.25"
