"""How well each exercise's checker catches single slips in its reference solution.

    python benchmarks/bench_mutants.py [--timeout 20] [--only draw_line,bezier]

Every single-slip mutant of every reference solution (tests/mutation.py: an
operator, a comparison, an integer constant plus or minus one, ``and``/``or``,
a unary minus, a dropped line, an index off by one) is checked in a process of
its own, two at a time, under a hard timeout. One line per exercise: the
mutants, how many the checker failed (of them: named a known mistake, stopped
by the checker's own budget), how many survived (passed), hung (the harness's
timeout, or its memory limit, hit: the checker did not stop them) and crashed
(the checker raised). Goal: at least 97 % failed for each exercise, a budget
stop counting as a failure, and no hang. Then every survivor, one line each,
and every hang and crash.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

import mutation  # tests/mutation.py, found through the path above

GOAL = 0.97


def table(outcomes: list[mutation.Outcome], exercises: list[mutation.Exercise]) -> list[str]:
    """The per-exercise lines, then the total."""
    header = (
        f"{'exercise':<24} {'mutants':>7} {'failed':>6} {'named':>5} {'stopped':>7} "
        f"{'survived':>8} {'hangs':>5} {'crashes':>7} {'failed %':>8}  goal >= 97 %, no hang"
    )
    lines = [header, "-" * len(header)]
    total: Counter[str] = Counter()
    for exercise in exercises:
        counts = Counter(o.outcome for o in outcomes if o.mutant.exercise == exercise.checker)
        mutants = sum(counts.values())
        if not mutants:
            continue
        total.update(counts)
        lines.append(_line(exercise.checker, counts))
    lines.append("-" * len(header))
    lines.append(_line("all", total))
    return lines


def _line(name: str, counts: Counter[str]) -> str:
    mutants = sum(counts.values())
    failed = sum(counts[o] for o in mutation.FAILED)
    hangs = counts["hang"] + counts["memory"]
    share = failed / mutants if mutants else 0.0
    met = share >= GOAL and hangs == 0
    return (
        f"{name:<24} {mutants:>7} {failed:>6} {counts['named']:>5} {counts['stopped']:>7} "
        f"{counts['survived']:>8} {hangs:>5} {counts['crash']:>7} {share:>8.1%}  "
        f"{'met' if met else 'NOT MET'}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--timeout", type=float, default=mutation.TIMEOUT)
    parser.add_argument("--only", default="", help="checker names, comma-separated")
    parser.add_argument("--workers", type=int, default=mutation.WORKERS)
    arguments = parser.parse_args()
    exercises = mutation.find_exercises()
    if arguments.only:
        wanted = set(arguments.only.split(","))
        exercises = [e for e in exercises if e.checker in wanted]
    work = mutation.everything(exercises)
    started = time.monotonic()
    done: Counter[str] = Counter()

    def progress(outcome: mutation.Outcome) -> None:
        done[outcome.outcome] += 1
        if sum(done.values()) % 50 == 0 or outcome.outcome in ("hang", "memory", "crash"):
            counts = ", ".join(f"{name} {count}" for name, count in sorted(done.items()))
            print(f"  {sum(done.values())}/{len(work)}: {counts}", file=sys.stderr, flush=True)

    outcomes = mutation.run(
        work, timeout=arguments.timeout, workers=arguments.workers, progress=progress
    )
    seconds = time.monotonic() - started
    print(f"single-slip mutants of {len(exercises)} reference solutions, {len(work)} mutants")
    print("\n".join(table(outcomes, exercises)))
    print(
        f"harness: {seconds:.0f} s for {len(work)} mutants on {arguments.workers} processes, "
        f"timeout {arguments.timeout:g} s each "
        f"(the time depends on the machine and its load; no goal)"
    )
    for title, kinds in (
        ("survivors", ("survived",)),
        ("hangs", ("hang", "memory")),
        ("crashes", ("crash",)),
    ):
        chosen = [o for o in outcomes if o.outcome in kinds]
        print(f"\n{title}: {len(chosen)}")
        for outcome in chosen:
            print(f"  {outcome.mutant.exercise}: {outcome.mutant.diff}")
            if outcome.outcome == "crash":
                print("    " + outcome.detail.replace("\n", "\n    "))


if __name__ == "__main__":
    main()
