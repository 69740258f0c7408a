#include "grammar/command_py/chipy_catalogue.hpp"

namespace lmgc::grammar {
namespace {

using M = ChipyMatch;
using S = CommandSupport;

// chipy's macro layer and module wrappers (LMGC90 2025, src/ChiPy): the calls of LMGC90's example
// scripts and their neighbours.
constexpr ChipyFunction kFunctions[] = {
    // The step and the files, as lmgc-solve does them.
    {"Initialize", M::exact, S::run, ""},
    {"Finalize", M::exact, S::run, ""},
    {"checkDirectories", M::exact, S::run, ""},
    {"SetDimension", M::exact, S::run, ""},
    {"ReadDatbox", M::exact, S::run, ""},
    {"ReadBodies", M::exact, S::run, ""},
    {"ReadBehaviours", M::exact, S::run, ""},
    {"ReadModels", M::exact, S::deformable, ""},
    {"ReadDrivenDof", M::exact, S::run, ""},
    {"LoadBehaviours", M::exact, S::run, ""},
    {"LoadModels", M::exact, S::deformable, ""},
    {"LoadTactors", M::exact, S::run, ""},
    {"ReadIniDof", M::exact, S::run, ""},
    {"ReadIniVlocRloc", M::exact, S::run, ""},
    {"ReadIniGPV", M::exact, S::deformable, ""},
    {"ReadIni", M::exact, S::run, ""},
    {"ComputeMass", M::exact, S::run, ""},
    {"IncrementStep", M::exact, S::run, ""},
    {"ComputeFext", M::exact, S::run, ""},
    {"ComputeBulk", M::exact, S::run, ""},
    {"ComputeFreeVelocity", M::exact, S::run, ""},
    {"SelectProxTactors", M::exact, S::run, ""},
    {"RecupRloc", M::exact, S::run, ""},
    {"ExSolver", M::exact, S::run, ""},
    {"UpdateTactBehav", M::exact, S::run, ""},
    {"StockRloc", M::exact, S::run, ""},
    {"ComputeDof", M::exact, S::run, ""},
    {"UpdateStep", M::exact, S::run, ""},
    {"TimeEvolution_SetTimeStep", M::exact, S::run, ""},
    {"TimeEvolution_UpdateStep", M::exact, S::run, ""},
    {"Integrator_InitTheta", M::exact, S::run, ""},
    {"nlgs_SetWithQuickScramble", M::exact, S::run, ""},
    {"nlgs_3D_SetWithQuickScramble", M::exact, S::run, ""},
    {"nlgs_3D_DiagonalResolution", M::exact, S::run, ""},
    {"SetPeriodicCondition", M::exact, S::run, ""},
    {"RBDY2_SetYminBoundary", M::exact, S::run, ""},
    {"RBDY2_SetYmaxBoundary", M::exact, S::run, ""},
    {"RBDY2_SetXminBoundary", M::exact, S::run, ""},
    {"RBDY2_SetXmaxBoundary", M::exact, S::run, ""},
    {"RBDY3_NewRotationScheme", M::exact, S::run, ""},
    {"RBDY3_SetSourcePointWithIni", M::exact, S::run, ""},
    {"RBDY3_SetSourcePoint", M::exact, S::run, ""},  // --source-point ... --source-point-relative
    {"PTPT3_LoadNetwork", M::exact, S::run, ""},
    {"PTPT3_UseCurrentNonuc0", M::exact, S::run, ""},
    {"PRPRx_UseCpCundallDetection", M::exact, S::run, ""},
    {"PRPRx_LowSizeArrayPolyr", M::exact, S::run, ""},  // sizes an array only
    {"PRPRx_VerboseF2F", M::exact, S::not_written, "prints face-to-face detection details"},
    // Outputs.
    {"WriteOut", M::exact, S::written, ""},
    {"WriteOutDof", M::exact, S::written, ""},
    {"WriteOutVlocRloc", M::exact, S::written, ""},
    {"WriteLast", M::exact, S::written, ""},
    {"WriteLastDof", M::exact, S::written, ""},
    {"WriteLastVlocRloc", M::exact, S::written, ""},
    {"WriteBodies", M::exact, S::written, ""},
    {"WriteBehaviours", M::exact, S::written, ""},
    {"WriteDrivenDof", M::exact, S::written, ""},
    {"WriteDisplayFiles", M::exact, S::written, ""},
    {"WritePostproFiles", M::exact, S::written, ""},
    {"OpenDisplayFiles", M::exact, S::written, ""},
    {"CloseDisplayFiles", M::exact, S::written, ""},
    {"OpenPostproFiles", M::exact, S::written, ""},
    {"ClosePostproFiles", M::exact, S::written, ""},
    {"utilities_", M::prefix, S::run, ""},  // messages, logs
    {"timer_", M::prefix, S::run, ""},
    // Polyhedron detection other than Cundall's common plane, and its tuning.
    {"PRPRx_UseNcDetection", M::exact, S::not_run, "selects the non-convex polyhedron detection"},
    {"PRPRx_UseNcF2fDetection", M::exact, S::not_run, "selects the non-convex face-to-face detection"},
    {"PRPRx_UseNcF2fExplicitDetection", M::exact, S::not_run,
     "selects the explicit non-convex face-to-face detection"},
    {"PRPRx_UseCpF2fDetection", M::exact, S::not_run, "selects the common-plane face-to-face detection"},
    {"PRPRx_UseCpF2fExplicitDetection", M::exact, S::not_run,
     "selects the explicit common-plane face-to-face detection"},
    {"PRPRx_UseTrianglesIntersectionDetection", M::exact, S::not_run,
     "selects the triangle-intersection detection"},
    {"PRPRx_UseStoDetection", M::exact, S::not_run, "selects the STO detection"},
    {"PRPRx_UseExternalDetection", M::exact, S::not_run, "selects an external detection"},
    {"PRPRx_ShrinkPolyrFaces", M::exact, S::not_run, "shrinks the polyhedra's faces in the detection"},
    {"PRPRx_SetCundallNeighbor", M::exact, S::not_run,
     "changes the band of Cundall's common-plane detection"},
    {"PRPRx_SetF2fMinimalSurfaceSize", M::exact, S::not_run, "changes the face-to-face detection's surfaces"},
    {"PRPRx_CpUseOldCcpm", M::exact, S::not_run, "selects the old common-plane contact points"},
    {"PRPRx_ForceF2fDetection", M::exact, S::not_run, "forces the face-to-face detection"},
    {"PRPRx_ForceNcDetection", M::exact, S::not_run, "forces the non-convex detection"},
    {"PRPRx_SetTolRecupRloc", M::exact, S::warm_start, "changes the distance of the warm start by position"},
    // Other integrators, restarts and drivers written in Python.
    {"Integrator_InitCrankNickolson", M::exact, S::multiphysics, "sets up the thermal integrator"},
    {"Integrator_InitGear", M::exact, S::not_run, "selects Gear's integrator"},
    {"Integrator_InitVerlet", M::exact, S::not_run, "selects Verlet's integrator"},
    {"Integrator_InitQS", M::exact, S::not_run, "selects the quasi-static integrator"},
    {"TimeEvolution_SetInitialStep", M::exact, S::not_run, "sets the initial step"},
    {"TimeEvolution_SetInitialTime", M::exact, S::not_run, "sets the initial time"},
    {"RBDY2_FatalDamping", M::exact, S::not_run, "sets velocities to zero"},
    {"RBDY3_FatalDamping", M::exact, S::not_run, "sets velocities to zero"},
    {"RBDY2_PutBodyVector", M::exact, S::script_only, "sets a body vector from the script"},
    {"RBDY3_PutBodyVector", M::exact, S::script_only, "sets a body vector from the script"},
    {"RBDY2_PutAllBodyVector", M::exact, S::script_only, "sets a body vector from the script"},
    {"RBDY3_PutAllBodyVector", M::exact, S::script_only, "sets a body vector from the script"},
    {"RBDY2_SetVlocyDrivenDof", M::exact, S::script_only, "imposes a driven velocity from the script"},
    {"RBDY3_SetVlocyDrivenDof", M::exact, S::script_only, "imposes a driven velocity from the script"},
    {"_PutBodyVector", M::contains, S::not_run, "sets a body vector from the script"},
    {"_PutBodyValue", M::contains, S::not_run, "sets a body value from the script"},
    {"DrivenDof", M::contains, S::not_run, "drives dofs from the script"},
    {"Visible", M::contains, S::not_run, "makes bodies visible or invisible from the script"},
    {"BiaxialLoading", M::contains, S::not_run, "drives walls under a biaxial load"},
    {"SetDomainBoundary", M::exact, S::not_run, "sets the domain's bounds"},
    {"RBDY3_Set", M::prefix, S::not_run, "changes RBDY3 bodies from the script"},
    // Multi-physics (MP_DEM) and PTPT2 links.
    {"ReadMpBehaviours", M::exact, S::multiphysics, "loads thermal or electrical behaviours (MP_DEM.DAT)"},
    {"WriteOutMpValues", M::exact, S::multiphysics, "writes multi-physics values"},
    {"mp_solver", M::prefix, S::multiphysics, "runs LMGC90's multi-physics solver"},
    {"RBDY2_MP_", M::prefix, S::multiphysics, "loads multi-physics behaviours"},
    {"RBDY3_MP_", M::prefix, S::multiphysics, "loads multi-physics behaviours"},
    {"PTPT2_", M::prefix, S::multiphysics, "sets up PTPT2 links"},
    // Deformable bodies (MAILx): nothing in a case without them.
    {"mecaMAILx_", M::prefix, S::deformable, ""},
    {"therMAILx_", M::prefix, S::deformable, ""},
    {"MAILx_", M::prefix, S::deformable, ""},
    {"NewtonRaphson_", M::prefix, S::deformable, ""},
    {"Assemble", M::prefix, S::deformable, ""},
    {"models_", M::prefix, S::deformable, ""},
    {"CLxxx_", M::prefix, S::deformable, ""},
    {"ALpxx_", M::prefix, S::deformable, ""},
    {"CSxxx_", M::prefix, S::deformable, ""},
    {"ASpxx_", M::prefix, S::deformable, ""},
    {"WriteOutGPV", M::exact, S::deformable, ""},
    {"WriteLastGPV", M::exact, S::deformable, ""},
    // Queries: no effect on the run.
    {"_Get", M::contains, S::run, ""},
    {"_get", M::contains, S::run, ""},
    {"_Is", M::contains, S::run, ""},
};

bool matches(const ChipyFunction& f, std::string_view name) {
  switch (f.match) {
    case ChipyMatch::exact:
      return name == f.name;
    case ChipyMatch::prefix:
      return name.substr(0, f.name.size()) == f.name;
    case ChipyMatch::contains:
      return name.find(f.name) != std::string_view::npos;
  }
  return false;
}

}  // namespace

std::span<const ChipyFunction> chipy_catalogue() {
  return kFunctions;
}

const ChipyFunction* find_chipy_function(std::string_view name) {
  for (const ChipyFunction& f : kFunctions)
    if (f.match == ChipyMatch::exact && matches(f, name)) return &f;
  // Queries before families: 'RBDY3_GetBodyVector' is a query, not an RBDY3 set-up.
  for (const ChipyFunction& f : kFunctions)
    if (f.match != ChipyMatch::exact && f.support == CommandSupport::run && matches(f, name)) return &f;
  for (const ChipyFunction& f : kFunctions)
    if (f.match != ChipyMatch::exact && matches(f, name)) return &f;
  return nullptr;
}

}  // namespace lmgc::grammar
