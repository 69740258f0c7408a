# Two elastic blocks glued node to node (COUPLED_DOF on P2P2L pairs of PT2DL), bent by gravity.
# Written by scripts/make_mailx_reference_cases.py; run unchanged by LMGC90 and by lmgc-run.
from pylmgc90 import chipy

chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep(1e-3)
chipy.Integrator_InitTheta(0.5)
chipy.ReadDatbox(deformable=True)
chipy.ComputeMass()
chipy.ComputeBulk()
nb_steps = 150
for k in range(nb_steps):
  chipy.IncrementStep()
  chipy.ComputeFext()
  chipy.ComputeBulk()
  chipy.AssembleMechanicalRHS()
  chipy.AssembleMechanicalLHS()
  chipy.ComputeFreeVelocity()
  chipy.SelectProxTactors()
  chipy.RecupRloc()
  chipy.ExSolver('Stored_Delassus_Loops         ', 'Quad ', 1e-10, 1.0, 50, 400)
  chipy.UpdateTactBehav()
  chipy.StockRloc()
  chipy.ComputeDof()
  chipy.UpdateStep()
chipy.WriteLastDof()
chipy.WriteLastVlocRloc()
chipy.Finalize()
