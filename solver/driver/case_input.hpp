#pragma once
// From a loaded case folder (case_folder::CaseFiles) to what a rigid 2D run needs: the Scene, the
// POSTPRO commands, the warm start of Vloc_Rloc.INI, the run parameters of COMMAND.DAT, and the
// echo files LMGC90 writes when it reads the case. docs/lmgc90-facts/state-and-outputs.md §1, §2, §4.
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
#include "run/run_options.hpp"
#include "run/run_parameters.hpp"
#include "solver/driver/run_2d.hpp"
#include "solver/driver/run_3d.hpp"

namespace lmgc::solver {

// Fills `scene` and `outputs` (case folder, POSTPRO commands, Vloc_Rloc writer, warm start).
// Returns false, with diagnostics, when the case is not a rigid 2D case or uses something the
// rigid 2D solver does not provide (L4001, L4002).
// MAILx bodies run as linear elastic meshes in `hypothesis` (SetDimension(2, mhyp)), without contact.
bool prepare_run_2d(const case_folder::CaseFiles& files, Scene2D& scene, RunOutputs2D& outputs,
                    grammar::DiagnosticSink& sink,
                    fem::Hypothesis hypothesis = fem::Hypothesis::plane_strain);

// True when every body of the case is RBDY3: lmgc-solve runs it with the rigid 3D pipeline.
bool is_rigid_3d_case(const case_folder::CaseFiles& files);

// The rigid 3D counterpart of prepare_run_2d (L4001, L4002 for what the 3D solver lacks).
bool prepare_run_3d(const case_folder::CaseFiles& files, Scene3D& scene, RunOutputs3D& outputs,
                    grammar::DiagnosticSink& sink);

// What lmgc-solve would refuse (L4001-L4003) or leave out (L4004) in this case, for lmgc-check:
// prepares the run into a scratch sink and passes those diagnostics on. Nothing when `sink` holds
// errors already (the builders take checked data only).
void report_solver_support(const case_folder::CaseFiles& files, grammar::DiagnosticSink& sink);

// The echo files of a rigid 2D run: as case_folder::echo_files, with BODIES.OUT after LMGC90's
// RBDY2 pre-computations (avrd, gyrd, centre of inertia), as LMGC90 writes it.
std::vector<case_folder::OutputFile> echo_files_2d(const case_folder::CaseFiles& files);

// The echo files of a rigid 3D run, BODIES.OUT after LMGC90's RBDY3 pre-computations.
std::vector<case_folder::OutputFile> echo_files_3d(const case_folder::CaseFiles& files);

}  // namespace lmgc::solver
