#!/usr/bin/python3
"""The cost of driving lmgc from Python: an example's command.py run by lmgc-run against lmgc-solve's
own loop with the same parameters (--read-script), in interleaved rounds; and the getters' cost.

Per round, both runs do the same steps of the same example and give the same DOF.LAST byte for byte
(checked). The time per step is each run's own from OUTBOX/run_report.csv: from IncrementStep to
UpdateStep, so lmgc-run's includes the Python calls of every stage between them. Reports the ratio
lmgc-run / lmgc-solve per round, its minimum and median. Then times RBDY2_GetBodyVector (one body)
and RBDY2_GetAllBodyVector (every body) against numpy's copy of an array of the same size: the
getters give one copy of the state (the array owns the buffer the session filled).

Usage: bench/chipy_overhead.py [--example RIGID_2D/1024DK_BoxJC] [--steps 200] [--rounds 5]
       [--build build/release] [--csv FILE]
"""
import argparse
import csv
import filecmp
import os
import statistics
import subprocess
import sys
import tempfile
import timeit

from lmgc90_examples import EXAMPLES, ROOT, prepare_case


def step_seconds(work):
    with open(os.path.join(work, "OUTBOX", "run_report.csv")) as f:
        rows = list(csv.DictReader(f))
    return sum(float(r["step_seconds"]) for r in rows) / max(len(rows), 1)


def getter_times(build, case, work):
    """Microseconds per call of the getters on the case after one step, and of numpy's copy."""
    prepare_case(case, work)
    code = f"""
import os, sys, timeit, numpy as np
sys.path.insert(0, {os.path.join(build, 'python')!r})
from lmgc import chipy
os.chdir({work!r})
chipy._configure(quiet=True)
chipy.Initialize(); chipy.checkDirectories(); chipy.SetDimension(2); chipy.ReadDatbox(deformable=False)
n = chipy.RBDY2_GetNbRBDY2()
one = timeit.timeit(lambda: chipy.RBDY2_GetBodyVector('V____', n // 2), number=20000) / 20000
every = timeit.timeit(lambda: chipy.RBDY2_GetAllBodyVector('V____'), number=500) / 500
a = np.zeros((n, 3)); b = np.zeros(3)
copy_all = timeit.timeit(lambda: a.copy(), number=500) / 500
copy_one = timeit.timeit(lambda: b.copy(), number=20000) / 20000
print(n, one * 1e6, every * 1e6, copy_one * 1e6, copy_all * 1e6)
chipy.Finalize()
"""
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout.split()
    return int(out[0]), [float(x) for x in out[1:]]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--example", default="RIGID_2D/1024DK_BoxJC")
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--csv", default=None)
    args = parser.parse_args()
    tools = os.path.join(args.build, "tools")
    case = os.path.join(EXAMPLES, args.example)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    scratch = tempfile.mkdtemp(prefix="lmgc_chipy_overhead_")
    ratios, rows = [], []
    for r in range(args.rounds):
        times = {}
        order = ("script", "solve") if r % 2 == 0 else ("solve", "script")
        for kind in order:
            work = os.path.join(scratch, kind)
            prepare_case(case, work)
            if kind == "script":
                command = [os.path.join(tools, "lmgc-run"), work, "--quiet", "--max-steps", str(args.steps)]
            else:
                command = [os.path.join(tools, "lmgc-solve"), work, "--quiet", "--read-script", "--steps",
                           str(args.steps)]
            subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
            times[kind] = step_seconds(work)
        same = filecmp.cmp(os.path.join(scratch, "script", "OUTBOX", "DOF.LAST"),
                           os.path.join(scratch, "solve", "OUTBOX", "DOF.LAST"), shallow=False)
        if not same:
            print("the two runs differ: DOF.LAST", file=sys.stderr)
            return 1
        ratio = times["script"] / times["solve"]
        ratios.append(ratio)
        rows.append([r + 1, times["solve"], times["script"], ratio])
        print(f"round {r + 1}: lmgc-solve {times['solve']:.5f} s/step, lmgc-run {times['script']:.5f} s/step, "
              f"ratio {ratio:.3f}", file=sys.stderr)
    bodies, getters = getter_times(args.build, case, os.path.join(scratch, "getters"))
    print(f"| example | steps | rounds | lmgc-run / lmgc-solve per step, min | median |")
    print(f"| --- | --- | --- | --- | --- |")
    print(f"| {args.example} | {args.steps} | {args.rounds} | {min(ratios):.3f} | {statistics.median(ratios):.3f} |")
    print()
    print(f"| getter ({bodies} bodies) | µs per call | numpy copy of the same size, µs |")
    print(f"| --- | --- | --- |")
    print(f"| RBDY2_GetBodyVector('V____', i) | {getters[0]:.2f} | {getters[2]:.2f} |")
    print(f"| RBDY2_GetAllBodyVector('V____') | {getters[1]:.2f} | {getters[3]:.2f} |")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["round", "lmgc_solve_step_seconds", "lmgc_run_step_seconds", "ratio"])
            w.writerows(rows)
            w.writerow([])
            w.writerow(["getter", "microseconds_per_call", "numpy_copy_microseconds", "bodies"])
            w.writerow(["RBDY2_GetBodyVector", getters[0], getters[2], bodies])
            w.writerow(["RBDY2_GetAllBodyVector", getters[1], getters[3], bodies])
    return 0


if __name__ == "__main__":
    sys.exit(main())
