"""course.check.budget: a case's budget, kept by the operating system where it can keep it."""

import time
import tracemalloc

import pytest

from course.check import budget

LINUX = pytest.mark.skipif(not budget._CAPS_MEMORY, reason="the address-space cap is Linux's")
SIGNALS = pytest.mark.skipif(budget._INTERRUPT is None, reason="no signal to interrupt a wait")


def _the_alarm_is_free():
    """A SIGALRM handler set by someone else is left alone, and no signal is sent then."""
    handler = budget.signal.getsignal(budget.signal.SIGALRM)
    if handler not in (budget.signal.SIG_DFL, budget.signal.SIG_IGN):
        pytest.skip("SIGALRM has another handler here (pytest --timeout's)")
    return handler


@SIGNALS
def test_one_long_wait_is_interrupted_at_the_wall_clocks_limit_not_at_its_end():
    before = _the_alarm_is_free()
    started = time.monotonic()
    with pytest.raises(budget.CaseStopped) as stopped:
        budget.run_bounded(lambda: time.sleep(60), seconds=0.05)  # the wall's limit: 0.5 s
    assert stopped.value.kind == "time"
    assert time.monotonic() - started < 5
    # The signal's handler is put back as it was: a later SIGALRM is not the checker's.
    assert budget.signal.getsignal(budget.signal.SIGALRM) == before


@LINUX
def test_memory_outside_tracemalloc_is_capped_by_the_system():
    # A 3 GiB map is invisible to tracemalloc; under the address-space cap it is refused.
    import mmap

    started = time.monotonic()
    with pytest.raises(budget.CaseStopped) as stopped:
        budget.run_bounded(lambda: mmap.mmap(-1, 3 * 2**30), memory=64 * 2**20)
    assert stopped.value.kind == "memory" and "past 64 MiB" in str(stopped.value)
    assert time.monotonic() - started < 2
    soft, _hard = budget.resource.getrlimit(budget.resource.RLIMIT_AS)
    assert soft == budget.resource.RLIM_INFINITY  # the cap is lifted after the case


@LINUX
def test_where_the_system_caps_memory_tracemalloc_does_not_slow_the_case():
    assert budget.run_bounded(tracemalloc.is_tracing) is False
    assert budget.run_bounded(lambda: sum(range(10**6))) == sum(range(10**6))


@SIGNALS
def test_a_case_run_inside_another_leaves_the_outer_ones_signal_in_place():
    before = _the_alarm_is_free()

    def outer():
        assert budget.run_bounded(lambda: "inner") == "inner"
        time.sleep(60)  # still interrupted: the signal's handler is the outer case's

    started = time.monotonic()
    with pytest.raises(budget.CaseStopped):
        budget.run_bounded(outer, seconds=0.05)
    assert time.monotonic() - started < 5
    assert budget.signal.getsignal(budget.signal.SIGALRM) == before
