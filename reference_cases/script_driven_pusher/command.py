# A pusher driven from the script (RBDY2_SetVlocyDrivenDof) shoves three disks along a floor, and a
# small disk is kicked upwards at steps 50, 300 and 550 (RBDY2_PutBodyVector 'Vbeg_'). The script records
# the bodies' positions (RBDY2_GetBodyVector 'Coor_') every 10 steps into trajectory.csv. The same
# script runs in LMGC90 and in lmgc (lmgc-run).
from pylmgc90 import chipy

dt = 1e-3
nb_steps = 600
theta = 0.5
norm = 'Quad '
tol = 1e-10
relax = 1.0
gs_it1 = 50
gs_it2 = 2000
solver_type = 'Stored_Delassus_Loops         '


def pusher_velocity(t):
    """0.5 m/s to the right for 0.4 s, then back at 0.25 m/s."""
    return 0.5 if t < 0.4 else -0.25


chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep(dt)
chipy.Integrator_InitTheta(theta)
chipy.ReadDatbox(deformable=False)
chipy.ComputeMass()

rows = []
for k in range(nb_steps):
  chipy.IncrementStep()
  chipy.RBDY2_SetVlocyDrivenDof(2, 1, pusher_velocity(chipy.TimeEvolution_GetTime()))
  chipy.ComputeFext()
  chipy.ComputeBulk()
  chipy.ComputeFreeVelocity()
  chipy.SelectProxTactors()
  chipy.RecupRloc()
  chipy.ExSolver(solver_type, norm, tol, relax, gs_it1, gs_it2)
  chipy.UpdateTactBehav()
  chipy.StockRloc()
  chipy.ComputeDof()
  chipy.UpdateStep()
  step = k + 1
  if step % 250 == 50:
    chipy.RBDY2_PutBodyVector('Vbeg_', 6, [0.0, 1.0, 0.0])
  if step % 10 == 0:
    row = [step, chipy.TimeEvolution_GetTime()]
    for body in range(2, chipy.RBDY2_GetNbRBDY2() + 1):
      row += list(chipy.RBDY2_GetBodyVector('Coor_', body))
    rows.append(row)

with open('trajectory.csv', 'w') as f:
  names = ['step', 'time']
  for body in range(2, 7):
    names += ['x%d' % body, 'y%d' % body, 'a%d' % body]
  f.write(','.join(names) + '\n')
  for row in rows:
    f.write(','.join(repr(float(v)) if i else str(v) for i, v in enumerate(row)) + '\n')

chipy.WriteLastDof()
chipy.WriteLastVlocRloc()
chipy.Finalize()
