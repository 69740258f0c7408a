# The square of Q4P0x (J2 plasticity, Swift hardening) stretched by 20 % in 20 steps.
# Written by scripts/make_mailx_reference_cases.py; run unchanged by LMGC90 and by lmgc-run.
from pylmgc90 import chipy

chipy.Initialize()
chipy.checkDirectories()
chipy.utilities_DisableLogMes()
chipy.SetDimension(2, 1)
chipy.TimeEvolution_SetTimeStep(0.02)
chipy.Integrator_InitTheta(1.0)
chipy.NewtonRaphson_SetFinalTime(0.4)
chipy.NewtonRaphson_SetMinTimeStep(0.02)
chipy.NewtonRaphson_SetMaxTimeStep(0.02)
chipy.NewtonRaphson_SetMaxIter(20)
chipy.NewtonRaphson_SetIncPatience(9999999)
chipy.ReadDatbox(deformable=True)
chipy.ComputeMass()
log = open('steps.txt', 'w')
while chipy.TimeEvolution_GetTime() < 0.4:
  chipy.IncrementStep()
  chipy.ComputeFext()
  chipy.NewtonRaphson_Initialize(1e-10)
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
  log.write('%d %.6e %d %d\n' % (chipy.TimeEvolution_GetStep(), h, k, istate))
  if not istate == 1:
    chipy.UpdateStep()
    chipy.WriteOut(5)
    if istate == 2:
      break
log.close()
chipy.WriteLastDof()
chipy.WriteLastGPV()
chipy.Finalize()
