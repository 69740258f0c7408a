#!/usr/bin/python3
"""lmgc and LMGC90 side by side on deformable bodies in contact, in interleaved rounds, each code
running the same command.py with its time loop timed by the script itself (time.perf_counter around
the loop, written to loop_seconds.txt), peak memory read from the process's rusage (ru_maxrss).

Cases:
- 4cubes: LMGC90's example mecaMAILx_RIGID_2D/4cubes (../shared; its models use MatLib, so LMGC90
  must be built with --matlib), its own command.py with the timing lines added around its loop.
- 1q4-traction, mur, taylor, braudel: LMGC90's examples mecaMAILx_2D/1Q4-traction (one Q4xxx in large
  strain, MatLib's neo-Hookean material, 10000 steps of LMGC90's Newton loop; no contact),
  mecaMAILx_2D/mur (nine Q4P0x blocks, the same material, in contact on a JONCx, 1500 steps),
  taylor (216 Q4P0x, LMGC90's own J2 plasticity, axisymmetric, 2000 steps) and braudel (48 Q4P0x, J2
  with Swift hardening, 100 steps), their own command.py with the timing lines added around the loop.
- stack: a refined mesh of our own: two Q4xxx blocks (nx × ny cells each, plane strain, LMGC90's own
  elasticity 'isext no___') stacked on a JONCx under gravity, two CLxxx points per edge of each
  block's bottom (CLJCx for the lower, CLALp on the lower's top ALpxx for the upper), IQS_CLB,
  θ = 0.5, Stored_Delassus_Loops QM/16 1.666e-4 (4cubes' solver), LMGC90's precon W calls.

Reports per round the seconds per step of each code, their ratio, the peak resident memory of each,
the NLGS iterations of the run (SOLVER_INFORMATIONS: the same in both codes means the same achieved
residual at each check) and the largest DOF difference relative to the largest value; then the
minimum and median of the ratios.

Usage: bench/mailx_contact_side_by_side.py --lmgc90 /work/lmgc90/build --case 4cubes|1q4-traction|mur|taylor|braudel|stack
       [--nx 60] [--ny 20] [--steps 200] [--rounds 3] [--build build/release] [--csv FILE]
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

import datbox_writer as w

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = os.path.join(os.path.dirname(ROOT), "shared", "lmgc90-examples")
EXAMPLE = os.path.join(EXAMPLES, "mecaMAILx_RIGID_2D", "4cubes")
NEWTON_EXAMPLES = {"1q4-traction": ("1Q4-traction", 10000), "mur": ("mur", 1500), "taylor": ("taylor", 2000),
                   "braudel": ("braudel", 100)}

STACK_SCRIPT = """import time
from pylmgc90 import chipy
chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep(1e-3)
chipy.Integrator_InitTheta(0.5)
chipy.ReadDatbox(deformable=True)
chipy.OpenPostproFiles()
chipy.ComputeMass()
chipy.ComputeBulk()
chipy.mecaMAILx_SetPreconAllBodies()
chipy.CLxxx_PushPreconNodes()
chipy.ALpxx_PushPreconNodes()
chipy.mecaMAILx_ComputePreconW()
chipy.AssembleMechanicalLHS()
start = time.perf_counter()
for k in range({steps}):
  chipy.IncrementStep()
  chipy.ComputeFext()
  chipy.ComputeBulk()
  chipy.AssembleMechanicalRHS()
  chipy.ComputeFreeVelocity()
  chipy.SelectProxTactors()
  chipy.RecupRloc()
  chipy.ExSolver('Stored_Delassus_Loops         ', 'QM/16', 1.666e-4, 1.0, 50, 500)
  chipy.UpdateTactBehav()
  chipy.StockRloc()
  chipy.ComputeDof()
  chipy.UpdateStep()
  chipy.WritePostproFiles()
seconds = time.perf_counter() - start
chipy.ClosePostproFiles()
chipy.WriteLastDof()
chipy.Finalize()
open('loop_seconds.txt', 'w').write(repr(seconds))
"""


def block(nx, ny, x0, y0, width, height, body, color, model, behav):
    """One MAILx Q4xxx block with CLxxx on its bottom (two per edge, clockwise) and an ALpxx per
    edge of its top (clockwise: left to right)."""
    nodes, elements = w.mailx_rectangle(nx, ny, width, height, "Q4xxx")
    nodes = [(x + x0, y + y0, b) for x, y, b in nodes]
    text = w.mailx_bodies(nodes, elements, "Q4xxx", model, behav).replace(" MAILx      1", f" MAILx{body:7d}", 1)
    text = text[:-len("$$$$$$\n")] + "$tacty\n"
    bottom = [i + 1 for i in range(nx + 1)]  # row 0, left to right
    top = [ny * (nx + 1) + i + 1 for i in range(nx + 1)]
    rank = 0
    for i in range(nx, 0, -1):  # right to left along the bottom
        for apab in (0.2, 0.8):
            rank += 1
            text += w.clxxx(rank, color, bottom[i], bottom[i - 1], apab)
    for i in range(nx):
        rank += 1
        text += w.alpxx(rank, color, [top[i], top[i + 1]])
    return text + "$$$$$$\n"


def make_stack(folder, nx, ny, steps):
    gap = 1e-3
    height = 1.0 * ny / nx  # square cells
    bodies = (block(nx, ny, 0.0, gap, 1.0, height, 1, "LOWER", "M2DQ4", "rubbr") +
              block(nx, ny, 0.1, 2 * gap + height, 1.0, height, 2, "UPPER", "M2DQ4", "rubbr") +
              w.rbdy2(1, "tdurx", 0.5, -0.05, 0.0, w.joncx(2.0, 0.05)))
    tact = (f"$behav  lawty\n iqsc0  IQS_CLB                         fric={w.real(0.3)}\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" MAILx  CLxxx  LOWER  iqsc0  RBDY2  JONCx  WALLx      {w.real(0.01)}\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" MAILx  CLxxx  UPPER  iqsc0  MAILx  ALpxx  LOWER      {w.real(0.01)}\n")
    bulk = w.elas_bulk("rubbr", 1000.0, 1e7, 0.3, gravity=(0.0, -9.81)) + (
        f"\n$behav  lawty\n tdurx  RIGID                           Umas={w.real(1000.0)}\n")
    files = {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=True),
             "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": w.fixed([1]), "TACT_BEHAV.DAT": tact,
             "DOF.INI": w.STATE_HEADER, "GPV.INI": w.STATE_HEADER,
             "Vloc_Rloc.INI": w.STATE_HEADER.replace("! DOF", "! Vloc_Rloc"),
             "POSTPRO.DAT": "SOLVER INFORMATIONS           :\nSTEP 1                        :\nEND                           :\n"}
    os.makedirs(os.path.join(folder, "DATBOX"))
    for name, text in files.items():
        with open(os.path.join(folder, "DATBOX", name), "w") as f:
            f.write(text)
    with open(os.path.join(folder, "command.py"), "w") as f:
        f.write(STACK_SCRIPT.format(steps=steps))


def make_4cubes(folder):
    shutil.copytree(os.path.join(EXAMPLE, "DATBOX"), os.path.join(folder, "DATBOX"))
    script = open(os.path.join(EXAMPLE, "command.py")).read()
    # Time the loop as the stack's script does: the same lines in both codes.
    script = script.replace("for k in range(1, nb_steps + 1, 1):",
                            "import time\nstart = time.perf_counter()\nfor k in range(1, nb_steps + 1, 1):", 1)
    script = script.replace("# close display & postpro",
                            "open('loop_seconds.txt', 'w').write(repr(time.perf_counter() - start))\n"
                            "chipy.WriteLastDof()\n# close display & postpro", 1)
    with open(os.path.join(folder, "command.py"), "w") as f:
        f.write(script)
    return 500


def make_newton_example(folder, case):
    name, steps = NEWTON_EXAMPLES[case]
    example = os.path.join(EXAMPLES, "mecaMAILx_2D", name)
    shutil.copytree(os.path.join(example, "DATBOX"), os.path.join(folder, "DATBOX"))
    script = open(os.path.join(example, "command.py")).read()
    loop = "while chipy.TimeEvolution_GetTime() < t_final :"
    script = script.replace(loop, "import time\nstart = time.perf_counter()\n" + loop, 1)
    script = script.replace("# close display & postpro",
                            "open('loop_seconds.txt', 'w').write(repr(time.perf_counter() - start))\n"
                            "chipy.WriteLastDof()\n# close display & postpro", 1)
    with open(os.path.join(folder, "command.py"), "w") as f:
        f.write(script)
    return steps


def run(command, cwd, env):
    """Runs to the end; returns the peak resident memory in MiB."""
    process = subprocess.Popen(command, cwd=cwd, env=env, stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    if status != 0:
        raise RuntimeError(f"{command} failed in {cwd}")
    return usage.ru_maxrss / 1024.0


def numbers(path):
    return [float(t.replace("D", "E")) for t in re.findall(r"[-+]?\d*\.\d+D[-+]\d+", open(path).read())]


def iterations(folder):
    path = os.path.join(folder, "POSTPRO", "SOLVER_INFORMATIONS.DAT")
    return sum(int(line.split()[1]) for line in open(path) if line.strip()) if os.path.exists(path) else -1


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmgc90", required=True)
    parser.add_argument("--case", choices=("4cubes", "stack") + tuple(NEWTON_EXAMPLES), required=True)
    parser.add_argument("--nx", type=int, default=60)
    parser.add_argument("--ny", type=int, default=20)
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    parser.add_argument("--csv", default=None)
    args = parser.parse_args()
    scratch = tempfile.mkdtemp(prefix="lmgc_mailx_contact_bench_")
    source = os.path.join(scratch, "case")
    if args.case == "4cubes" or args.case in NEWTON_EXAMPLES:
        os.makedirs(source)
        steps = make_4cubes(source) if args.case == "4cubes" else make_newton_example(source, args.case)
    else:
        steps = args.steps
        make_stack(source, args.nx, args.ny, steps)
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    # Python's default buffering of a redirected stdout, as a user's shell has it (the scripts print a
    # message per call; an inherited PYTHONUNBUFFERED would make each a system call in lmgc-run only,
    # LMGC90's messages going through Fortran's buffered output).
    env.pop("PYTHONUNBUFFERED", None)
    rows = []
    for r in range(args.rounds):
        seconds, memory = {}, {}
        for code in (("lmgc", "lmgc90") if r % 2 == 0 else ("lmgc90", "lmgc")):
            work = os.path.join(scratch, code)
            shutil.rmtree(work, ignore_errors=True)
            shutil.copytree(source, work)
            if code == "lmgc":
                memory[code] = run([os.path.join(args.build, "tools", "lmgc-run"), work, "--quiet"], work, env)
            else:
                memory[code] = run([sys.executable, "command.py"], work, dict(env, PYTHONPATH=args.lmgc90))
            seconds[code] = float(open(os.path.join(work, "loop_seconds.txt")).read()) / steps
        a = numbers(os.path.join(scratch, "lmgc", "OUTBOX", "DOF.LAST"))
        b = numbers(os.path.join(scratch, "lmgc90", "OUTBOX", "DOF.LAST"))
        scale = max(abs(v) for v in b) or 1.0
        difference = max(abs(x - y) for x, y in zip(a, b)) / scale if len(a) == len(b) else float("nan")
        its = (iterations(os.path.join(scratch, "lmgc")), iterations(os.path.join(scratch, "lmgc90")))
        rows.append([r + 1, seconds["lmgc90"], seconds["lmgc"], seconds["lmgc90"] / seconds["lmgc"],
                     memory["lmgc90"], memory["lmgc"], its[1], its[0], difference])
        print(f"round {r + 1}: LMGC90 {seconds['lmgc90'] * 1e3:.3f} ms/step {memory['lmgc90']:.0f} MiB, "
              f"lmgc {seconds['lmgc'] * 1e3:.3f} ms/step {memory['lmgc']:.0f} MiB, speed-up {rows[-1][3]:.2f}, "
              f"NLGS iterations {its[1]} / {its[0]}, DOF.LAST difference {difference:.1e}", file=sys.stderr)
    ratios = [row[3] for row in rows]
    name = args.case if args.case != "stack" else f"stack of two {args.nx} × {args.ny} Q4xxx blocks"
    print("| case | steps | rounds | LMGC90 / lmgc per step, min | median | peak memory LMGC90 / lmgc (MiB) "
          "| NLGS iterations LMGC90 / lmgc | DOF.LAST largest difference |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    print(f"| {name} | {steps} | {args.rounds} | {min(ratios):.2f} | {statistics.median(ratios):.2f} | "
          f"{max(row[4] for row in rows):.0f} / {max(row[5] for row in rows):.0f} | {rows[-1][6]} / {rows[-1][7]} | "
          f"{max(row[8] for row in rows):.1e} |")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["round", "lmgc90_step_seconds", "lmgc_step_seconds", "speedup", "lmgc90_peak_mib",
                          "lmgc_peak_mib", "lmgc90_nlgs_iterations", "lmgc_nlgs_iterations",
                          "dof_last_relative_difference"])
            out.writerows(rows)
    shutil.rmtree(scratch)
    return 0


if __name__ == "__main__":
    sys.exit(main())
