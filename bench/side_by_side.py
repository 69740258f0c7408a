#!/usr/bin/python3
"""lmgc-solve against LMGC90 itself, side by side, on LMGC90's rigid examples.

Each example runs from its own command.py in both codes, for the same --steps, in interleaved rounds
(LMGC90, lmgc, lmgc, LMGC90, ...) on the same machine. The script is edited only in what it writes:
nb_steps = N and no file written inside the time loop (freq_write and freq_display beyond N), so that
LMGC90's in-loop writes are not timed; everything else (NLGS parameters, quick scramble, rotation
scheme, ...) is the example's. Timed: LMGC90's time loop (the script's `for ... in range(...)` loop,
wrapped in a clock), lmgc-solve's steps (OUTBOX/run_report.csv). Both single-threaded.

Reported per example: the time per step of each code (minimum and median over the rounds), the
ratio LMGC90 / lmgc of each round (minimum and median), and the achieved NLGS check norm of each
(QuadDV / (tol QuadWR) at a step's last check, median over the steps with contacts: 1 is the
tolerance), so that speed is compared at the achieved residual each code reached.

Usage: bench/side_by_side.py [--steps 100] [--rounds 3] [--lmgc90 ../lmgc90/build]
                             [--build build/release] [--only NAME] [--csv FILE]
"""
import argparse
import csv
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from lmgc90_examples import EXAMPLES, ROOT, prepare_case, rigid_examples

LOOP = re.compile(r"^(\s*)for\s+\w+\s+in\s+range\(.*\)\s*:\s*$")


def timed_script(text, steps):
    """The example's command.py with N steps, no writes in the loop, and a clock around the loop."""
    text = re.sub(r"^nb_steps\s*=.*$", f"nb_steps = {steps}", text, flags=re.M)
    never = 10 * steps + 10
    text = re.sub(r"^freq_write\s*=.*$", f"freq_write = {never}", text, flags=re.M)
    text = re.sub(r"^freq_display\s*=.*$", f"freq_display = {never}", text, flags=re.M)
    lines = text.splitlines()
    out, k = [], 0
    while k < len(lines):
        m = LOOP.match(lines[k])
        if not m:
            out.append(lines[k])
            k += 1
            continue
        indent = m.group(1)
        out.append(f"{indent}import time as _side_by_side_clock")
        out.append(f"{indent}_side_by_side_start = _side_by_side_clock.perf_counter()")
        out.append(lines[k])
        k += 1
        while k < len(lines) and (not lines[k].strip() or lines[k].startswith(indent + " ") or
                                  lines[k].startswith(indent + "\t")):
            out.append(lines[k])
            k += 1
        out.append(f"{indent}print('SIDE_BY_SIDE_LOOP_SECONDS', "
                   f"_side_by_side_clock.perf_counter() - _side_by_side_start, flush=True)")
        out.extend(lines[k:])
        break
    return "\n".join(out) + "\n"


def run_lmgc90(work, lmgc90, steps):
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", PYTHONPATH=lmgc90)
    done = subprocess.run(["/usr/bin/python3", "command.py"], cwd=work, env=env, capture_output=True,
                          text=True, errors="replace")
    m = re.search(r"SIDE_BY_SIDE_LOOP_SECONDS\s+([0-9.eE+-]+)", done.stdout)
    if done.returncode != 0 or not m:
        raise RuntimeError(f"LMGC90 failed in {work}: {done.stderr[-400:]}")
    # The norm of each step's last check: LMGC90 prints "@ step = k", then each check's norms.
    last, current = [], None
    for line in done.stdout.splitlines():
        if "@ step =" in line and current is not None:
            last.append(current)
            current = None
        check = re.search(r"QuadDV  /QuadWR\s*=\s*([-+]?\d*\.\d+D[-+]\d+)", line)
        if check:
            current = float(check.group(1).replace("D", "E"))
    if current is not None:
        last.append(current)
    return float(m.group(1)) / steps, (statistics.median(last) if last else None)


def run_lmgc(work, build, steps):
    solve = os.path.join(build, "tools", "lmgc-solve")
    done = subprocess.run([solve, "--quiet", "--steps", str(steps), work], capture_output=True, text=True,
                          env=dict(os.environ, OMP_NUM_THREADS="1"))
    if done.returncode not in (0, 3):
        raise RuntimeError(f"lmgc-solve failed in {work}: {done.stderr[-400:]}")
    with open(os.path.join(work, "OUTBOX", "run_report.csv")) as f:
        rows = list(csv.DictReader(f))
    seconds = sum(float(r["step_seconds"]) for r in rows) / max(len(rows), 1)
    # quad_dv is QuadDV / (tol QuadWR), LMGC90's printed measure.
    checked = [float(r["quad_dv"]) for r in rows if int(r["contacts"]) > 0]
    return seconds, (statistics.median(checked) if checked else None)


def fmt(x, digits=3):
    return "—" if x is None else f"{x:.{digits}g}"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--lmgc90", default=os.path.join(os.path.dirname(ROOT), "lmgc90", "build"))
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--only")
    parser.add_argument("--csv")
    args = parser.parse_args()
    if not os.path.isdir(EXAMPLES):
        print(f"no examples at {EXAMPLES}")
        return 0
    scratch = tempfile.mkdtemp(prefix="lmgc_side_by_side_")
    print(f"{args.steps} steps, {args.rounds} interleaved rounds, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    print("| example | LMGC90 s/step (min / median) | lmgc s/step (min / median) | LMGC90 / lmgc (min / median) "
          "| check norm LMGC90 / lmgc |")
    print("| --- | --- | --- | --- | --- |")
    rows = []
    for case in rigid_examples(args.only):
        theirs, ours, ratios = [], [], []
        norm_theirs = norm_ours = None
        for k in range(args.rounds):
            order = ("lmgc90", "lmgc") if k % 2 == 0 else ("lmgc", "lmgc90")
            result = {}
            for which in order:
                work = os.path.join(scratch, which)
                prepare_case(os.path.join(EXAMPLES, case), work, lambda text: timed_script(text, args.steps))
                if which == "lmgc90":
                    result[which] = run_lmgc90(work, args.lmgc90, args.steps)
                else:
                    result[which] = run_lmgc(work, args.build, args.steps)
            theirs.append(result["lmgc90"][0])
            ours.append(result["lmgc"][0])
            ratios.append(result["lmgc90"][0] / result["lmgc"][0])
            norm_theirs, norm_ours = result["lmgc90"][1], result["lmgc"][1]
        row = [case, args.steps, args.rounds, min(theirs), statistics.median(theirs), min(ours),
               statistics.median(ours), min(ratios), statistics.median(ratios), norm_theirs, norm_ours]
        rows.append(row)
        print(f"| {case} | {row[3]:.4g} / {row[4]:.4g} | {row[5]:.4g} / {row[6]:.4g} | "
              f"{row[7]:.2f} / {row[8]:.2f} | {fmt(norm_theirs, 2)} / {fmt(norm_ours, 2)} |", flush=True)
    shutil.rmtree(scratch, ignore_errors=True)
    if args.csv:
        os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["example", "steps", "rounds", "lmgc90_s_per_step_min", "lmgc90_s_per_step_median",
                        "lmgc_s_per_step_min", "lmgc_s_per_step_median", "ratio_min", "ratio_median",
                        "lmgc90_check_norm_median", "lmgc_check_norm_median"])
            w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
