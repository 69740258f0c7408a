# Patch test: nine distorted Q4xxx whose boundary follows u = A x in one quasi-static step.
# Written by scripts/make_mailx_reference_cases.py; run unchanged by LMGC90 and by lmgc-run.
from pylmgc90 import chipy

dt = 1.0
theta = 1.0
nb_steps = 1
freq_write = 1

chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep(dt)
chipy.Integrator_InitTheta(theta)
chipy.ReadDatbox(deformable=True)
chipy.ComputeMass()
chipy.ComputeBulk()
for k in range(nb_steps):
  chipy.IncrementStep()
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
  chipy.WriteOut(freq_write)
chipy.WriteLastDof()
chipy.WriteLastGPV()
chipy.Finalize()
