"""How well each exercise's checker catches single slips in its reference solution.

    python benchmarks/bench_mutants.py [--timeout 20] [--only draw_line,bezier]

Every single-slip mutant of every reference solution (tests/mutation.py: an
operator, a comparison, an integer constant plus or minus one, ``and``/``or``,
a unary minus, a dropped line, an index off by one) is checked in a process of
its own, two at a time, under a hard timeout. One line per exercise: the
mutants, how many the checker failed (of them: named a known mistake, stopped
by the checker's own budget), how many survived (passed), hung (the harness's
timeout, or its memory limit, hit: the checker did not stop them) and crashed
(the checker raised), and the share failed. Goal, for each exercise: at least
97 % of the mutants that are not equivalent failed (tests/test_mutants.py lists
the equivalent survivors, and why), a budget stop counting as a failure, and no
hang. Then every survivor, one line each, and every hang and crash.
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


def reasons() -> dict[tuple[str, str], str]:
    """Why each survivor listed in tests/test_mutants.py passes, by (exercise, diff)."""
    import test_mutants  # beside mutation.py

    return {(exercise, diff): why for exercise, diff, why in test_mutants.SURVIVORS}


def is_equivalent(why: str | None) -> bool:
    """A listed survivor that computes what the reference does (or a tie the lesson allows)."""
    return why is not None and why.startswith(("equivalent", "acceptable"))


def table(
    outcomes: list[mutation.Outcome],
    exercises: list[mutation.Exercise],
    why: dict[tuple[str, str], str],
) -> list[str]:
    """The per-exercise lines, then the total."""
    header = (
        f"{'exercise':<24} {'mutants':>7} {'failed':>6} {'named':>5} {'stopped':>7} "
        f"{'survived':>8} {'(equiv.)':>8} {'hangs':>5} {'crashes':>7} {'failed %':>8} "
        f"{'% of non-equiv.':>15}  goal"
    )
    lines = [header, "-" * len(header)]
    total: Counter[str] = Counter()
    for exercise in exercises:
        counts: Counter[str] = Counter()
        for outcome in outcomes:
            if outcome.mutant.exercise == exercise.checker:
                counts[outcome.outcome] += 1
                key = (outcome.mutant.exercise, outcome.mutant.diff)
                if outcome.outcome == "survived" and is_equivalent(why.get(key)):
                    counts["equivalent"] += 1
        if counts:
            total.update(counts)
            lines.append(_line(exercise.checker, counts))
    lines.append("-" * len(header))
    lines.append(_line("all", total))
    return lines


def _line(name: str, counts: Counter[str]) -> str:
    mutants = sum(counts[o] for o in mutation.OUTCOMES)
    failed = sum(counts[o] for o in mutation.FAILED)
    hangs = counts["hang"] + counts["memory"]
    share = failed / mutants if mutants else 0.0
    rest = mutants - counts["equivalent"]
    share_of_rest = failed / rest if rest else 1.0
    met = share_of_rest >= GOAL and hangs == 0
    return (
        f"{name:<24} {mutants:>7} {failed:>6} {counts['named']:>5} {counts['stopped']:>7} "
        f"{counts['survived']:>8} {counts['equivalent']:>8} {hangs:>5} {counts['crash']:>7} "
        f"{share:>8.1%} {share_of_rest:>15.1%}  {'met' if met else 'NOT MET'}"
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
    why = reasons()
    print("\n".join(table(outcomes, exercises, why)))
    print(
        "goal: at least 97 % of the mutants that are not equivalent failed (a budget stop is a "
        "failure), and no hang; equivalent: listed in tests/test_mutants.py as computing the "
        "reference's answer, or a tie the checker accepts by design"
    )
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
            reason = why.get((outcome.mutant.exercise, outcome.mutant.diff))
            mark = "" if title != "survivors" else "  [NOT LISTED]" if reason is None else ""
            if mark == "" and is_equivalent(reason):
                mark = f"  [{str(reason).split(':')[0]}]"
            mark = mark or ("  [listed, to catch]" if title == "survivors" else "")
            print(f"  {outcome.mutant.exercise}: {outcome.mutant.diff}{mark}")
            if outcome.outcome == "crash":
                print("    " + outcome.detail.replace("\n", "\n    "))


if __name__ == "__main__":
    main()
