#!/usr/bin/python3
"""lmgc and LMGC90 side by side on a refined linear elastic mesh without contact: a Q4xxx cantilever
(nx × ny cells, plane strain, consistent mass, clamped at x = 0, under gravity) run by the same
command.py in both codes, in interleaved rounds. The script times its own time loop
(time.perf_counter, written to loop_seconds.txt), so both codes are timed alike, Python calls
included. Reports per round the seconds per step of each and their ratio, the minimum and median of
the ratios, and whether the two DOF.LAST agree (largest difference relative to the largest
displacement).

Usage: bench/mailx_side_by_side.py --lmgc90 /work/lmgc90/build [--nx 200] [--ny 20] [--steps 200]
       [--rounds 3] [--build build/release] [--csv FILE]
"""
import argparse
import csv
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

import datbox_writer as w

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SCRIPT = """import time
from pylmgc90 import chipy
chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep({dt!r})
chipy.Integrator_InitTheta(0.5)
chipy.ReadDatbox(deformable=True)
chipy.ComputeMass()
chipy.ComputeBulk()
start = time.perf_counter()
for k in range({steps}):
{step}seconds = time.perf_counter() - start
chipy.WriteLastDof()
chipy.Finalize()
open('loop_seconds.txt', 'w').write(repr(seconds))
"""


def make_case(folder, nx, ny, steps):
    nodes, elements = w.mailx_rectangle(nx, ny, 10.0, 1.0, "Q4xxx")
    driven = {k + 1: [0.0, 0.0] for k, (x, y, _) in enumerate(nodes) if x == 0.0}
    os.makedirs(os.path.join(folder, "DATBOX"))
    files = {"BODIES.DAT": w.mailx_bodies(nodes, elements, "Q4xxx", "M2DQ4", "steel"),
             "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=False),
             "BULK_BEHAV.DAT": w.elas_bulk("steel", 7800.0, 2e11, 0.3, gravity=(0.0, -9.81)),
             "DRV_DOF.DAT": w.mailx_driven(driven), "DOF.INI": w.STATE_HEADER, "GPV.INI": w.STATE_HEADER}
    for name, text in files.items():
        with open(os.path.join(folder, "DATBOX", name), "w") as f:
            f.write(text)
    with open(os.path.join(folder, "command.py"), "w") as f:
        f.write(SCRIPT.format(dt=1e-4, steps=steps, step=w.MAILX_STEP))


def dof_values(path):
    values = []
    for line in open(path):
        for field in line.replace("D", "E").split():
            try:
                values.append(float(field.split("=")[-1]) if "=" in field else float(field))
            except ValueError:
                pass
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmgc90", required=True)
    parser.add_argument("--nx", type=int, default=200)
    parser.add_argument("--ny", type=int, default=20)
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--csv", default=None)
    args = parser.parse_args()
    scratch = tempfile.mkdtemp(prefix="lmgc_mailx_bench_")
    source = os.path.join(scratch, "case")
    make_case(source, args.nx, args.ny, args.steps)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    rows = []
    for r in range(args.rounds):
        seconds = {}
        for code in (("lmgc", "lmgc90") if r % 2 == 0 else ("lmgc90", "lmgc")):
            work = os.path.join(scratch, code)
            shutil.rmtree(work, ignore_errors=True)
            shutil.copytree(source, work)
            if code == "lmgc":
                command = [os.path.join(args.build, "tools", "lmgc-run"), work, "--quiet"]
                subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
            else:
                subprocess.run([sys.executable, "command.py"], cwd=work, check=True, stdout=subprocess.DEVNULL,
                               env=dict(env, PYTHONPATH=args.lmgc90))
            seconds[code] = float(open(os.path.join(work, "loop_seconds.txt")).read()) / args.steps
        a = dof_values(os.path.join(scratch, "lmgc", "OUTBOX", "DOF.LAST"))
        b = dof_values(os.path.join(scratch, "lmgc90", "OUTBOX", "DOF.LAST"))
        scale = max(abs(v) for v in b) or 1.0
        difference = max(abs(x - y) for x, y in zip(a, b)) / scale if len(a) == len(b) else float("nan")
        rows.append([r + 1, seconds["lmgc90"], seconds["lmgc"], seconds["lmgc90"] / seconds["lmgc"], difference])
        print(f"round {r + 1}: LMGC90 {seconds['lmgc90']:.5f} s/step, lmgc {seconds['lmgc']:.5f} s/step, "
              f"speed-up {rows[-1][3]:.2f}, DOF.LAST relative difference {difference:.1e}", file=sys.stderr)
    ratios = [row[3] for row in rows]
    nodes = (args.nx + 1) * (args.ny + 1)
    print("| mesh | dofs | steps | rounds | LMGC90 / lmgc per step, min | median | DOF.LAST largest difference |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    print(f"| {args.nx} × {args.ny} Q4xxx | {2 * nodes} | {args.steps} | {args.rounds} | {min(ratios):.2f} | "
          f"{statistics.median(ratios):.2f} | {max(row[4] for row in rows):.1e} |")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["round", "lmgc90_step_seconds", "lmgc_step_seconds", "speedup", "dof_last_relative_difference"])
            out.writerows(rows)
    shutil.rmtree(scratch)
    return 0


if __name__ == "__main__":
    sys.exit(main())
