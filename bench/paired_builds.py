#!/usr/bin/python3
"""Two builds of lmgc-solve on LMGC90's rigid examples: the same iterates, and the time per step.

For a change that must keep the iterates (a reshaping of the code): runs every RIGID_2D and RIGID_3D
example with lmgc-solve of build A and of build B, in interleaved rounds (A, B, B, A, ...), each on a
scratch copy of its case and driven by its own command.py, for --steps steps. Reports per example
whether OUTBOX/DOF.LAST and OUTBOX/Vloc_Rloc.LAST are byte for byte equal between A and B, and the
time per step of B over A: the minimum and the median of the paired ratios (lmgc-solve's own
per-step time from OUTBOX/run_report.csv, so start-up and the final writes are not counted).

Usage: bench/paired_builds.py A_SOLVE B_SOLVE [--steps 100] [--rounds 5] [--only NAME] [--csv FILE]
"""
import argparse
import csv
import filecmp
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

from lmgc90_examples import EXAMPLES, prepare_case, rigid_examples


def run(solve, case, steps, work):
    """Runs one case; returns (seconds per step, OUTBOX folder)."""
    prepare_case(os.path.join(EXAMPLES, case), work)
    # No periodic files: only the state at the end is compared.
    subprocess.run([solve, "--quiet", "--steps", str(steps), "--write-every", "0", "--display-every", "0",
                    work], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=dict(os.environ, OMP_NUM_THREADS="1"))
    with open(os.path.join(work, "OUTBOX", "run_report.csv")) as f:
        rows = list(csv.DictReader(f))
    seconds = sum(float(r["step_seconds"]) for r in rows)
    return seconds / max(len(rows), 1), os.path.join(work, "OUTBOX")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--only")
    parser.add_argument("--csv")
    args = parser.parse_args()
    if not os.path.isdir(EXAMPLES):
        print(f"no examples at {EXAMPLES}")
        return 0
    scratch = tempfile.mkdtemp(prefix="lmgc_paired_")
    rows = []
    print("| example | DOF.LAST | Vloc_Rloc.LAST | B/A time per step, min | median |")
    print("| --- | --- | --- | --- | --- |")
    for case in rigid_examples(args.only):
        ratios = []
        same = {"DOF.LAST": True, "Vloc_Rloc.LAST": True}
        for k in range(args.rounds):
            order = ("a", "b") if k % 2 == 0 else ("b", "a")
            result = {}
            for which in order:
                solve = args.a if which == "a" else args.b
                result[which] = run(solve, case, args.steps, os.path.join(scratch, which))
            for name in same:
                pa, pb = (os.path.join(result[w][1], name) for w in ("a", "b"))
                if os.path.exists(pa) != os.path.exists(pb) or (
                        os.path.exists(pa) and not filecmp.cmp(pa, pb, shallow=False)):
                    same[name] = False
            if result["a"][0] > 0.0:
                ratios.append(result["b"][0] / result["a"][0])
        low = min(ratios) if ratios else float("nan")
        median = statistics.median(ratios) if ratios else float("nan")
        verdict = {True: "identical", False: "DIFFERS"}
        print(f"| {case} | {verdict[same['DOF.LAST']]} | {verdict[same['Vloc_Rloc.LAST']]} | {low:.3f} | {median:.3f} |",
              flush=True)
        rows.append([case, args.steps, same["DOF.LAST"], same["Vloc_Rloc.LAST"], f"{low:.4f}", f"{median:.4f}"])
    shutil.rmtree(scratch, ignore_errors=True)
    if args.csv:
        os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["example", "steps", "dof_last_identical", "vloc_rloc_last_identical", "ratio_min",
                        "ratio_median"])
            w.writerows(rows)
    return 0 if all(r[2] and r[3] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
