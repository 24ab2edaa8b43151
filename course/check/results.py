"""A checker's result and the handouts' mistakes it names: what a report is made of.

:class:`CheckResult` is what every checker returns, shown in a notebook as its report;
:class:`Mistake` is one of the handouts' known mistakes; :class:`CheckFailed` is what a
grader sees of a failure. :mod:`course.check.base` re-exports them for the checkers.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from course.i18n import _

__all__ = ["CheckFailed", "CheckResult", "Mistake"]


@dataclass(frozen=True)
class Mistake:
    """One of the handouts' known mistakes, as a checker recognises it.

    ``answer(**case)`` is what code with this mistake returns for a case,
    computed by the library's reproduction of the mistake; ``explanation``
    tells the student what their code must have done ("your curve runs
    backwards: you wrote t P[i] + (1 - t) P[i+1]"). ``matches(answer,
    given)`` decides whether the student's answer is the mistake's; by
    default, the checker's own comparison. A mistake that makes the code raise rather
    than answer (a division by a zero height) gives the exception's class as ``raises``:
    its ``answer`` raises it on the cases where the student's code does, and a student's
    exception of that class, on a case where the reproduction raises it too, is named.
    """

    name: str
    explanation: str
    answer: Callable[..., Any]
    matches: Callable[[Any, Any], bool] | None = None
    raises: type[BaseException] | None = None

    def raised(self, error: BaseException, case: dict[str, Any]) -> bool:
        """Whether ``error``, raised by the student's code on ``case``, is this mistake's: of
        the kind it raises, and raised by its reproduction on ``case`` too.

        Examples
        --------
        >>> flat = Mistake("flat", "", lambda height: 1 / height, raises=ZeroDivisionError)
        >>> flat.raised(ZeroDivisionError("division by zero"), {"height": 0})
        True
        >>> flat.raised(ZeroDivisionError("division by zero"), {"height": 2})
        False
        """
        if self.raises is None or not isinstance(error, self.raises):
            return False
        try:
            self.answer(**case)
        except self.raises:
            return True
        except Exception:
            return False
        return False


@dataclass(frozen=True)
class CheckResult:
    """The outcome of checking one exercise; truthy when it passed.

    ``picture`` is a PNG of the difference (or None); ``mistake`` the name of
    the known mistake recognised (or None). In a notebook the report shows
    as text, then the picture. The lessons' check cells call :meth:`graded`: the
    report, its outcome (:meth:`outcome`) in the text's metadata, and under nbgrader a
    failure raised; :meth:`assert_passed` always raises on a failure.
    """

    exercise: str
    passed: bool
    cases_run: int
    message: str
    picture: bytes | None = None
    mistake: str | None = None

    def __bool__(self) -> bool:
        return self.passed

    def assert_passed(self) -> CheckResult:
        """Return this result if it passed; otherwise raise :class:`CheckFailed` with the report.

        Examples
        --------
        >>> CheckResult("f", True, 2, "all 2 cases pass").assert_passed()
        PASS f: all 2 cases pass
        >>> CheckResult("f", False, 1, "case 1 is wrong").assert_passed()
        Traceback (most recent call last):
        ...
        course.check.results.CheckFailed: FAIL f: case 1 is wrong
        """
        if not self.passed:
            raise CheckFailed(str(self))
        return self

    def graded(self) -> None:
        """Show the report; under nbgrader (``NBGRADER_EXECUTION`` set, as ``nbgrader
        autograde`` and ``validate`` do), then raise :class:`CheckFailed` on a failure,
        which costs the test cell its points. In a student's own session it only shows
        the report, so Run All goes on past an exercise not yet written.

        Examples
        --------
        >>> CheckResult("f", True, 2, "all 2 cases pass").graded()
        PASS f: all 2 cases pass
        """
        self._show({"course": {"check": self.outcome()}})
        if not self.passed and os.environ.get("NBGRADER_EXECUTION"):
            raise CheckFailed(str(self))

    def outcome(self) -> dict[str, Any]:
        """What a grader records of this result: the exercise, whether it passed, the named
        mistake (its English name, or None) and the report's text.

        Examples
        --------
        >>> result = CheckResult("f", False, 1, "case 1 is wrong", mistake="drawn backwards")
        >>> result.outcome()["mistake"], result.outcome()["report"]
        ('drawn backwards', 'FAIL f: case 1 is wrong')
        """
        return {
            "exercise": self.exercise,
            "passed": self.passed,
            "mistake": self.mistake,
            "report": str(self),
        }

    def __str__(self) -> str:
        if self.passed:
            return _("PASS {exercise}: {message}").format(
                exercise=self.exercise, message=self.message
            )
        return _("FAIL {exercise}: {message}").format(exercise=self.exercise, message=self.message)

    __repr__ = __str__

    def _ipython_display_(self) -> None:
        self._show()

    def _show(self, metadata: dict[str, Any] | None = None) -> None:
        """The report as text, then its picture; ``metadata`` rides with the text (a check
        cell's outcome, which the class's mistakes report reads). Printed outside IPython."""
        from IPython import get_ipython
        from IPython.display import display

        if get_ipython() is None:
            print(self)
            return
        if metadata is None:
            display({"text/plain": str(self)}, raw=True)
        else:
            display({"text/plain": str(self)}, raw=True, metadata=metadata)
        if self.picture is not None:
            display({"image/png": self.picture}, raw=True)


class CheckFailed(AssertionError):
    """A failed check, raised for graders: its message is the checker's whole report.

    IPython shows it as its first line only (the report itself is the output above it in
    a test cell): no traceback of the course's own code, no server's paths, in the
    notebook or in nbgrader's feedback.
    """

    def _render_traceback_(self) -> list[str]:
        first = str(self).splitlines()[0] if str(self) else ""
        return [f"CheckFailed: {first}"]
