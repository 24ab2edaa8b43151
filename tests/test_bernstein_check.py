"""Lesson 02's checkers: Pascal's rule, exactly and without help; naive_bezier of any degree."""

import functools
import itertools
import math

import graded_draws
import numpy as np
import pytest

from course.check import base
from course.curves.bezier_handouts import comb_recursive_calls
from course.lessons.l02_bernstein import check


def pascal(m, n):
    row = [1]
    for _ in range(m):
        row = [1] + [a + b for a, b in itertools.pairwise(row)] + [1]
    return row[n] if n <= m else 0


def handout_recursion(m, n):  # seed 002's comb
    if m < n:
        return 0
    if m == n or n == 0:
        return 1
    if n == 1:
        return m
    return handout_recursion(m - 1, n) + handout_recursion(m - 1, n - 1)


@functools.cache
def remembered(m, n):
    if m < n:
        return 0
    if m == n or n == 0:
        return 1
    return remembered(m - 1, n) + remembered(m - 1, n - 1)


def numpy_row(dtype):
    def comb(m, n):
        row = np.ones(1, dtype=dtype)
        for _ in range(m):
            row = np.concatenate([row[:1], row[:-1] + row[1:], row[-1:]])
        return row[n] if n <= m else 0

    return comb


def float_row(m, n):
    row = [1.0]
    for _ in range(m):
        row = [1.0] + [a + b for a, b in itertools.pairwise(row)] + [1.0]
    return row[n] if n <= m else 0


def one_row_short(m, n):
    row = [1]
    for _ in range(m - 1):
        row = [1] + [a + b for a, b in itertools.pairwise(row)] + [1]
    return row[n] if n < len(row) else 0


def test_pascal_rule_passes_in_one_line_by_rows_or_remembered_recursion():
    assert str(check.comb(pascal)) == "PASS comb: all 14 cases pass"
    assert check.comb(remembered)


@pytest.mark.parametrize(
    ("solution", "mistake", "case"),
    [
        (handout_recursion, "the exponential recursion", 10),
        (numpy_row(np.int32), "32-bit integers", 11),
        (numpy_row(np.int64), "64-bit integers", 13),
        (float_row, "floating point", 1),
        (one_row_short, "off by one row", 3),
    ],
)
def test_each_known_mistake_of_comb_is_named(solution, mistake, case, monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    result = check.comb(solution)
    assert not result and result.mistake == mistake
    assert str(result).startswith(f"FAIL comb: case {case} ")
    assert str(result).splitlines()[-2:] == [
        f"Hint: {check.COMB_HINTS.where}",
        '(More: check.hint("comb").)',
    ]


def test_the_exponential_recursion_is_stopped_quickly_and_counted():
    message = str(check.comb(handout_recursion))
    assert "case 10 was stopped: more than 20,000 Python function calls" in message
    assert "inputs: m=20, n=7" in message and "would make 1.4e+11 calls" in message


@pytest.mark.parametrize(
    ("solution", "called"),
    [
        (lambda m, n: math.comb(m, n), "math.comb was called"),
        (
            lambda m, n: math.factorial(m) // (math.factorial(n) * math.factorial(m - n)),
            "math.factorial was called",
        ),
    ],
)
def test_the_library_answers_are_refused(solution, called):
    result = check.comb(solution)
    reason = "this exercise builds the coefficients itself, by Pascal's rule"
    if "factorial" in called:
        reason += ", not from factorials"
    assert not result and str(result).splitlines()[0] == f"FAIL comb: {called}: {reason}"


def test_a_refused_import_is_caught_however_it_was_imported():
    from math import comb as imported

    assert "math.comb was called" in str(check.comb(lambda m, n: imported(m, n)))


comb = pascal  # the student's comb of exercise 1, under the name the notebook gives it


def naive_solution(points, t):
    n = len(points) - 1
    return sum(comb(n, i) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))


def de_casteljau_loop(points, t):
    """Right points, by lesson 01's repeated interpolation: no Bernstein sum, no comb."""
    points = np.asarray(points, dtype=float)
    while len(points) > 1:
        points = (1 - t) * points[:-1] + t * points[1:]
    return points[0]


def test_right_points_without_comb_are_told_the_exercise_is_the_bernstein_sum(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    result = check.naive_bezier(de_casteljau_loop)
    assert not result and result.mistake == "not the Bernstein sum"
    message = str(result)
    assert message.startswith(
        "FAIL naive_bezier: your naive_bezier gives the right points, but not by the Bernstein sum"
    )
    assert "weighted by comb(n, i) t^i (1 - t)^(n - i)" in message
    assert f"Hint: {check.NAIVE_HINTS.where}" in message

    # A helper of the student's that calls comb counts: the sum is theirs.
    def weight(n, i, t):
        return comb(n, i) * t**i * (1 - t) ** (n - i)

    def with_a_helper(points, t):
        n = len(points) - 1
        return sum(weight(n, i, t) * p for i, p in enumerate(points))

    assert check.naive_bezier(with_a_helper)


def test_a_wrong_answer_without_comb_that_no_mistake_explains_is_told_so_too():
    def off_de_casteljau(points, t):
        return de_casteljau_loop(points, t) + 1.0

    result = check.naive_bezier(off_de_casteljau)
    assert not result and result.mistake == "not the Bernstein sum"
    assert "your naive_bezier never calls your comb" in result.message


def test_naive_bezier_passes_in_one_line_whatever_it_returns_a_point_in():
    assert str(check.naive_bezier(naive_solution)) == "PASS naive_bezier: all 57 cases pass"
    assert check.naive_bezier(lambda p, t: tuple(naive_solution(p, t)))
    with pytest.raises(TypeError, match="naive_bezier"):
        check.naive_bezier(np.zeros(2))


@pytest.mark.parametrize(
    ("solution", "mistake"),
    [
        (
            lambda p, t: sum(
                pascal(len(p) - 1, i) * t ** (len(p) - 1 - i) * (1 - t) ** i * q
                for i, q in enumerate(p)
            ),
            "the reversed weights",
        ),
        (
            lambda p, t: sum(
                pascal(len(p), i) * t**i * (1 - t) ** (len(p) - i) * q for i, q in enumerate(p)
            ),
            "the degree off by one",
        ),
        (lambda p, t: naive_solution(p, t)[::-1], "x and y swapped"),
    ],
)
def test_each_known_mistake_of_naive_bezier_is_named_with_its_picture(solution, mistake):
    result = check.naive_bezier(solution)
    assert not result and result.mistake == mistake and result.picture is not None


def test_int32_binomials_are_named_at_degree_40():
    def int32_comb(n, k):
        value = pascal(n, k) % 2**32  # not math.comb: naive_bezier refuses it
        return value - 2**32 if value >= 2**31 else value

    def naive_int32(points, t):
        n = len(points) - 1
        return sum(int32_comb(n, i) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))

    # They pass on the 55 curves of up to 12 points (C(11, 5) fits in an int) and fail on the
    # first of 41 points, case 56: C(40, 20) does not.
    result = check.naive_bezier(naive_int32)
    assert not result and result.mistake == "32-bit binomials"
    assert str(result).startswith("FAIL naive_bezier: case 56 is wrong")


def comb_in_int32_products(m, n):
    """comb by the product formula, in np.int32 as a student copying the C++ `int` writes it."""
    if n > m:
        return 0
    value = np.int32(1)
    with np.errstate(over="ignore"):
        for i in range(n):
            value = value * np.int32(m - i) // np.int32(i + 1)
    return value


def naive_with_int32_products(points, t):
    comb = comb_in_int32_products
    n = len(points) - 1
    return sum(comb(n, i) * t**i * (1 - t) ** (n - i) * points[i] for i in range(n + 1))


def test_binomials_that_overflow_in_int32_products_are_named_at_degree_40():
    # Before: no name at all (its weights are not the int32 Pascal row's), and a picture of
    # 41 labels on top of each other.
    result = check.naive_bezier(naive_with_int32_products)
    assert not result and result.mistake == "binomials that overflow"
    assert str(result).startswith("FAIL naive_bezier: case 56 is wrong")
    assert "Keep np.int32 and np.int64 out of your comb" in result.message
    assert check.naive_bezier(naive_solution)


def test_a_picture_of_many_control_points_labels_only_some():
    from course.check import pictures

    labels = []
    real = pictures.Figure

    class Counting(real):
        def add_subplot(self, *args, **kwargs):
            axes = super().add_subplot(*args, **kwargs)
            annotate = axes.annotate
            axes.annotate = lambda text, *a, **k: (labels.append(text), annotate(text, *a, **k))[1]
            return axes

    pictures.Figure = Counting
    try:
        pictures.curve_picture(
            np.random.default_rng(0).uniform(0, 700, (41, 2)), [[0, 0]], [[0, 0]]
        )
    finally:
        pictures.Figure = real
    assert [label for label in labels if label.startswith("P")] == [
        "P0",
        "P10",
        "P20",
        "P30",
        "P40",
    ]


def product_formula(m, n):
    if n > m:
        return 0
    result = 1
    for i in range(n):
        result = result * (m - i) // (i + 1)
    return result


def factorial(k):
    value = 1
    for i in range(1, k + 1):
        value *= i
    return value


def by_factorials(m, n):
    return factorial(m) // (factorial(n) * factorial(m - n)) if n <= m else 0


def float_product(m, n):
    if n > m:
        return 0
    result = 1
    for i in range(n):
        result = result * (m - i) / (i + 1)
    return result


@pytest.mark.parametrize(
    ("solution", "product"),
    [(product_formula, "result * (m - i) // (i + 1)"), (by_factorials, "value *= i")],
)
def test_a_comb_that_multiplies_is_told_to_use_pascals_rule(solution, product, monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    result = check.comb(solution)
    assert not result and result.mistake == "not Pascal's rule"
    assert str(result).startswith(
        "FAIL comb: your comb gives the right numbers, but not by Pascal's rule"
    )
    assert f"({product})" in result.message or "fact" in result.message
    assert "C(m, n) = C(m - 1, n - 1) + C(m - 1, n)" in result.message


def test_pascal_rule_with_a_list_made_longer_is_not_a_product():
    def in_place_row(m, n):
        if n > m:
            return 0
        row = [1] + [0] * m
        for k in range(1, m + 1):
            for i in range(k, 0, -1):
                row[i] += row[i - 1]
        return row[n]

    assert check.comb(in_place_row)


def test_a_float_comb_is_named_at_once_not_by_the_call_budget(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    # C(1, 1) = 1.0 is already a float; so is the handout's recursion returning 1.0, which
    # the call budget would otherwise stop first.
    result = check.comb(float_product)
    assert result.mistake == "floating point"
    assert str(result).startswith("FAIL comb: case 3 is wrong")
    assert "given:    1.0" in result.message

    def float_recursion(m, n):
        if m < n:
            return 0.0
        if n in (0, m):
            return 1.0
        return float_recursion(m - 1, n) + float_recursion(m - 1, n - 1)

    result = check.comb(float_recursion)
    assert result.mistake == "floating point"
    assert str(result).startswith("FAIL comb: case 1 is wrong")


def rounded_float_product(m, n):
    if n > m:
        return 0
    result = 1.0
    for i in range(n):
        result = result * (m - i) / (i + 1)
    return int(round(result))  # noqa: RUF046 (the student's code, as written)


def test_a_float_product_rounded_back_to_an_int_is_named_not_pascals_rule(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    result = check.comb(rounded_float_product)
    # Exact up to 2^53: the first wrong answer is C(67, 33), case 13.
    assert not result and result.mistake == "not Pascal's rule"
    assert str(result).startswith("FAIL comb: case 13 is wrong")
    assert "your comb multiplies or divides (result * (m - i) / (i + 1))" in result.message
    assert "int(round(...)) cannot bring back the ones lost" in result.message
    assert check.comb(pascal)


def test_a_naive_bezier_with_math_comb_is_told_to_use_its_own_comb():
    def with_math_comb(points, t):
        n = len(points) - 1
        return sum(math.comb(n, i) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))

    result = check.naive_bezier(with_math_comb)
    assert not result
    assert str(result).startswith(
        "FAIL naive_bezier: math.comb was called: this exercise weights the points with your "
        "own comb"
    )
    assert check.naive_bezier(naive_solution)


def test_the_any_degree_reports_upside_down_binomial_is_named():
    def upside_down(points, t):
        n = len(points) - 1
        return sum(pascal(i, n) * t**i * (1 - t) ** (n - i) * p for i, p in enumerate(points))

    result = check.naive_bezier(upside_down)
    assert not result and result.mistake == "the binomial upside down"
    assert "your curve is t^n P[n] alone" in result.message
    assert result.picture is not None


# --- graded: cases drawn for each submission ------------------------------------------------


def accumulating_naive_bezier():
    """A naive_bezier whose sum starts from where the last call left it."""
    total = np.zeros(2)

    def naive(points, t):
        nonlocal total
        total = total + naive_solution(points, t)
        return total

    return naive


#: The mistakes a function answering as the mistake does cannot make: a float that rounds
#: to the right integer, a product (recognised in the code), binomials that overflow (recognised
#: by the weights the student's sum gives), an accumulator (across calls),
#: right points without comb (recognised in the code).
WRITTEN_COMB = {2: lambda: float_row, 6: lambda: rounded_float_product}
WRITTEN_NAIVE = {
    5: lambda: naive_with_int32_products,
    6: accumulating_naive_bezier,
    7: lambda: de_casteljau_loop,
}


def test_graded_comb_cases_are_drawn_in_the_fixed_cases_families():
    for cases in graded_draws.check_drawn_cases("comb"):
        pairs = [(c["m"], c["n"]) for c in cases]
        assert pairs[:3] == [(0, 0), (1, 0), (1, 1)]
        assert all(4 <= m <= 7 and 0 < n < m for m, n in pairs[3:5])
        assert pairs[5][1] == 0 and pairs[6][0] == pairs[6][1]
        assert all(n > m for m, n in pairs[7:9])
        assert comb_recursive_calls(*pairs[9]) > 2 * check.MAX_CALLS
        assert all(2**31 < math.comb(m, n) < 2**53 for m, n in pairs[10:12])
        assert math.comb(*pairs[12]) > 2**64 and 92 <= pairs[13][0] <= 100
        # Pascal's rule answers the biggest within the call budget and far within the time.
        assert str(graded_draws.graded("comb", pascal, 0)).startswith("PASS comb")


def test_graded_naive_bezier_cases_are_drawn_in_the_fixed_cases_families():
    fixed = check.curve_cases(max_points=12)
    for cases in graded_draws.check_drawn_cases("naive_bezier"):
        sizes = [len(c["control_points"]) for c in cases]
        assert sizes[:-2] == [len(c["control_points"]) for c in fixed]
        assert 39 <= sizes[-1] == sizes[-2] <= 43 and cases[-1]["t"] == 0.5


@pytest.mark.parametrize(
    ("name", "written"), [("comb", WRITTEN_COMB), ("naive_bezier", WRITTEN_NAIVE)]
)
def test_graded_cases_tell_every_mistake_the_reference_passes_a_stub_fails(name, written):
    graded_draws.check_graded(name, written)


@pytest.mark.parametrize(
    ("solution", "mistake"),
    [(handout_recursion, "the exponential recursion"), (product_formula, "not Pascal's rule")],
)
def test_graded_comb_stops_the_recursion_and_names_a_product(solution, mistake):
    for seed in graded_draws.SEEDS:
        assert graded_draws.graded("comb", solution, seed).mistake == mistake
