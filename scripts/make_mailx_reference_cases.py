#!/usr/bin/python3
"""Writes the MAILx reference cases of reference_cases/ (DATBOX/ and command.py) and, with
--lmgc90 BUILD, runs them with LMGC90 (its build folder on PYTHONPATH) to store what LMGC90 writes
in <case>/lmgc90_reference/ (DOF.LAST, GPV.LAST): the files the tests compare lmgc's with.

- mailx_patch_q4: nine distorted Q4xxx (plane strain, no mass) whose boundary nodes follow u = A x
  in one quasi-static step (θ = 1, h = 1): the patch test through the whole run.
- mailx_cantilever_t3: a T3xxx cantilever (plane stress, lumped mass, Rayleigh damping) clamped at
  one end and falling under gravity for 200 steps: the θ-scheme against LMGC90's.

Usage: scripts/make_mailx_reference_cases.py [--lmgc90 /work/lmgc90/build]
"""
import argparse
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import datbox_writer as w  # noqa: E402

A = [[1e-3, 2e-3], [-0.5e-3, 1.5e-3]]

LOOP = "for k in range(nb_steps):\n" + w.MAILX_STEP + """  chipy.WriteOut(freq_write)
  chipy.WritePostproFiles()
chipy.ClosePostproFiles()
chipy.WriteLastDof()
chipy.WriteLastGPV()
chipy.Finalize()
"""


def script(comment, mhyp, dt, theta, steps, freq_write, extra="", postpro=False):
    loop = LOOP if postpro else LOOP.replace("  chipy.WritePostproFiles()\n", "").replace("chipy.ClosePostproFiles()\n", "")
    opening = "chipy.OpenPostproFiles()\n" if postpro else ""
    return f"""{comment}
# Written by scripts/make_mailx_reference_cases.py; run unchanged by LMGC90 and by lmgc-run.
from pylmgc90 import chipy

dt = {dt!r}
theta = {theta!r}
nb_steps = {steps}
freq_write = {freq_write}

chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, {mhyp})
chipy.TimeEvolution_SetTimeStep(dt)
chipy.Integrator_InitTheta(theta)
chipy.ReadDatbox(deformable=True)
{opening}chipy.ComputeMass()
chipy.ComputeBulk()
{extra}""" + loop


def write(folder, files, text):
    if os.path.exists(os.path.join(folder, "DATBOX")):
        shutil.rmtree(os.path.join(folder, "DATBOX"))
    os.makedirs(os.path.join(folder, "DATBOX"))
    files = dict(files)
    files.setdefault("DOF.INI", w.STATE_HEADER)
    files.setdefault("GPV.INI", w.STATE_HEADER)
    for name, content in files.items():
        with open(os.path.join(folder, "DATBOX", name), "w") as f:
            f.write(content)
    with open(os.path.join(folder, "command.py"), "w") as f:
        f.write(text)


def patch_q4(folder):
    nodes, elements = w.mailx_rectangle(3, 3, 1.0, 1.0, "Q4xxx", distort=0.06)
    driven = {k + 1: [A[0][0] * x + A[0][1] * y, A[1][0] * x + A[1][1] * y]
              for k, (x, y, boundary) in enumerate(nodes) if boundary}
    write(folder, {"BODIES.DAT": w.mailx_bodies(nodes, elements, "Q4xxx", "M2DL_", "steel"),
                   "MODELS.DAT": w.mailx_model("M2DL_", "Q4xxx", lumped=False),
                   "BULK_BEHAV.DAT": w.elas_bulk("steel", 0.0, 1e9, 0.25),
                   "DRV_DOF.DAT": w.mailx_driven(driven)},
          script("# Patch test: nine distorted Q4xxx whose boundary follows u = A x in one quasi-static step.",
                 1, 1.0, 1.0, 1, 1))


def cantilever_t3(folder):
    nodes, elements = w.mailx_rectangle(10, 2, 1.0, 0.1, "T3xxx")
    driven = {k + 1: [0.0, 0.0] for k, (x, y, _) in enumerate(nodes) if x == 0.0}
    tip = [k + 1 for k, (x, y, _) in enumerate(nodes) if x == 1.0]
    clamp = sorted(driven)
    # NEW MECAx SETS (mailx-2d.md §8): sets, then per set its members, per member (body, count) and nodes.
    sets = f"{2:7d}\n"
    for nodes_of_set in (tip, clamp):
        sets += f"{1:7d}\n{1:7d} {len(nodes_of_set):7d}\n" + "".join(f"{n:7d}\n" for n in nodes_of_set)
    postpro = ("NEW MECAx SETS                :\nSTEP 1                        :\n" + sets +
               "Dep EVOLUTION                 :\nSTEP 1                        :\n"
               "Fint EVOLUTION                :\nSTEP 1                        :\nEND                           :\n")
    write(folder, {"POSTPRO.DAT": postpro,
                   "BODIES.DAT": w.mailx_bodies(nodes, elements, "T3xxx", "M2DT3", "rubbr"),
                   "MODELS.DAT": w.mailx_model("M2DT3", "T3xxx", lumped=True),
                   "BULK_BEHAV.DAT": w.elas_bulk("rubbr", 1000.0, 1e7, 0.3, gravity=(0.0, -9.81)),
                   "DRV_DOF.DAT": w.mailx_driven(driven)},
          script("# A T3xxx cantilever (plane stress, lumped mass) clamped at x = 0, falling under gravity.",
                 2, 1e-3, 0.5, 200, 50, extra="chipy.mecaMAILx_ComputeRayleighDamping(0.5, 1e-4)\n", postpro=True))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmgc90", default=None, help="LMGC90's build folder (pylmgc90 inside)")
    args = parser.parse_args()
    cases = {"mailx_patch_q4": patch_q4, "mailx_cantilever_t3": cantilever_t3}
    for name, make in cases.items():
        folder = os.path.join(ROOT, "reference_cases", name)
        make(folder)
        if not args.lmgc90:
            continue
        work = os.path.join("/tmp", "lmgc90_" + name)
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(folder, work, ignore=shutil.ignore_patterns("lmgc90_reference", "README.md"))
        subprocess.run([sys.executable, "command.py"], cwd=work, check=True, stdout=subprocess.DEVNULL,
                       env=dict(os.environ, PYTHONPATH=args.lmgc90, OMP_NUM_THREADS="1"))
        reference = os.path.join(folder, "lmgc90_reference")
        os.makedirs(reference, exist_ok=True)
        for f in ("DOF.LAST", "GPV.LAST"):
            shutil.copy(os.path.join(work, "OUTBOX", f), reference)
        for f in sorted(os.listdir(os.path.join(work, "POSTPRO"))):
            if f.startswith(("Dep_", "Fint_")):
                shutil.copy(os.path.join(work, "POSTPRO", f), reference)
        print(f"{name}: LMGC90's DOF.LAST and GPV.LAST stored in {reference}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
