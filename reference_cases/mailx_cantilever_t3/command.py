# A T3xxx cantilever (plane stress, lumped mass) clamped at x = 0, falling under gravity.
# Written by scripts/make_mailx_reference_cases.py; run unchanged by LMGC90 and by lmgc-run.
from pylmgc90 import chipy

dt = 0.001
theta = 0.5
nb_steps = 200
freq_write = 50

chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 2)
chipy.TimeEvolution_SetTimeStep(dt)
chipy.Integrator_InitTheta(theta)
chipy.ReadDatbox(deformable=True)
chipy.OpenPostproFiles()
chipy.ComputeMass()
chipy.ComputeBulk()
chipy.mecaMAILx_ComputeRayleighDamping(0.5, 1e-4)
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
  chipy.WritePostproFiles()
chipy.ClosePostproFiles()
chipy.WriteLastDof()
chipy.WriteLastGPV()
chipy.Finalize()
