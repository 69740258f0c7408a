#!/usr/bin/python3
"""Writes the MAILx reference cases of reference_cases/ (DATBOX/ and command.py) and, with
--lmgc90 BUILD, runs them with LMGC90 (its build folder on PYTHONPATH) to store what LMGC90 writes
in <case>/lmgc90_reference/ (DOF.LAST, GPV.LAST): the files the tests compare lmgc's with.

- mailx_patch_q4: nine distorted Q4xxx (plane strain, no mass) whose boundary nodes follow u = A x
  in one quasi-static step (θ = 1, h = 1): the patch test through the whole run.
- mailx_cantilever_t3: a T3xxx cantilever (plane stress, lumped mass, Rayleigh damping) clamped at
  one end and falling under gravity for 200 steps: the θ-scheme against LMGC90's.
- mailx_disk_on_block: a rigid DISKx rolling and sliding on an elastic Q4xxx block whose top is one
  ALpxx polyline ('+ALpxx' lines), under a tilted gravity (DKALp): against LMGC90.
- mailx_block_on_wall: an elastic Q4xxx block landing and sliding on a JONCx (CLJCx, GAP_SGR_CLB)
  under a tilted gravity: against LMGC90.
- mailx_glued_blocks: an elastic block glued on another (COUPLED_DOF on CLALp pairs) whose bottom is
  clamped, sheared by a tilted gravity: against LMGC90.
- mailx_neo_hookean_stretch: a square of 2 × 2 Q4xxx in large strain (MatLib's neo-Hookean material)
  stretched by 50 % in 20 quasi-static steps of LMGC90's Newton loop: P22 against the closed form of
  plane-strain uniaxial stress, and against LMGC90.
- mailx_adaptive_stretch: the same square stretched in large steps with few Newton iterations
  allowed: LMGC90's adaptive time step cuts steps and grows them back; the steps, their time steps
  and the final state against LMGC90's.
- mailx_rotated_at_rest: the same square at rest, rotated by 90° in DOF.INI: its stresses stay at
  round-off (frame invariance), against LMGC90 too.
- mailx_j2_traction_linear, mailx_j2_traction_swift: the square of 2 × 2 Q4P0x with LMGC90's own
  J2 plasticity (linear and Swift hardening) stretched by 20 % in plane strain: at every plastic
  Gauss point q = σ_y(p), and against LMGC90.
- mailx_hertz_cylinder: an elastic half-cylinder (T3xxx, plane strain) pressed by a line load on a
  rigid JONCx, frictionless CLJCx contacts: the contact half-width and the peak pressure against
  Hertz's (compared with the closed form, not run by LMGC90 here).

- mailx_mac_czm_blocks, mailx_mal_czm_blocks, mailx_gap_mohr_blocks, mailx_gap_wet_blocks: two elastic
  blocks bonded at their interface (CLALp) by MAC_CZM, MAL_CZM, GAP_MOHR_DS_CLB or GAP_WET_DS_CLB,
  pressed, then pulled apart and sheared by the upper block's top: against LMGC90.

- mailx_glued_points: two elastic blocks side by side glued node to node by COUPLED_DOF on P2P2L pairs
  of coinciding PT2DL points, bent by gravity: against LMGC90.
- mailx_disk_on_diskl: a rigid DISKx landing and sliding on the DISKL arcs of an elastic block
  (DKDKL): against LMGC90.

Usage: scripts/make_mailx_reference_cases.py [--lmgc90 /work/lmgc90/build]
"""
import argparse
import math
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
    if "TACT_BEHAV.DAT" in files:  # LMGC90 reads it whenever there are laws
        files.setdefault("Vloc_Rloc.INI", w.STATE_HEADER.replace("! DOF", "! Vloc_Rloc"))
    for name, content in files.items():
        with open(os.path.join(folder, "DATBOX", name), "w") as f:
            f.write(content)
    with open(os.path.join(folder, "command.py"), "w") as f:
        f.write(text)


def contact_script(comment, dt, theta, steps, tolerance, gs_it2):
    """command.py of a case with contacts: LMGC90's linear driver sequence, the NLGS
    (Stored_Delassus_Loops, Quad, tolerance, 50 sweeps a check, gs_it2 checks), the last DOF and
    Vloc_Rloc files. dt, theta and tolerance are the script's literals (strings)."""
    return f"""{comment}
# Written by scripts/make_mailx_reference_cases.py; run unchanged by LMGC90 and by lmgc-run.
from pylmgc90 import chipy

chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep({dt})
chipy.Integrator_InitTheta({theta})
chipy.ReadDatbox(deformable=True)
chipy.ComputeMass()
chipy.ComputeBulk()
nb_steps = {steps}
for k in range(nb_steps):
  chipy.IncrementStep()
  chipy.ComputeFext()
  chipy.ComputeBulk()
  chipy.AssembleMechanicalRHS()
  chipy.AssembleMechanicalLHS()
  chipy.ComputeFreeVelocity()
  chipy.SelectProxTactors()
  chipy.RecupRloc()
  chipy.ExSolver('Stored_Delassus_Loops         ', 'Quad ', {tolerance}, 1.0, 50, {gs_it2})
  chipy.UpdateTactBehav()
  chipy.StockRloc()
  chipy.ComputeDof()
  chipy.UpdateStep()
chipy.WriteLastDof()
chipy.WriteLastVlocRloc()
chipy.Finalize()
"""


def newton_script(comment, dt, theta, t_final, dt_min, dt_max, max_iter, patience, tol):
    """command.py of a large-strain case without contact: LMGC90's Newton loop and adaptive step (the
    sequence of its example 1Q4-traction); each step's time step, iterations and ComputeTimeStep
    state go to steps.txt."""
    return f"""{comment}
# Written by scripts/make_mailx_reference_cases.py; run unchanged by LMGC90 and by lmgc-run.
from pylmgc90 import chipy

chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep({dt!r})
chipy.Integrator_InitTheta({theta!r})
chipy.NewtonRaphson_SetFinalTime({t_final!r})
chipy.NewtonRaphson_SetMinTimeStep({dt_min!r})
chipy.NewtonRaphson_SetMaxTimeStep({dt_max!r})
chipy.NewtonRaphson_SetMaxIter({max_iter})
chipy.NewtonRaphson_SetIncPatience({patience})
chipy.ReadDatbox(deformable=True)
chipy.ComputeMass()
log = open('steps.txt', 'w')
while chipy.TimeEvolution_GetTime() < {t_final!r}:
  chipy.IncrementStep()
  chipy.ComputeFext()
  chipy.NewtonRaphson_Initialize({tol!r})
  is_converged = 1
  k = 0
  while is_converged == 1:
    k += 1
    chipy.ComputeBulk()
    chipy.AssembleMechanicalRHS()
    chipy.AssembleMechanicalLHS()
    chipy.ComputeFreeVelocity()
    chipy.ComputeDof()
    if k > 1:
      is_converged = chipy.NewtonRaphson_CheckConvergence(chipy.mecaMAILx_ComputeResidueNorm())
  h = chipy.TimeEvolution_GetTimeStep()
  istate = chipy.NewtonRaphson_ComputeTimeStep()
  log.write('%d %.6e %d %d\\n' % (chipy.TimeEvolution_GetStep(), h, k, istate))
  if not istate == 1:
    chipy.UpdateStep()
    chipy.WriteOut(5)
    if istate == 2:
      break
log.close()
chipy.WriteLastDof()
chipy.WriteLastGPV()
chipy.Finalize()
"""


def square_case(folder, script_text, dof_ini=None, material=None):
    """The unit square of 2 × 2 Q4xxx (E = 1e6 Pa, ν = 0.3, ρ = 1 kg/m², plane strain, MatLib's
    neo-Hookean), its bottom held vertically (the corner (0, 0) also horizontally) and its top pulled
    up at 0.5 m/s, unless dof_ini holds it at rest elsewhere."""
    nodes, elements = w.mailx_rectangle(2, 2, 1.0, 1.0, "Q4xxx")
    files = {"BODIES.DAT": w.mailx_bodies(nodes, elements, "Q4xxx", "M2DNL", "rubbr"),
             "MODELS.DAT": w.mailx_model_neo_hookean("M2DNL", "Q4xxx"),
             "BULK_BEHAV.DAT": w.elas_bulk("rubbr", 1.0, 1e6, 0.3)}
    if material is not None:  # (hardening, coefficients): LMGC90's own J2 plasticity on Q4P0x
        files["MODELS.DAT"] = w.mailx_model_j2("M2DNL")
        files["BULK_BEHAV.DAT"] = w.elas_plas_bulk("rubbr", 1.0, 1e6, 0.3, *material)
    if dof_ini is None:
        driven = {}
        for k, (x, y, _) in enumerate(nodes):
            if y == 0.0:
                driven[k + 1] = [0.0 if x == 0.0 else None, 0.0]
            elif y == 1.0:
                driven[k + 1] = [None, 0.5]
        files["DRV_DOF.DAT"] = w.mailx_driven(driven)
    else:
        files["DRV_DOF.DAT"] = "$$$$$$\n"
        files["DOF.INI"] = dof_ini(nodes)
    write(folder, files, script_text)


def neo_hookean_stretch(folder):
    square_case(folder, newton_script(
        "# A 2 x 2 Q4xxx square (neo-Hookean) stretched by 50 % in 20 quasi-static steps.",
        0.05, 1.0, 1.0, 0.05, 0.05, 20, 9999999, 1e-10))


def adaptive_stretch(folder):
    square_case(folder, newton_script(
        "# The square stretched in large steps, 4 Newton iterations allowed: the step is cut and grows back.",
        0.25, 1.0, 1.0, 1e-3, 0.25, 4, 2, 1e-10))


def rotated_at_rest(folder):
    def dof_ini(nodes):
        text = w.STATE_HEADER + "$bdyty\n MAILx      1\n$model\n MECAx\n$nodty\n"
        for k, (x, y, _) in enumerate(nodes):  # X = R x − x, R the rotation by 90°
            text += (f" NO2xx{k + 1:7d}                X(1)={w.real(-y - x)}  X(2)={w.real(x - y)}\n"
                     f"                             V(1)={w.real(0.0)}  V(2)={w.real(0.0)}\n")
        return text + "$$$$$$\n"
    square_case(folder, newton_script(
        "# The square at rest, rotated by 90 degrees: no stress (frame invariance).",
        0.05, 0.5, 0.5, 0.05, 0.05, 20, 9999999, 1e-10), dof_ini=dof_ini)


def j2_traction(hardening, coefficients):
    def make(folder):
        square_case(folder, newton_script(
            f"# The square of Q4P0x (J2 plasticity, {hardening} hardening) stretched by 20 % in 20 steps.",
            0.02, 1.0, 0.4, 0.02, 0.02, 20, 9999999, 1e-10), material=(hardening, coefficients))
    return make


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


def disk_on_block(folder):
    nx, ny, length, height = 20, 4, 1.0, 0.2
    nodes, elements = w.mailx_rectangle(nx, ny, length, height, "Q4xxx")
    clamp = {k + 1: [0.0, 0.0] for k, (x, y, _) in enumerate(nodes) if y == 0.0}
    top = [ny * (nx + 1) + i + 1 for i in range(nx + 1)]  # left to right: clockwise along the top
    bodies = w.mailx_bodies(nodes, elements, "Q4xxx", "M2DQ4", "rubbr")[:-len("$$$$$$\n")] + "$tacty\n"
    bodies += w.alpxx(1, "BLOCK", top)
    radius = 0.05
    bodies += "$$$$$$\n" + w.rbdy2(1, "steel", 0.2, height + radius + 1e-3, 0.0, w.disk(radius, "DISKS"))
    bulk = w.elas_bulk("rubbr", 1000.0, 1e7, 0.3, gravity=(3.0, -9.81)) + (
        f"\n$behav  lawty\n steel  RIGID                           Umas={w.real(7800.0)}\n")
    tact = (f"$behav  lawty\n iqsc0  IQS_CLB                         fric={w.real(0.3)}\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" RBDY2  DISKx  DISKS  iqsc0  MAILx  ALpxx  BLOCK      {w.real(0.01)}\n")
    text = contact_script(
        "# A rigid disk rolling and sliding on an elastic block (DKALp), under a tilted gravity.",
        "1e-3", "0.5", 300, "1e-6", 200)
    write(folder, {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=True),
                   "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": w.mailx_driven(clamp), "TACT_BEHAV.DAT": tact}, text)


def block_on_wall(folder):
    nx, ny, length, height = 8, 2, 0.4, 0.1
    nodes, elements = w.mailx_rectangle(nx, ny, length, height, "Q4xxx")
    nodes = [(x, y + 2e-3, b) for x, y, b in nodes]
    bottom = [i + 1 for i in range(nx + 1)]
    bodies = w.mailx_bodies(nodes, elements, "Q4xxx", "M2DQ4", "rubbr")[:-len("$$$$$$\n")] + "$tacty\n"
    rank = 0
    for i in range(nx, 0, -1):  # right to left along the bottom: clockwise
        for apab in (0.2, 0.8):
            rank += 1
            bodies += w.clxxx(rank, "BLOCK", bottom[i], bottom[i - 1], apab)
    bodies += "$$$$$$\n" + w.rbdy2(1, "tdurx", 0.5, -0.05, 0.0, w.joncx(1.0, 0.05))
    bulk = w.elas_bulk("rubbr", 1000.0, 1e6, 0.3, gravity=(4.0, -9.81)) + (
        f"\n$behav  lawty\n tdurx  RIGID                           Umas={w.real(1000.0)}\n")
    tact = (f"$behav  lawty\n gapc0  GAP_SGR_CLB                     fric={w.real(0.3)}\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" MAILx  CLxxx  BLOCK  gapc0  RBDY2  JONCx  WALLx      {w.real(0.01)}\n")
    text = contact_script(
        "# An elastic block landing and sliding on a rigid JONCx (CLJCx, GAP_SGR_CLB), tilted gravity.",
        "1e-3", "0.5", 200, "1e-8", 400)
    write(folder, {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=True),
                   "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": w.fixed([1]), "TACT_BEHAV.DAT": tact}, text)


def glued_blocks(folder):
    nx, ny, length, height = 10, 3, 1.0, 0.3
    lower_nodes, elements = w.mailx_rectangle(nx, ny, length, height, "Q4xxx")
    upper_nodes = [(x, y + height, b) for x, y, b in lower_nodes]
    clamp = {k + 1: [0.0, 0.0] for k, (x, y, _) in enumerate(lower_nodes) if y == 0.0}
    top = [ny * (nx + 1) + i + 1 for i in range(nx + 1)]
    bottom = [i + 1 for i in range(nx + 1)]
    lower = w.mailx_bodies(lower_nodes, elements, "Q4xxx", "M2DQ4", "rubbr")[:-len("$$$$$$\n")] + "$tacty\n"
    lower += w.alpxx(1, "LOWER", top)
    upper = w.mailx_bodies(upper_nodes, elements, "Q4xxx", "M2DQ4", "rubbr").replace(" MAILx      1", " MAILx      2", 1)
    upper = upper[:-len("$$$$$$\n")] + "$tacty\n"
    for k, i in enumerate(range(nx, 0, -1)):  # right to left along the bottom: clockwise
        upper += w.clxxx(k + 1, "UPPER", bottom[i], bottom[i - 1], 0.5)
    bodies = lower + "$$$$$$\n" + upper + "$$$$$$\n"
    bulk = w.elas_bulk("rubbr", 1000.0, 1e6, 0.3, gravity=(5.0, -9.81))
    tact = ("$behav  lawty\n glued  COUPLED_DOF\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" MAILx  CLxxx  UPPER  glued  MAILx  ALpxx  LOWER      {w.real(0.01)}\n")
    text = contact_script(
        "# An elastic block glued on another (COUPLED_DOF on CLALp), sheared by a tilted gravity.",
        "1e-3", "0.5", 100, "1e-8", 400)
    write(folder, {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=True),
                   "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": w.mailx_driven(clamp), "TACT_BEHAV.DAT": tact}, text)


def cohesive_blocks(law, rows, steps=400):
    """Two elastic blocks of 4 × 2 Q4xxx, one on the other, bonded at their interface by the 2D
    cohesive law `law` on CLALp pairs (the upper block's bottom edges, two CLxxx points each, on the
    lower block's top ALpxx). The lower block's bottom is clamped; the upper block's top nodes move
    at vx = 2.5 mm/s and vy = 5 − 10 cos(2πt/0.6) mm/s: the interface is pressed first, then opened
    and sheared."""
    def make(folder):
        nx, ny, length, height = 4, 2, 0.4, 0.1
        lower_nodes, elements = w.mailx_rectangle(nx, ny, length, height, "Q4xxx")
        upper_nodes = [(x, y + height, b) for x, y, b in lower_nodes]
        bottom = [i + 1 for i in range(nx + 1)]
        top = [ny * (nx + 1) + i + 1 for i in range(nx + 1)]
        lower = w.mailx_bodies(lower_nodes, elements, "Q4xxx", "M2DQ4", "rock_")[:-len("$$$$$$\n")] + "$tacty\n"
        lower += w.alpxx(1, "LOWER", top)
        upper = w.mailx_bodies(upper_nodes, elements, "Q4xxx", "M2DQ4", "rock_").replace(" MAILx      1", " MAILx      2", 1)
        upper = upper[:-len("$$$$$$\n")] + "$tacty\n"
        rank = 0
        for i in range(nx, 0, -1):  # right to left along the bottom: clockwise
            for apab in (0.25, 0.75):
                rank += 1
                upper += w.clxxx(rank, "UPPER", bottom[i], bottom[i - 1], apab)
        bodies = lower + "$$$$$$\n" + upper + "$$$$$$\n"
        bulk = w.elas_bulk("rock_", 2500.0, 1e7, 0.25)
        omega = 2.0 * math.pi / 0.6
        driven = (w.mailx_driven({n: [0.0, 0.0] for n in bottom}, body=1) +
                  w.mailx_driven({n: [2.5e-3, (5e-3, -1e-2, omega, 0.0)] for n in top}, body=2))
        tact = (w.tact_law("czm01", law, rows) + "\n"
                "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
                f" MAILx  CLxxx  UPPER  czm01  MAILx  ALpxx  LOWER      {w.real(0.005)}\n")
        text = contact_script(
            f"# Two elastic blocks bonded by {law} (CLALp), pressed, then pulled apart and sheared.",
            "1e-3", "0.5", steps, "1e-10", 400)
        write(folder, {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=True),
                       "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": driven, "TACT_BEHAV.DAT": tact}, text)
    return make


def pt2dl(rank, color, noda, nodb, apab, plus=False):
    """A MAILx '$tacty' PT2DL line: the point at apab from noda on (noda, nodb)."""
    return f"{'+' if plus else ' '}PT2DL{rank:7d}  color  {color}  noda={noda:5d}  nodb={nodb:5d}  apab={w.real(apab)}\n"


def glued_points(folder):
    """Two elastic blocks side by side whose facing edges share their nodes' positions, glued node to
    node by COUPLED_DOF on P2P2L pairs of PT2DL points; the left block's left edge clamped, a tilted
    gravity bends the pair."""
    nx, ny, length, height = 4, 2, 0.2, 0.1
    left_nodes, elements = w.mailx_rectangle(nx, ny, length, height, "Q4xxx")
    right_nodes = [(x + length, y, b) for x, y, b in left_nodes]
    clamp = {k + 1: [0.0, 0.0] for k, (x, y, _) in enumerate(left_nodes) if x == 0.0}
    right_edge = [j * (nx + 1) + nx + 1 for j in range(ny + 1)]  # bottom to top
    left_edge = [j * (nx + 1) + 1 for j in range(ny + 1)]
    def points(edge, color):
        out = ""
        for k, node in enumerate(edge):  # one point per node: apab 0 on its edge, 1 for the last
            other, apab = (edge[k + 1], 0.0) if k + 1 < len(edge) else (edge[k - 1], 0.0)
            out += pt2dl(k + 1, color, node, other, apab)
        return out
    left = w.mailx_bodies(left_nodes, elements, "Q4xxx", "M2DQ4", "rubbr")[:-len("$$$$$$\n")] + "$tacty\n"
    left += points(right_edge, "LEFTx")
    right = w.mailx_bodies(right_nodes, elements, "Q4xxx", "M2DQ4", "rubbr").replace(" MAILx      1", " MAILx      2", 1)
    right = right[:-len("$$$$$$\n")] + "$tacty\n" + points(left_edge, "RIGHT")
    bodies = left + "$$$$$$\n" + right + "$$$$$$\n"
    bulk = w.elas_bulk("rubbr", 1000.0, 1e6, 0.3, gravity=(2.0, -9.81))
    tact = ("$behav  lawty\n glued  COUPLED_DOF\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" MAILx  PT2DL  LEFTx  glued  MAILx  PT2DL  RIGHT      {w.real(0.01)}\n")
    text = contact_script(
        "# Two elastic blocks glued node to node (COUPLED_DOF on P2P2L pairs of PT2DL), bent by gravity.",
        "1e-3", "0.5", 150, "1e-10", 400)
    write(folder, {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=True),
                   "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": w.mailx_driven(clamp), "TACT_BEHAV.DAT": tact}, text)


def diskl(rank, color, noda, nodb, apab, height, half_chord):
    """A MAILx '$tacty' DISKL line: the disk through the arc of sagitta `height` and half chord
    `half_chord` over the point at apab on the edge (noda, nodb), bulging to the edge's left."""
    return (f" DISKL{rank:7d}  color  {color}  noda={noda:5d}  nodb={nodb:5d}  apab={w.real(apab)}"
            f"  bdyr={w.real(height)}  brpm={w.real(half_chord)}\n")


def disk_on_diskl(folder):
    """A rigid DISKx landing and rolling on the arcs (DISKL) carried by the top edges of an elastic
    block (DKDKL), under a tilted gravity."""
    nx, ny, length, height = 4, 1, 0.4, 0.1
    nodes, elements = w.mailx_rectangle(nx, ny, length, height, "Q4xxx")
    clamp = {k + 1: [0.0, 0.0] for k, (x, y, _) in enumerate(nodes) if y == 0.0}
    top = [ny * (nx + 1) + i + 1 for i in range(nx + 1)]  # left to right: the arcs bulge upwards
    bodies = w.mailx_bodies(nodes, elements, "Q4xxx", "M2DQ4", "rubbr")[:-len("$$$$$$\n")] + "$tacty\n"
    for k in range(1, 3):
        bodies += diskl(k, "ARCSx", top[k], top[k + 1], 0.5, 0.04, 0.05)
    radius = 0.04
    bodies += "$$$$$$\n" + w.rbdy2(1, "steel", 0.14, height + 0.04 + radius + 2e-3, 0.0, w.disk(radius, "DISKS"))
    bulk = w.elas_bulk("rubbr", 1000.0, 1e7, 0.3, gravity=(2.0, -9.81)) + (
        f"\n$behav  lawty\n steel  RIGID                           Umas={w.real(7800.0)}\n")
    tact = (f"$behav  lawty\n iqsc0  IQS_CLB                         fric={w.real(0.1)}\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" RBDY2  DISKx  DISKS  iqsc0  MAILx  DISKL  ARCSx      {w.real(0.01)}\n")
    text = contact_script(
        "# A rigid disk landing and rolling on the arcs (DISKL) of an elastic block (DKDKL), tilted gravity.",
        "1e-3", "0.5", 300, "1e-10", 400)
    write(folder, {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DQ4", "Q4xxx", lumped=True),
                   "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": w.mailx_driven(clamp), "TACT_BEHAV.DAT": tact}, text)


HERTZ = {"radius": 0.1, "young": 1e8, "poisson": 0.3, "load": 86300.0}


def hertz_cylinder(folder):
    """The lower half of a cylinder of radius R centred at the origin (flat face y = 0 on top), meshed
    in polar rings of T3xxx, angular nodes graded towards the bottom and radial rings towards the rim;
    a CLxxx point at the middle of each rim edge within 0.3 rad of the bottom, a JONCx whose top is
    y = -R, the load P spread on the flat face as nodal forces ramped over 10 steps."""
    R, P = HERTZ["radius"], HERTZ["load"]
    n_angle, n_ring = 120, 40
    # phi(s) = 3π/2 + π/2 (α s + (1 - α) s³), s in [-1, 1]: fine at the bottom (s = 0).
    alpha = 0.15
    angles = [1.5 * math.pi + 0.5 * math.pi * (alpha * s + (1 - alpha) * s ** 3)
              for s in (-1 + 2 * j / n_angle for j in range(n_angle + 1))]
    radii = [R * (1 - (1 - i / n_ring) ** 1.5) for i in range(n_ring + 1)]
    nodes = [(0.0, 0.0, False)]
    index = {}
    for i in range(1, n_ring + 1):
        for j, phi in enumerate(angles):
            x, y = radii[i] * math.cos(phi), radii[i] * math.sin(phi)
            if j in (0, n_angle):
                y = 0.0  # the flat face exactly
            index[(i, j)] = len(nodes) + 1
            nodes.append((x, y, False))
    elements = [[1, index[(1, j)], index[(1, j + 1)]] for j in range(n_angle)]
    for i in range(1, n_ring):
        for j in range(n_angle):
            a, b, c, d = index[(i, j)], index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)]
            elements += [[a, b, c], [a, c, d]]
    bodies = w.mailx_bodies(nodes, elements, "T3xxx", "M2DT3", "elast")[:-len("$$$$$$\n")] + "$tacty\n"
    # Rim edges described clockwise (phi decreasing): the CLxxx normal points out.
    k = 0
    for j in range(n_angle):
        if abs(0.5 * (angles[j] + angles[j + 1]) - 1.5 * math.pi) > 0.3:
            continue
        k += 1
        bodies += w.clxxx(k, "CYLIN", index[(n_ring, j + 1)], index[(n_ring, j)], 0.5)
    bodies += "$$$$$$\n" + w.rbdy2(1, "tdurx", 0.0, -R - 0.05, 0.0, w.joncx(0.5, 0.05))
    # The load: a uniform traction P / 2R on the flat face, as nodal forces (tributary lengths).
    face = sorted([(nodes[n - 1][0], n) for n in [1] + [index[(i, j)] for i in range(1, n_ring + 1) for j in (0, n_angle)]])
    forces = {}
    for m, (x, n) in enumerate(face):
        left = face[m - 1][0] if m > 0 else x
        right = face[m + 1][0] if m + 1 < len(face) else x
        forces[n] = -P / (2 * R) * 0.5 * (right - left)
    ramp = 1.0 / (10 * 0.005)
    driven = "$bdyty\n MAILx      1\n$model\n MECAx\n"
    for n in sorted(forces):
        driven += (f"$nodty\n NO2xx{n:7d}\n{w.TEMPLATE}\n force{2:7d} {w.real(forces[n])} {w.real(0.0)} {w.real(0.0)}"
                   f" {w.real(0.0)} {w.real(0.0)} {w.real(ramp)}\n")
    driven += "$$$$$$\n" + w.fixed([1])
    bulk = w.elas_bulk("elast", 1000.0, HERTZ["young"], HERTZ["poisson"]) + (
        f"\n$behav  lawty\n tdurx  RIGID                           Umas={w.real(1000.0)}\n")
    tact = (f"$behav  lawty\n hertz  IQS_CLB                         fric={w.real(0.0)}\n\n"
            "$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
            f" MAILx  CLxxx  CYLIN  hertz  RBDY2  JONCx  WALLx      {w.real(0.01)}\n")
    text = contact_script(
        "# Hertz: an elastic half-cylinder pressed on a rigid plane by a line load, frictionless.",
        "0.005", "1.0", 40, "1e-8", 400)
    write(folder, {"BODIES.DAT": bodies, "MODELS.DAT": w.mailx_model("M2DT3", "T3xxx", lumped=True),
                   "BULK_BEHAV.DAT": bulk, "DRV_DOF.DAT": driven, "TACT_BEHAV.DAT": tact}, text)


# Cases also restarted from LMGC90's last files (DOF.LAST, Vloc_Rloc.LAST and a GPV.INI of their step)
# for RESTART_STEPS more steps: the warm start reads their interactions and internals back.
RESTARTED = ("mailx_mac_czm_blocks", "mailx_disk_on_diskl", "mailx_glued_points")
RESTART_STEPS = 50


def restart_folder(folder, reference, into):
    """`folder`'s DATBOX and command.py in `into`, starting from `reference`'s DOF.LAST and
    Vloc_Rloc.LAST, for RESTART_STEPS steps."""
    shutil.rmtree(into, ignore_errors=True)
    os.makedirs(into)
    shutil.copytree(os.path.join(folder, "DATBOX"), os.path.join(into, "DATBOX"))
    shutil.copy(os.path.join(reference, "DOF.LAST"), os.path.join(into, "DATBOX", "DOF.INI"))
    shutil.copy(os.path.join(reference, "Vloc_Rloc.LAST"), os.path.join(into, "DATBOX", "Vloc_Rloc.INI"))
    with open(os.path.join(reference, "DOF.LAST")) as f:
        header = "".join(f.readlines()[:6]).replace("! DOF", "! GPV")
    with open(os.path.join(into, "DATBOX", "GPV.INI"), "w") as f:
        f.write(header)
    with open(os.path.join(folder, "command.py")) as f:
        text = f.read()
    with open(os.path.join(into, "command.py"), "w") as f:
        f.write("\n".join(f"nb_steps = {RESTART_STEPS}" if line.startswith("nb_steps = ") else line
                          for line in text.split("\n")))


def restart(work, reference, lmgc90):
    into = work + "_restart"
    restart_folder(work, reference, into)
    subprocess.run([sys.executable, "command.py"], cwd=into, check=True, stdout=subprocess.DEVNULL,
                   env=dict(os.environ, PYTHONPATH=lmgc90, OMP_NUM_THREADS="1"))
    os.makedirs(os.path.join(reference, "restart"), exist_ok=True)
    for f in ("DOF.LAST", "Vloc_Rloc.LAST"):
        shutil.copy(os.path.join(into, "OUTBOX", f), os.path.join(reference, "restart", f))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmgc90", default=None, help="LMGC90's build folder (pylmgc90 inside)")
    parser.add_argument("--only", nargs="*", default=None, help="run LMGC90 on these cases only")
    args = parser.parse_args()
    cases = {"mailx_patch_q4": patch_q4, "mailx_cantilever_t3": cantilever_t3,
             "mailx_block_on_wall": block_on_wall, "mailx_disk_on_block": disk_on_block,
             "mailx_glued_blocks": glued_blocks,
             "mailx_neo_hookean_stretch": neo_hookean_stretch, "mailx_adaptive_stretch": adaptive_stretch,
             "mailx_rotated_at_rest": rotated_at_rest,
             "mailx_j2_traction_linear": j2_traction("linear", (2e3, 1e4)),
             "mailx_j2_traction_swift": j2_traction("Swift", (1e4, 0.01, 0.2)),
             "mailx_hertz_cylinder": hertz_cylinder,
             "mailx_glued_points": glued_points, "mailx_disk_on_diskl": disk_on_diskl,
             "mailx_mac_czm_blocks": cohesive_blocks(
                 "MAC_CZM", [[("dfrc", 0.3), ("sfrc", 0.5)], [("cn", 1e9), ("ct", 5e8)],
                             [("visc", 0.0), ("dupr", 2.0)]]),
             "mailx_mal_czm_blocks": cohesive_blocks(
                 "MAL_CZM", [[("dfrc", 0.3), ("sfrc", 0.5)], [("cn", 1e9), ("ct", 5e8)],
                             [("s1", 4e4), ("s2", 2e4)], [("G1", 6.0), ("G2", 6.0)]]),
             "mailx_gap_mohr_blocks": cohesive_blocks(
                 "GAP_MOHR_DS_CLB", [[("cohn", 4e4), ("coht", 2e4)], [("dfrc", 0.3), ("sfrc", 0.5)]]),
             "mailx_gap_wet_blocks": cohesive_blocks(
                 "GAP_WET_DS_CLB", [[("cohn", 2e2), ("coht", 1e2)], [("Wthk", 2e-4)],
                                    [("dfrc", 0.3), ("sfrc", 0.5)]])}
    for name, make in cases.items():
        folder = os.path.join(ROOT, "reference_cases", name)
        make(folder)
        if not args.lmgc90 or name == "mailx_hertz_cylinder" or (args.only and name not in args.only):
            continue
        work = os.path.join("/tmp", "lmgc90_" + name)
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(folder, work, ignore=shutil.ignore_patterns("lmgc90_reference", "README.md"))
        subprocess.run([sys.executable, "command.py"], cwd=work, check=True, stdout=subprocess.DEVNULL,
                       env=dict(os.environ, PYTHONPATH=args.lmgc90, OMP_NUM_THREADS="1"))
        reference = os.path.join(folder, "lmgc90_reference")
        os.makedirs(reference, exist_ok=True)
        for f in ("DOF.LAST", "GPV.LAST", "Vloc_Rloc.LAST"):
            if os.path.exists(os.path.join(work, "OUTBOX", f)):
                shutil.copy(os.path.join(work, "OUTBOX", f), reference)
        if os.path.exists(os.path.join(work, "steps.txt")):
            shutil.copy(os.path.join(work, "steps.txt"), reference)
        for f in sorted(os.listdir(os.path.join(work, "POSTPRO"))) if os.path.isdir(os.path.join(work, "POSTPRO")) else []:
            if f.startswith(("Dep_", "Fint_")):
                shutil.copy(os.path.join(work, "POSTPRO", f), reference)
        print(f"{name}: LMGC90's DOF.LAST and GPV.LAST stored in {reference}")
        if name in RESTARTED:
            restart(work, reference, args.lmgc90)

    return 0


if __name__ == "__main__":
    sys.exit(main())
