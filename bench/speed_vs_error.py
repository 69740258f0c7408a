#!/usr/bin/python3
"""Time per step against achieved error for RIGID_2D/1024DK_BoxJC.

Starts from LMGC90's own state at step 400 of its reference run (DOF.OUT.4 and Vloc_Rloc.OUT.4
as DOF.INI and Vloc_Rloc.INI: a settled, loaded packing), then runs --steps steps of lmgc-solve
for each NLGS tolerance of the Quad norm (1e-2 ... 1e-8) with an iteration cap high enough to
reach it, and reports per tolerance: seconds per step, mean NLGS iterations, and the achieved
natural-map residual / |q| (median and worst over the steps). Writes a markdown table and a PNG
plot (matplotlib) of time per step against the median achieved residual.

Usage: bench/speed_vs_error.py [--build build/release] [--steps 50] [--out-dir bench/results/debian12-2core]
"""
import argparse
import gzip
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.environ.get("LMGC_SHARED_DIR", os.path.join(os.path.dirname(ROOT), "shared"))
CASE = os.path.join(SHARED, "lmgc90-examples", "RIGID_2D", "1024DK_BoxJC")


def copy_state(source, target):
    """Copies an LMGC90 state file, decompressing a .gz copy when that is what is stored."""
    if os.path.exists(source):
        shutil.copy(source, target)
    else:
        with gzip.open(source + ".gz", "rb") as f, open(target, "wb") as g:
            g.write(f.read())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--steps", type=int, default=50)
    parser.add_argument("--out-dir", default=os.path.join(ROOT, "bench", "results", "debian12-2core"))
    args = parser.parse_args()
    solve = os.path.join(args.build, "tools", "lmgc-solve")
    if not os.path.isdir(CASE):
        print(f"no example at {CASE}", file=sys.stderr)
        return 2
    rows = []
    for exponent in range(2, 9):
        tol = 10.0 ** -exponent
        work = tempfile.mkdtemp(prefix="lmgc_speed_error_")
        shutil.copytree(os.path.join(CASE, "DATBOX"), os.path.join(work, "DATBOX"))
        os.remove(os.path.join(work, "DATBOX", "COMMAND.DAT"))
        reference = os.path.join(CASE, "reference_lmgc90", "OUTBOX")
        copy_state(os.path.join(reference, "DOF.OUT.4"), os.path.join(work, "DATBOX", "DOF.INI"))
        copy_state(os.path.join(reference, "Vloc_Rloc.OUT.4"), os.path.join(work, "DATBOX", "Vloc_Rloc.INI"))
        subprocess.run([solve, work, "--quiet", "--steps", str(args.steps), "--dt", "2e-4", "--theta", "0.5",
                        "--norm", "Quad", "--tol", repr(tol), "--gs-it1", "50", "--gs-it2", "2000",
                        "--write-every", "0"], check=True)
        report = np.genfromtxt(os.path.join(work, "OUTBOX", "run_report.csv"), delimiter=",", names=True)
        shutil.rmtree(work)
        residual = report["residual_natural_map_over_q"]
        rows.append((tol, report["step_seconds"].mean(), report["iterations"].mean(), np.median(residual),
                     residual.max(), int((report["converged"] == 0).sum()), report["contacts"].mean()))
        print(f"tol {tol:.0e}: {rows[-1][1]:.4f} s/step, {rows[-1][2]:.0f} iterations, residual {rows[-1][3]:.2e}",
              file=sys.stderr)
    lines = ["| Quad tol | s/step | mean iterations | residual/‖q‖ median | worst | capped steps | contacts |",
             "|---|---|---|---|---|---|---|"]
    for tol, seconds, iterations, median, worst, capped, contacts in rows:
        lines.append(f"| {tol:.0e} | {seconds:.4f} | {iterations:.0f} | {median:.2e} | {worst:.2e} | {capped} "
                     f"| {contacts:.0f} |")
    table = "\n".join(lines) + "\n"
    print(table)
    os.makedirs(args.out_dir, exist_ok=True)
    with open(os.path.join(args.out_dir, "speed_vs_error_1024DK_BoxJC.md"), "w") as f:
        f.write(f"1024DK_BoxJC from LMGC90's step-400 state, {args.steps} steps per tolerance, dt 2e-4, "
                "gs_it1 50, gs_it2 2000, single thread.\n\n" + table)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.loglog([r[3] for r in rows], [r[1] for r in rows], "o-", label="lmgc-solve (NLGS, Quad norm)")
    for tol, seconds, _, median, *_ in rows:
        ax.annotate(f"tol {tol:.0e}", (median, seconds), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.axhline(0.0986, color="gray", linestyle="--", label="LMGC90 s/step (its run: tol 1e-5, capped 402/930)")
    ax.set_xlabel("achieved natural-map residual / ‖q‖ (median over steps)")
    ax.set_ylabel("seconds per step")
    ax.set_title("1024DK_BoxJC: time per step against achieved error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out_dir, "speed_vs_error_1024DK_BoxJC.png"), dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
