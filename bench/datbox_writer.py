"""Writes LMGC90 case folders for the benchmarks and comparisons (bench/memory.py,
bench/masonry_wall.py): DATBOX/ files in LMGC90's column layout (docs/grammar.md) and a
command.py that LMGC90 runs and lmgc-solve reads. Rigid 2D bodies only."""
import math
import os

TEMPLATE = "$dofty  numbr [CT......+......AMP..*..cos.(..OMEGA.*.time.+.PHI..)]...*...[RAMPI.....+.....RAMP.*.time]"


def real(x):
    """A real in LMGC90's D14.7 form: ' 0.1234567D+01'."""
    if x == 0.0:
        return " 0.0000000D+00"
    exponent = math.floor(math.log10(abs(x))) + 1
    digits = round(abs(x) / 10.0 ** exponent * 1e7)
    if digits >= 10**7:
        digits, exponent = digits // 10, exponent + 1
    return f"{'-' if x < 0 else ' '}0.{digits:07d}D{exponent:+03d}"


def rbdy2(number, behav, x, y, angle, contactor):
    """One RBDY2 block; avrd and gyrd 0 (LMGC90 computes them from the contactor)."""
    return (f"$bdyty\n RBDY2{number:7d}\n$blmty\n PLAIN      1  behav  {behav}  avrd={real(0.0)}  gyrd={real(0.0)}\n"
            f"$nodty\n NO3xx      1                coo1={real(x)}  coo2={real(y)}  coo3={real(angle)}\n"
            f"$tacty\n{contactor}$$$$$$\n")


def disk(radius, color="BLEUx"):
    return f" DISKx      1  color  {color}  byrd={real(radius)}\n"


def joncx(half_length, half_width, color="WALLx"):
    return f" JONCx      1  color  {color}  ax1 ={real(half_length)}  ax2 ={real(half_width)}\n"


def polygon(vertices, color="BLEUx"):
    """Vertices about the body's node, counter-clockwise."""
    lines = f" POLYG      1  color  {color}  nb_vertex={len(vertices):7d}\n"
    for x, y in vertices:
        lines += f"                             coo1={real(x)}  coo2={real(y)}\n"
    return lines


def fixed(bodies):
    """DRV_DOF.DAT: the three velocities of each body imposed to zero."""
    out = ""
    for body in bodies:
        out += f"$bdyty\n RBDY2{body:7d}\n$nodty\n NO3xx      1\n{TEMPLATE}\n"
        for dof in (1, 2, 3):
            out += f" vlocy      {dof}{real(0.0)} {real(0.0)} {real(0.0)} {real(0.0)} {real(1.0)} {real(0.0)}\n"
        out += "$$$$$$\n"
    return out


def bulk_behav(densities, gravity=-9.81):
    """BULK_BEHAV.DAT with gravity along y and one RIGID law per (name, density)."""
    out = f"$gravy\n                   grv1={real(0.0)}  grv2={real(gravity)}  grv3={real(0.0)}\n"
    for name, density in densities:
        out += f"\n$behav  lawty\n {name}  RIGID                           Umas={real(density)}\n"
    return out


def tact_behav(law, friction, rows):
    """TACT_BEHAV.DAT: one IQS_CLB law and its '$seety' rows (cdtac, cdcol, antac, ancol, alert)."""
    out = f"$behav  lawty\n {law}  IQS_CLB                         fric={real(friction)}\n\n"
    for cdtac, cdcol, antac, ancol, alert in rows:
        out += (f"$seety\n cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert\n"
                f" RBDY2  {cdtac}  {cdcol}  {law}  RBDY2  {antac}  {ancol}      {real(alert)}\n\n")
    return out


def write_case(folder, files, script):
    """DATBOX/<name> for each (name, text) of `files`, and command.py."""
    datbox = os.path.join(folder, "DATBOX")
    os.makedirs(datbox, exist_ok=True)
    files = dict(files)
    files.setdefault("DOF.INI", f"! DOF\n$steps      0                time={real(0.0)}\n")
    files.setdefault("Vloc_Rloc.INI", f"! Vloc_Rloc\n$steps      0                time={real(0.0)}\n")
    for name, text in files.items():
        with open(os.path.join(datbox, name), "w") as f:
            f.write(text)
    with open(os.path.join(folder, "command.py"), "w") as f:
        f.write(script)


def rigid_2d_script(dt, steps, tol, gs_it1, gs_it2, norm="Quad ", write_every=0, theta=0.5, timed=False):
    """A command.py in LMGC90's usual sequence (the rigid 2D loop of its user's guide)."""
    write = "  chipy.WriteOut(freq_write)\n" if write_every else ""
    timer_start = "  start = time.perf_counter()\n" if timed else ""
    timer_stop = "  times.append(time.perf_counter() - start)\n" if timed else ""
    timer_file = ("with open('step_seconds.txt', 'w') as f:\n"
                  "  f.write('\\n'.join(str(t) for t in times) + '\\n')\n") if timed else ""
    return f"""# Written by lmgc's bench/datbox_writer.py: run by LMGC90, read by lmgc-solve.
import time
from pylmgc90 import chipy

dt = {dt!r}
theta = {theta!r}
nb_steps = {steps}
solver_type = 'Stored_Delassus_Loops         '
norm = {norm!r}
tol = {tol!r}
relax = 1.0
gs_it1 = {gs_it1}
gs_it2 = {gs_it2}
freq_write = {write_every or 1}

chipy.Initialize()
chipy.checkDirectories()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep(dt)
chipy.Integrator_InitTheta(theta)
chipy.ReadDatbox(deformable=False)
chipy.ComputeMass()
times = []
for k in range(0, nb_steps):
{timer_start}  chipy.IncrementStep()
  chipy.ComputeFext()
  chipy.ComputeBulk()
  chipy.ComputeFreeVelocity()
  chipy.SelectProxTactors()
  chipy.RecupRloc()
  chipy.ExSolver(solver_type, norm, tol, relax, gs_it1, gs_it2)
  chipy.StockRloc()
  chipy.ComputeDof()
  chipy.UpdateStep()
{write}{timer_stop}chipy.WriteLastDof()
chipy.WriteLastVlocRloc()
chipy.Finalize()
{timer_file}"""


def mailx_rectangle(nx, ny, length, height, element="Q4xxx", distort=0.0):
    """Nodes and elements of a MAILx rectangle [0, length] × [0, height]: nx × ny cells, each one
    Q4xxx or two T3xxx; interior nodes moved by up to `distort` (never inverted). Nodes row after
    row from the bottom; returns ([(x, y, on_boundary)], [[node, ...]])."""
    nodes, index = [], {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y = length * i / nx, height * j / ny
            boundary = i in (0, nx) or j in (0, ny)
            if distort and not boundary:
                x += distort * math.sin(3.7 * x + 1.3 * y)
                y += distort * math.cos(2.1 * x - 4.3 * y)
            index[(i, j)] = len(nodes) + 1
            nodes.append((x, y, boundary))
    elements = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = index[(i, j)], index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)]
            elements += [[a, b, c, d]] if element == "Q4xxx" else [[a, b, c], [a, c, d]]
    return nodes, elements


def mailx_bodies(nodes, elements, element, model, behav):
    """BODIES.DAT of one MAILx body (2D nodes)."""
    out = "$bdyty\n MAILx      1\n$blmty\n"
    for k, e in enumerate(elements):
        out += f" {element}{k + 1:7d}  nodes" + "".join(f"{v:7d}" for v in e) + "\n"
        out += f"               model  {model}  behav  {behav}\n"
    out += "$nodty\n"
    for k, (x, y, _) in enumerate(nodes):
        out += f" NO2xx{k + 1:7d}                coo1={real(x)}  coo2={real(y)}\n"
    return out + "$$$$$$\n"


def mailx_model(model, element, lumped):
    """MODELS.DAT: one mechanical model, small strain, LMGC90's own linear elasticity."""
    return (f"$model  mdlty  finel  eleop  value\n {model}\n        MECAx  {element}  isext  no___\n"
            "                      kine_  small\n                      form_  xxxxx\n"
            "                      aniso  iso__\n                      mater  elas_\n"
            f"                      mstrg  {'lump_' if lumped else 'coher'}\n")


def mailx_model_neo_hookean(model, element):
    """MODELS.DAT: one mechanical model in large strain (total Lagrangian), MatLib's neo-Hookean material."""
    return (f"$model  mdlty  finel  eleop  value\n {model}\n        MECAx  {element}  isext  MatL_\n"
            "                      kine_  large\n                      form_  TotaL\n"
            "                      aniso  iso__\n                      mater  neoh_\n"
            "                      mstrg  lump_\n                      cplth  no___\n")


def mailx_model_j2(model):
    """MODELS.DAT: one Q4P0x model of LMGC90's own large-strain material (updated Lagrangian)."""
    return (f"$model  mdlty  finel  eleop  value\n {model}\n        MECAx  Q4P0x  isext  no___\n"
            "                      kine_  large\n                      form_  UpdtL\n"
            "                      mstrg  lump_\n")


def elas_plas_bulk(name, density, young, poisson, hardening, coefficients):
    """BULK_BEHAV.DAT with one ELAS_PLAS law, von Mises, isotropic hardening 'linear' (SIG0, K___) or
    'Swift' (C0__, EPS0, n___)."""
    labels = {"linear": ("SIG0", "K___"), "Swift": ("C0__", "EPS0", "n___")}[hardening]
    values = "  ".join(f"{label}={real(v)}" for label, v in zip(labels, coefficients))
    pad = " " * 40
    return (f"$gravy\n                   grv1={real(0.0)}  grv2={real(0.0)}  grv3={real(0.0)}\n\n"
            f"$behav  lawty\n {name}  ELAS_PLAS                       Umas={real(density)}\n"
            f"{pad}elas: standard\n{pad}ani_: isotropic\n"
            f"{pad}EYng={real(young)}  EPss={real(poisson)}\n"
            f"{pad}crit: Von-Mises\n{pad}isoh: {hardening}\n{pad}{values}\n"
            f"{pad}cinh: none\n{pad}visc: none\n")


def elas_bulk(name, density, young, poisson, gravity=(0.0, 0.0)):
    """BULK_BEHAV.DAT with one ELAS law."""
    return (f"$gravy\n                   grv1={real(gravity[0])}  grv2={real(gravity[1])}  grv3={real(0.0)}\n\n"
            f"$behav  lawty\n {name}  ELAS                            Umas={real(density)}\n"
            "                                        elas: standard\n                                        ani_: isotropic\n"
            f"                                        EYng={real(young)}  EPss={real(poisson)}\n")


def mailx_driven(velocities, body=1):
    """DRV_DOF.DAT of one MAILx body: {node: [v or None per component]} imposed velocities, each a
    constant or a tuple (CT, AMP, OMEGA, PHI): CT + AMP cos(OMEGA t + PHI)."""
    out = f"$bdyty\n MAILx{body:7d}\n$model\n MECAx\n"
    for node in sorted(velocities):
        out += f"$nodty\n NO2xx{node:7d}\n{TEMPLATE}\n"
        for c, v in enumerate(velocities[node]):
            if v is not None:
                ct, amp, omega, phi = v if isinstance(v, tuple) else (v, 0.0, 0.0, 0.0)
                out += (f" vlocy{c + 1:7d} {real(ct)} {real(amp)} {real(omega)} {real(phi)} {real(1.0)}"
                        f" {real(0.0)}\n")
    return out + "$$$$$$\n"


def tact_law(nickname, law, rows):
    """A TACT_BEHAV.DAT '$behav' card: rows of (label, value) pairs, the first beside the law's name,
    the others on continuation lines."""
    lines = []
    for k, row in enumerate(rows):
        values = "  ".join(f"{label:<4}={real(v)}" for label, v in row)
        lines.append((f" {nickname}  {law:<30}  " if k == 0 else " " * 40) + values)
    return "$behav  lawty\n" + "\n".join(lines) + "\n"


def clxxx(rank, color, noda, nodb, apab):
    """A MAILx '$tacty' CLxxx line: the point at apab from noda on the edge (noda, nodb)."""
    return f" CLxxx{rank:7d}  color  {color}  noda={noda:5d}  nodb={nodb:5d}  apab={real(apab)}\n"


def alpxx(rank, color, nodes):
    """A MAILx ALpxx polyline through `nodes`: its first segment, then one '+ALpxx' line per segment."""
    lines = f" ALpxx{rank:7d}  color  {color}  noda={nodes[0]:5d}  nodb={nodes[1]:5d}\n"
    for a, b in zip(nodes[1:-1], nodes[2:]):
        lines += f"+ALpxx{rank:7d}  color  {color}  noda={a:5d}  nodb={b:5d}\n"
    return lines


STATE_HEADER = ("! DOF\n\n$steps      0                time= 0.0000000D+00\n\n"
                "!-----------------------------------------------------------------------\n")


# One step of a deformable case in LMGC90's linear driver sequence, indented for the body of a loop.
MAILX_STEP = """  chipy.IncrementStep()
  chipy.ComputeFext()
  chipy.ComputeBulk()
  chipy.AssembleMechanicalRHS()
  chipy.AssembleMechanicalLHS()
  chipy.ComputeFreeVelocity()
  chipy.SelectProxTactors()
  chipy.RecupRloc()
  chipy.ExSolver('Stored_Delassus_Loops         ', 'Quad ', 1e-4, 1.0, 10, 10)
  chipy.UpdateTactBehav()
  chipy.StockRloc()
  chipy.ComputeDof()
  chipy.UpdateStep()
"""
