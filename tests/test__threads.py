"""course.poisson._threads: the solvers' BLAS and FFT threads, and that they give them back."""

import threading
import time

import numpy as np
import pytest
import scipy.fft
from threadpoolctl import threadpool_info, threadpool_limits

from course.poisson import _threads, capacitance, solvers


def blas_threads() -> list[int]:
    return [
        library["num_threads"] for library in threadpool_info() if library["user_api"] == "blas"
    ]


def most_blas_threads() -> int:
    with threadpool_limits(limits=None):
        return min(blas_threads())


needs_two = pytest.mark.skipif(
    most_blas_threads() < 2, reason="BLAS runs on one thread here: nothing to limit"
)


@pytest.mark.parametrize(
    ("cores", "load", "expected"),
    [
        (1, 0.0, 1),  # one core: never more than this process's thread
        (2, 0.0, 2),
        (2, 0.05, 2),  # a whisper of load leaves the second core idle
        (2, 0.6, 1),  # more than half of it busy: not idle
        (2, 1.3, 1),
        (2, 2.0, 1),  # the two busy loops on two cores
        (4, 1.0, 3),
        (4, 1.49, 3),
        (4, 1.51, 2),
        (8, 0.0, _threads.MAX_THREADS),  # capped
        (8, 2.5, _threads.MAX_THREADS),
        (8, 6.0, 2),
        (8, 50.0, 1),  # never fewer than one
        (8, -1.0, _threads.MAX_THREADS),  # a nonsense load counts as none
        (8, float("inf"), 1),  # the system does not say: one thread
        (8, float("nan"), 1),
    ],
)
def test_threads_to_use_is_this_process_plus_the_idle_cores(cores, load, expected):
    assert _threads.threads_to_use(cores=cores, load=load) == expected


def test_threads_to_use_reads_the_machine_by_default(monkeypatch):
    monkeypatch.setattr(_threads, "available_cores", lambda: 6)
    monkeypatch.setattr(_threads, "others_load", lambda: 2.2)
    assert _threads.threads_to_use() == 4  # 1 + round(6 - 1 - 2.2)
    monkeypatch.setattr(_threads, "others_load", lambda: 4.9)
    assert _threads.threads_to_use() == 1


def test_the_load_and_the_cores_are_sensible_numbers():
    assert _threads.available_cores() >= 1
    assert _threads.others_load() >= 0.0


@needs_two
def test_limited_threads_lowers_blas_and_fft_and_restores_both():
    with threadpool_limits(limits=2, user_api="blas"), scipy.fft.set_workers(2):
        assert blas_threads() == [2] * len(blas_threads())
        with _threads.limited_threads(1) as workers:
            assert workers == 1
            assert scipy.fft.get_workers() == 1
            assert set(blas_threads()) == {1}
        assert blas_threads() == [2] * len(blas_threads())
        assert scipy.fft.get_workers() == 2


@needs_two
def test_limited_threads_never_raises_the_caller_s_lower_limit():
    with threadpool_limits(limits=1, user_api="blas"), scipy.fft.set_workers(1):
        with _threads.limited_threads(2) as workers:
            assert workers == 1
            assert scipy.fft.get_workers() == 1
            assert set(blas_threads()) == {1}
        assert set(blas_threads()) == {1}
    with threadpool_limits(limits=2, user_api="blas"), scipy.fft.set_workers(2):
        with _threads.limited_threads(_threads.MAX_THREADS) as workers:
            assert workers == 2
            assert set(blas_threads()) == {2}  # not raised to MAX_THREADS either


@needs_two
def test_limited_threads_restores_after_an_exception():
    with threadpool_limits(limits=2, user_api="blas"):
        with pytest.raises(ZeroDivisionError), _threads.limited_threads(1):
            assert set(blas_threads()) == {1}
            _ = 1 / 0
        assert set(blas_threads()) == {2}
        assert scipy.fft.get_workers() == 1  # its default, untouched


@needs_two
def test_nested_limits_restore_the_outer_one_and_then_the_caller_s():
    with threadpool_limits(limits=2, user_api="blas"):
        with _threads.limited_threads(2):
            with _threads.limited_threads(1):
                assert set(blas_threads()) == {1}
            assert set(blas_threads()) == {2}  # the inner block left; the outer has not
        assert set(blas_threads()) == {2}


@needs_two
def test_threads_of_the_caller_take_turns_and_leave_the_caller_s_limit():
    # No limit held by the main thread here: threadpoolctl lets a thread change
    # OpenBLAS's setting only while no other thread holds it.
    before = blas_threads()
    assert min(before) >= 2
    seen, started = [], threading.Barrier(3)

    def solve_repeatedly():
        started.wait(5)
        for _ in range(15):
            with _threads.limited_threads(1):
                time.sleep(0.002)  # let the other threads run, and try to enter
                seen.append(set(blas_threads()))
                with _threads.limited_threads(1):  # a nested block in the same thread
                    seen.append(set(blas_threads()))

    workers = [threading.Thread(target=solve_repeatedly) for _ in range(3)]
    for worker in workers:
        worker.start()
    for worker in workers:
        worker.join(60)
    assert len(seen) == 90
    assert all(threads == {1} for threads in seen)  # no thread lifted another's limit early
    assert blas_threads() == before  # nor left BLAS limited for good


@needs_two
def test_the_solvers_run_inside_the_limit_and_restore_it(monkeypatch):
    seen = []
    original = capacitance.box_solve

    def spying_box_solve(rhs):
        seen.append(set(blas_threads()))
        return original(rhs)

    monkeypatch.setattr(capacitance, "box_solve", spying_box_solve)
    monkeypatch.setattr(_threads, "threads_to_use", lambda: 1)
    values, region, source = disc_problem()
    with threadpool_limits(limits=2, user_api="blas"):
        capacitance.solve_capacitance(values, region, source)
        assert seen and all(threads == {1} for threads in seen)
        assert set(blas_threads()) == {2}


def disc_problem(channels=3, size=61):
    rng = np.random.default_rng(7)
    rows, columns = np.indices((size, size))
    region = np.hypot(rows - size // 2, columns - size // 2) < size // 2 - 2
    values = rng.random((channels, size, size))
    source = (rng.random((channels, size, size)) - 0.5) * region
    return values, region, source


def rectangle_problem(channels=3, height=200, width=200):
    rng = np.random.default_rng(8)
    region = np.zeros((height, width), bool)
    region[1:-1, 1:-1] = True
    values = rng.random((channels, height, width))
    source = (rng.random((channels, height, width)) - 0.5) * region
    return values, region, source


@needs_two
@pytest.mark.parametrize(
    ("solver", "problem"),
    [
        (solvers.solve_dst, rectangle_problem),  # 198 + 1 is prime: BLAS products
        (solvers.solve_dst, lambda: rectangle_problem(height=130, width=161)),  # FFTs
        (capacitance.solve_capacitance, disc_problem),
        (solvers.solve_direct, disc_problem),
    ],
)
def test_the_solvers_agree_to_rounding_on_one_thread_and_on_two(monkeypatch, solver, problem):
    values, region, source = problem()
    results = {}
    for threads in (1, 2):
        monkeypatch.setattr(_threads, "threads_to_use", lambda threads=threads: threads)
        with threadpool_limits(limits=2, user_api="blas"):
            results[threads] = solver(values, region, source)
    # Not bit for bit: OpenBLAS splits a product differently on two threads,
    # which changes the order of some sums.
    np.testing.assert_allclose(results[1], results[2], rtol=0, atol=1e-12)
    for result in results.values():
        assert solvers.residual(result, region, source) < 1e-9


@needs_two
def test_what_lesson_08_prints_is_the_same_on_one_thread_and_on_two(monkeypatch):
    # The load chooses the thread count (threads_to_use), so the printed numbers must not
    # depend on it: two threads change the last bits of a solve (the test above), and
    # the captions round far above them.
    from course import poisson
    from course.lessons.l08_poisson import figures
    from course.widgets.picture import rounding_level

    lake, plane = figures.lab_scene()
    problem = poisson.clone_problem(lake, plane, figures.LAB_OFFSET)
    printed = {}
    for threads in (1, 2):
        monkeypatch.setattr(_threads, "threads_to_use", lambda threads=threads: threads)
        with threadpool_limits(limits=2, user_api="blas"), scipy.fft.set_workers(2):
            printed[threads] = [
                figures.headline_figure().caption,
                figures.correction_figure().caption,
                figures.colour_figure().caption,
                *(
                    rounding_level(problem.residual(poisson.solve(problem, method)), 1e-10)
                    for method in ("dst", "direct", "capacitance")
                ),
            ]
    assert printed[1] == printed[2]
