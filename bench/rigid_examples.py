#!/usr/bin/python3
"""Speed and achieved error of lmgc on LMGC90's RIGID_2D or RIGID_3D examples, against LMGC90's own run.

For every example with reference_lmgc90/RUN.md: runs the example's own command.py, unchanged, with
lmgc's chipy module (lmgc-run --max-steps: the number of steps LMGC90 ran, or --steps-cap), then
reads OUTBOX/run_report.csv and prints one markdown table row: seconds per step (from IncrementStep
to UpdateStep: the script's writes between steps are not counted, as in LMGC90's figure), NLGS sweep
rate (contact updates per second = sum(sweeps run x contacts) / time in the sweeps, the time
LMGC90's "[NLGS2] iter" timer counts), mean NLGS iterations (as LMGC90 counts them) and the share of
them run (3D skips the rest of a block whose sweeps stand still), steps that hit the iteration cap,
and the achieved natural-map residual / |q| (median and worst over the steps with contacts), next
to LMGC90's seconds per step, sweep rate and unconverged steps from RUN.md. Single thread. The
script runs with `--norand` absent, as LMGC90's reference runs did.

Usage: bench/rigid_examples.py [--dimension 2|3] [--build build/release] [--steps-cap N] [--only NAME]
       [--out FILE]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = os.environ.get("LMGC_SHARED_DIR", os.path.join(os.path.dirname(ROOT), "shared"))
EXAMPLES = os.path.join(EXAMPLES, "lmgc90-examples")


def run_md(case):
    text = open(os.path.join(case, "reference_lmgc90", "RUN.md")).read()
    params = dict(re.findall(r"`(\w+) = ([^`]+)`", text.split("script parameters", 1)[1].split("\n", 1)[0]))
    params = {k: v.strip("'").strip() for k, v in params.items()}

    def row(label):
        m = re.search(r"^\| " + re.escape(label) + r"[^|]*\| (.+?) \|$", text, re.M)
        return m.group(1) if m else ""

    steps = int(row("steps run").split()[0])
    per_step = float(row("wall time per step").split()[0])
    rate = re.search(r"= ([0-9.e+]+) updates/s", text)
    unconverged = re.search(r"\| (\d+) of (\d+) steps with contacts", text)
    return params, steps, per_step, float(rate.group(1)) if rate else float("nan"), (
        f"{unconverged.group(1)}/{unconverged.group(2)}" if unconverged else "")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dimension", type=int, choices=(2, 3), default=2)
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--steps-cap", type=int, default=None)
    parser.add_argument("--only", default=None)
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    run = os.path.join(args.build, "tools", "lmgc-run")
    if not os.path.exists(run):
        print(f"no {run}: this build has no Python module (python3-dev, pybind11-dev)", file=sys.stderr)
        return 2
    examples = os.path.join(EXAMPLES, f"RIGID_{args.dimension}D")
    if not os.path.isdir(examples):
        print(f"no examples at {examples}", file=sys.stderr)
        return 2
    header = ("| example | steps | lmgc s/step | LMGC90 s/step | speed-up | lmgc updates/s | LMGC90 updates/s "
              "| mean iterations | sweeps run | capped steps (lmgc / LMGC90) | residual/‖q‖ median | worst |")
    lines = [header, "|" + "---|" * header.count("|")[:-1] if False else "|" + "---|" * (header.count("|") - 1)]
    for name in sorted(os.listdir(examples)):
        case = os.path.join(examples, name)
        if args.only and name != args.only:
            continue
        if not os.path.exists(os.path.join(case, "reference_lmgc90", "RUN.md")):
            continue
        params, steps, lmgc90_per_step, lmgc90_rate, lmgc90_capped = run_md(case)
        if args.steps_cap:
            steps = min(steps, args.steps_cap)
        work = tempfile.mkdtemp(prefix="lmgc_bench_")
        shutil.copytree(os.path.join(case, "DATBOX"), os.path.join(work, "DATBOX"))
        shutil.copy(os.path.join(case, "command.py"), work)
        command = [run, work, "--quiet", "--max-steps", str(steps)]
        start = time.perf_counter()
        subprocess.run(command, check=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
        wall = time.perf_counter() - start
        report = np.genfromtxt(os.path.join(work, "OUTBOX", "run_report.csv"), delimiter=",", names=True)
        shutil.rmtree(work)
        contacts, iterations = report["contacts"], report["iterations"]
        with_contacts = contacts > 0
        per_step = report["step_seconds"].mean()
        # Sweeps alone, as LMGC90's rate in RUN.md ("[NLGS2] iter" of TIMER.OUT: scramble and
        # sweeps, no set-up, checks or post pass).
        sweeps = report["sweep_seconds"].sum()
        # Sweeps run: the counted iterations less those skipped once the iterates stood still (3D).
        skipped = report["sweeps_skipped"] if "sweeps_skipped" in report.dtype.names else 0 * iterations
        run = iterations - skipped
        rate = (run * contacts).sum() / sweeps if sweeps > 0 else float("nan")
        run_share = run[with_contacts].sum() / max(iterations[with_contacts].sum(), 1)
        capped = int(((report["converged"] == 0) & with_contacts).sum())
        residual = report["residual_natural_map_over_q"][with_contacts]
        median = np.median(residual) if residual.size else 0.0
        worst = residual.max() if residual.size else 0.0
        lines.append(
            f"| {name} | {steps} | {per_step:.3g} | {lmgc90_per_step:.3g} | {lmgc90_per_step / per_step:.1f}x "
            f"| {rate:.3g} | {lmgc90_rate:.3g} | {iterations[with_contacts].mean() if with_contacts.any() else 0:.0f} "
            f"| {100 * run_share:.0f}% "
            f"| {capped}/{int(with_contacts.sum())} / {lmgc90_capped} | {median:.2e} | {worst:.2e} |")
        print(lines[-1], f"(wall {wall:.1f} s)", file=sys.stderr)
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
