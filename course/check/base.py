"""The machinery behind every exercise checker: reports that teach, and never hang.

A checker runs the student's function on a list of cases and compares each
answer with the library's. The function is called by position, in the
handout's order, so its parameters may have any names; a wrong number of
parameters is reported with the handout's signature before any case runs.
Each case runs under a time and a memory budget
(:mod:`course.check.sandbox`), on copies of its inputs, which are compared
with the originals afterwards: an answer that changes its input fails, even
when its value is right.

A pass is one line, with a small picture of the student's own result when
the checker can draw one. A failure names the first failing case, its
inputs, what was expected and what was given, and where they first differ;
it shows a picture of the difference when the checker can draw one; and it
ends with a hint. Before the hint, the failure is compared with the
handouts' own mistakes, which the library reproduces (:class:`Mistake`):
when the student's answer is what one of them gives, the report names it.

Hints come in steps (:class:`Hints`): the first failure of an exercise says
where to look; from the second failure on, the report says more;
``check.hint("name")`` says more at once, and only
``check.hint("name", recipe=True)`` gives the recipe.

The report's parts have their own modules, re-exported here for the checkers:
:mod:`~course.check.hints` (the steps), :mod:`~course.check.answers`
(reading the student's answer), :mod:`~course.check.comparisons` (values and
pixel sets) and :mod:`~course.check.references` (answers that call the
library's own). Every sentence follows :func:`course.use_language`; a
mistake's name, which :attr:`CheckResult.mistake` keeps in English, is
translated where the report shows it.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable, Mapping, Sequence
from contextlib import AbstractContextManager, ExitStack
from dataclasses import dataclass, field
from functools import partial
from typing import Any

from course.check.answers import (
    AnswerError,
    Reading,
    non_finite,
    only_data,
    pixel_rows,
    read_answer,
)
from course.check.comparisons import close, first_difference, pixel_difference, same_pixels
from course.check.exercises import what_run_cases_takes
from course.check.grading import drawn_cases, grading_seed
from course.check.hints import Hint, Hints, failure_hint, hint, register_hints
from course.check.references import CallBudget, call_budget, forbidden_message, known_mistake
from course.check.results import CheckFailed, CheckResult, Mistake
from course.check.sandbox import (
    CaseStopped,
    arity_problem,
    changed_argument,
    copies,
    is_stub,
    run_bounded,
    student_line,
)
from course.check.shown import show_value
from course.check.views import CheckersView
from course.i18n import _

# The names the checkers import from here, wherever they are defined.
__all__ = [
    "AnswerError",
    "CallBudget",
    "CheckFailed",
    "CheckResult",
    "Hint",
    "Hints",
    "Mistake",
    "call_budget",
    "close",
    "copies_of",
    "first_difference",
    "hint",
    "pixel_difference",
    "pixel_rows",
    "register_hints",
    "run_cases",
    "same_pixels",
]

Case = Mapping[str, Any]


# How often each exercise has failed in this kernel: the hints' step.
_FAILURES: Counter[str] = Counter()

#: Most of the student's warnings a report shows (each once per line of their code).
_MOST_WARNINGS = 3

# The checker's own result class, held from import, and every class of the report as it was
# defined: a cell that replaced a method (``CheckResult.assert_passed = lambda self: self``)
# or left a thread doing so does not make a failure pass; run_cases puts them back.
_Result = CheckResult
_AS_DEFINED = {kind: dict(vars(kind)) for kind in (CheckResult, CheckFailed, Mistake)}
_MISSING = object()
_PYTHONS_OWN = frozenset({"__slotnames__"})  # what Python adds to a class (copyreg's cache)


def _reinstate_own_classes() -> None:
    """Put back what an earlier cell replaced in the report's classes; remove what it added."""
    for kind, defined in _AS_DEFINED.items():
        now = vars(kind)
        for name, value in defined.items():
            if now.get(name, _MISSING) is not value:
                type.__setattr__(kind, name, value)
        for name in [name for name in now if name not in defined and name not in _PYTHONS_OWN]:
            type.__delattr__(kind, name)


def _hint_line(exercise: str, hint: str | Hints) -> str:
    """The report's hint: a plain text, or the next step of an exercise's hints."""
    if isinstance(hint, str):
        return _("Hint: {hint}").format(hint=_(hint))
    _FAILURES[exercise] += 1
    return failure_hint(exercise, hint, _FAILURES[exercise])


def _validated_cases(cases: Any) -> tuple[Case, ...]:
    """The cases as the checker's own tuple: code that reaches it cannot shorten it."""
    if isinstance(cases, (str, bytes, Mapping)) or not isinstance(cases, Iterable):
        raise TypeError(
            _("cases must be a list of mappings, one per case; got {cases_type}").format(
                cases_type=type(cases).__name__
            )
        )
    listed = tuple(cases)
    for index, case in enumerate(listed):
        if not isinstance(case, Mapping) or not all(isinstance(k, str) for k in case):
            raise TypeError(
                _(
                    "cases must be a list of mappings from parameter names to inputs; case "
                    "[{index}] is {case_type}"
                ).format(index=index, case_type=type(case).__name__)
            )
    return listed


@dataclass
class _Report:
    exercise: str
    hint: str | Hints
    warned: list[str] = field(default_factory=list)  # the student's warnings, as text

    def fail(self, count: int, lines: list[str], hinted: bool = True, **extra: Any) -> CheckResult:
        lines = [*lines, *self.warnings()]
        text = "\n".join([*lines, _hint_line(self.exercise, self.hint)] if hinted else lines)
        return _Result(self.exercise, False, count, text, **extra)

    def start(self) -> str:
        where = self.hint if isinstance(self.hint, str) else self.hint.where
        return _("Start here: {where}").format(where=_(where))

    def warnings(self) -> list[str]:
        """The warnings the student's code raised, shown once, as text: never printed to
        stderr (nbgrader zeroes a cell that writes there), never counted."""
        return [
            _("  your code warned (this is not counted): {warning}").format(warning=warning)
            for warning in self.warned[:_MOST_WARNINGS]
        ]


def _quietly(function: Callable[..., Any] | None, *arguments: Any) -> Any:
    """A report's extra (a line, a picture): None rather than an error from the checker."""
    if function is None:
        return None
    try:
        return function(*arguments)
    except Exception:
        return None


def _told(what: Callable[[], Any], fallback: Any = "", seconds: float | None = None) -> Any:
    """``what()`` under a case's budget, or ``fallback``: what a student's object says of itself
    (an exception's message) may take forever or raise in turn."""
    try:
        return run_bounded(what, seconds=seconds)
    except KeyboardInterrupt:
        raise
    except BaseException:
        return fallback


def run_cases(
    exercise: str,
    student: Callable[..., Any],
    cases: Iterable[Case],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    convert: Callable[[Any], Any] = lambda value: value,
    *,
    hint: str | Hints | None = None,
    mistakes: Sequence[Mistake] = (),
    difference: Callable[[Any, Any], str] = first_difference,
    picture: Callable[[Case, Any, Any], bytes | None] | None = None,
    watch: Callable[[], AbstractContextManager[Any]] | None = None,
    explain: Callable[[Case, Any, Any], str] | None = None,
    explain_nan: Callable[[Case, Any], str] | None = None,
    show: Callable[[Any], str] | None = None,
    answer: Callable[[Any, tuple[Any, ...]], Any] | None = None,
    writable: Sequence[str] = (),
    forbidden: Mapping[Any, str] | None = None,
    on_change: str = "",
    pass_picture: Callable[[list[tuple[Case, Any, Any]]], bytes | None] | None = None,
    seconds: float | None = None,
    memory: int | None = None,
) -> CheckResult:
    """Call ``student(*case.values())`` and ``reference(**case)`` for every case.

    The student's function gets deep copies of the case's inputs, by
    position, in the case's order (the handout's), under a budget of
    ``seconds`` and ``memory`` bytes (:data:`~course.check.sandbox.TIME_BUDGET`,
    :data:`~course.check.sandbox.MEMORY_BUDGET` by default). A copy it
    changed fails the case, naming the argument and the first changed
    element (plus ``on_change``), unless the argument is ``writable``.
    ``answer(returned, arguments)``, if given, makes the answer from what it
    returned and the arguments after the call (a window painted into);
    otherwise the answer is what it returned, and None is reported as a
    missing ``return``.

    ``convert`` turns the answer into the reference's form (a tuple into an
    array, say; an :class:`AnswerError` it raises is the report's words)
    before ``compare(expected, given)``. Reading the answer (``answer``,
    ``convert``) runs under the case's budget too, and the answer is then
    made plain (:func:`~course.check.answers.plain`): no method of the
    student's runs after it, so an answer that lies (an ``int`` whose
    ``__eq__`` is always True) or never ends (an endless iterator) fails
    with a report, never a traceback. Stops at the first wrong answer, or at the first
    exception the student's code raises (naming their line, and the mistake that raises it:
    :meth:`Mistake.raised`), and reports that case: its inputs, both answers, ``difference(
    expected, given)``, ``explain(case, expected, given)`` (``explain_nan(case, given)``
    for an answer that holds NaN or inf: where, and why), the mistake of
    ``mistakes`` whose answer the student's matches, ``picture(case,
    expected, given)`` and the next step of ``hint``. ``watch()``, if given,
    makes a context manager the student's code runs under, each case anew
    (:func:`call_budget`); ``forbidden`` maps the library's own answers to
    the message given when the student's code calls or names one; ``hint`` and ``forbidden``
    default to the exercise's declaration (:func:`course.check.exercises.exercise`). On a pass,
    ``pass_picture`` draws the (case, expected, given) of every case.

    The checker's own work runs in :class:`~course.check.views.CheckersView`:
    numpy, math and the builtins as the course imported them, whatever an
    earlier cell patched. The warnings the student's code raises are shown
    once in the report, as text, and count for nothing; the checker no
    longer makes Python show them again. The expected answer is computed
    after the student's call, and a check passes only when every one of its
    cases ran.
    """
    if not callable(student):
        raise TypeError(
            _("{exercise}: expected a function to check; got {type}").format(
                exercise=exercise, type=type(student).__name__
            )
        )
    _reinstate_own_classes()
    with CheckersView() as view:
        hint, forbidden = what_run_cases_takes(exercise, hint, forbidden)
        cases = _validated_cases(drawn_cases(exercise, _validated_cases(cases)))
        graded = grading_seed() is not None  # a graded report shows no expected value
        declared = len(cases)  # held apart from the loop's count: both must agree to pass
        report = _Report(exercise, hint)
        parameters = tuple(cases[0]) if cases else ()
        mismatch = arity_problem(student, parameters)
        if mismatch is not None:
            return report.fail(
                0,
                [
                    _("your function cannot be called as the handout does: {mismatch}").format(
                        mismatch=mismatch
                    )
                ],
            )
        forbidden = dict(forbidden or {})
        if forbidden:
            named = forbidden_message(student, forbidden)
            if named is not None:
                return report.fail(0, [named])

        def guarded() -> AbstractContextManager[Any]:
            stack = ExitStack()
            if forbidden:
                stack.enter_context(call_budget(forbidden=forbidden))
            if watch is not None:
                stack.enter_context(watch())
            return stack

        results: list[tuple[Case, Any, Any]] = []
        count = 0
        for count, case in enumerate(cases, start=1):
            inputs = ", ".join(f"{name}={show_value(value)}" for name, value in case.items())
            inputs_line = _("  inputs: {inputs}").format(inputs=inputs)
            arguments = copies(tuple(case.values()))
            try:
                with view.students(report.warned):
                    returned = run_bounded(
                        lambda arguments=arguments: student(*arguments),
                        seconds=seconds,
                        memory=memory,
                        watch=guarded if (forbidden or watch is not None) else None,
                    )
            except CaseStopped as stopped:
                return report.fail(
                    count,
                    [
                        _("case {count} was stopped: {reason}").format(count=count, reason=stopped),
                        inputs_line,
                    ],
                )
            except CallBudget as stopped:
                reason, *known = str(stopped).split("\n", 1)
                lines = [
                    _("case {count} was stopped: {reason}").format(count=count, reason=reason),
                    inputs_line,
                    *known,
                ]
                return report.fail(count, lines, mistake=stopped.mistake)
            except NotImplementedError as error:
                # A stub's message ("your code here", in the edition's language) is quoted.
                said = _told(lambda error=error: str(error), "", seconds)
                not_written = (
                    _("not written yet: your function raised NotImplementedError: {error}")
                    if said
                    else _("not written yet: your function raised NotImplementedError")
                )
                return report.fail(
                    count, [not_written.format(error=said), report.start()], hinted=False
                )
            except KeyboardInterrupt:  # the student stopped the kernel: stop the check
                raise
            except BaseException as error:  # the student's bug, reported, not raised
                line = _told(lambda error=error: student_line(error), None, seconds)
                lines = [
                    _("case {count} raised {error_type}: {error}").format(
                        count=count,
                        error_type=type(error).__name__,
                        error=_told(lambda error=error: str(error), "", seconds),
                    )
                ]
                if line is not None:
                    lines.append(_("  at {line}").format(line=line))
                known = next((m for m in mistakes if m.raised(error, copies_of(case))), None)
                lines += [inputs_line, *([known_mistake(known)] if known else [])]
                return report.fail(count, lines, mistake=known.name if known else None)
            names = tuple(name for name in parameters if name not in writable)
            keep = [i for i, name in enumerate(parameters) if name not in writable]
            compared = (names, tuple(case[n] for n in names), tuple(arguments[i] for i in keep))
            if only_data(arguments):  # the budget's thread is needed only for the student's code
                changed = changed_argument(*compared)
            else:
                changed = _told(
                    lambda compared=compared: changed_argument(*compared), None, seconds
                )
            if changed is not None:
                lines = [
                    _("case {count} changed its input {changed}").format(
                        count=count, changed=changed
                    ),
                    _(
                        "  your function must leave its inputs as they were: work on a copy "
                        "(np.array(x, dtype=float) or x.copy())"
                    ),
                    inputs_line,
                ]
                if on_change:
                    lines.append(f"  {_(on_change)}")
                return report.fail(count, lines)
            if answer is None and returned is None:
                if is_stub(student):
                    return report.fail(
                        count,
                        [_("not written yet: your function returns nothing"), report.start()],
                        hinted=False,
                    )
                return report.fail(
                    count,
                    [
                        _(
                            "case {count} returned None: did you forget the return statement?"
                        ).format(count=count),
                        inputs_line,
                    ],
                )
            read = partial(read_answer, count, returned, arguments, answer, convert, compare)
            try:
                data = only_data((returned, arguments))
                reading = read() if data else run_bounded(read, seconds=seconds, memory=memory)
            except CaseStopped as stopped:
                reading = Reading(
                    lines=[
                        _("case {count}: reading your answer was stopped: {reason}").format(
                            count=count, reason=stopped
                        )
                    ]
                )
            except KeyboardInterrupt:
                raise
            except BaseException as error:  # a student's method raised more than an Exception
                said = _told(lambda error=error: str(error), "", seconds)
                reason = f"{type(error).__name__}: {said}"
                reading = Reading(
                    lines=[
                        _("case {count}: your answer cannot be read: {reason}").format(
                            count=count, reason=reason
                        )
                    ]
                )
            if reading.lines is not None:
                return report.fail(count, [*reading.lines, inputs_line])
            given = reading.given
            # Computed only now, after the student's call: no frame of theirs can read it.
            expected = reference(**case)
            bad = non_finite(given)
            if bad is not None:
                lines = [
                    _("case {count}: {problem}").format(count=count, problem=bad),
                    inputs_line,
                ]
                said = _quietly(explain_nan, case, given)
                if said:
                    lines.append(f"  {said}")
                # A mistake with its own rule may expect NaN (an empty window's mean).
                known = _recognise([m for m in mistakes if m.matches], case, given, compare)
                if known is not None:
                    lines.append(known_mistake(known))
                return report.fail(count, lines, mistake=None if known is None else known.name)
            try:
                same = bool(compare(expected, given))
            except Exception:  # an answer of another form than the reference's
                same = False
            if same:
                results.append((case, expected, given))
                continue
            writer = show or show_value
            lines = [
                _("case {count} is wrong").format(count=count),
                inputs_line,
                _("  expected: {value}").format(value=_quietly(writer, expected)),
                _("  given:    {value}").format(value=_quietly(writer, given) or reading.described),
            ]
            for extra in (_quietly(difference, expected, given), reading.narrow):
                if extra:
                    lines.append(f"  {extra}")
            if graded:  # the case's inputs and the student's answer, not the expected one
                lines = [lines[0], lines[1], lines[3]]
            elif explain is not None:
                said = _quietly(explain, case, expected, given)
                if said:
                    lines.append(f"  {said}")
            known = _recognise(mistakes, case, given, compare)
            if known is not None:
                lines.append(known_mistake(known))
            drawn = None if graded else _quietly(picture, case, expected, given)
            return report.fail(
                count, lines, picture=drawn, mistake=None if known is None else known.name
            )
        if not declared:
            return report.fail(0, [_("no case ran: a check needs at least one case")])
        if count != declared or len(results) != declared:
            return report.fail(
                count,
                [
                    _(
                        "only {count} of the {declared} cases ran: a check passes only when "
                        "every case runs"
                    ).format(count=len(results), declared=declared)
                ],
            )
        drawn = _quietly(pass_picture, results)
        passed = "\n".join([_("all {count} cases pass").format(count=count), *report.warnings()])
        return _Result(exercise, True, count, passed, picture=drawn)


def _recognise(
    mistakes: Sequence[Mistake], case: Case, given: Any, compare: Callable[[Any, Any], bool]
) -> Mistake | None:
    """The first mistake whose answer for ``case`` is the student's (inside the checker's view,
    where no warning is shown)."""
    for mistake in mistakes:
        try:
            if (mistake.matches or compare)(mistake.answer(**copies_of(case)), given):
                return mistake
        except Exception:
            continue
    return None


def copies_of(case: Case) -> dict[str, Any]:
    """A case with every input deep-copied, for code that may write into it."""
    return dict(zip(case, copies(tuple(case.values())), strict=True))
