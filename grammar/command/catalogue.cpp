#include "grammar/command/catalogue.hpp"

namespace lmgc::grammar {
namespace {

using A = CommandArgumentKind;
using M = CommandMatch;
using I = CommandInline;
using S = CommandSupport;

constexpr A kReal[] = {A::real};
constexpr A kInteger[] = {A::integer};
constexpr A kWord[] = {A::word};
constexpr A kNlgsCheck[] = {A::type_tol, A::real};                                    // type tol / relax
constexpr A kNlgsSolver[] = {A::word, A::type_tol, A::real, A::integer, A::integer};  // storage .. block iter
constexpr A kSourcePoint[] = {A::integer, A::real, A::reals};  // first body, radius, shift
constexpr A kTwoReals[] = {A::reals, A::reals};
constexpr A kBiaxialWalls[] = {A::reals, A::real, A::real, A::word};
constexpr std::span<const A> kNone{};

// Module commands: chic_command_overall, chic_command_RBDY2/RBDY3/mecaMAILx/..., chic_command_nlgs,
// postpro and display handlers of the v2-era wrappers; CHIC's own words at the end.
// docs/lmgc90-facts/state-and-outputs.md §2.1.2-2.1.3.
constexpr CommandKeyword kKeywords[] = {
    // Time, integrator, global (overall).
    {"DIME", "overall", M::prefix, I::none, kWord},
    {"TIME STEP", "overall", M::prefix, I::none, kReal},
    {"THETA", "overall", M::prefix, I::none, kReal},
    {"THERMAL THETA", "overall", M::prefix, I::none, kReal, false, S::multiphysics},
    {"FINAL TIME", "overall", M::prefix, I::none, kReal, false, S::not_run},
    {"MIN TIME STEP", "overall", M::prefix, I::none, kReal, false, S::not_run},
    {"MAX TIME STEP", "overall", M::prefix, I::none, kReal, false, S::not_run},
    {"NB BULK ITER MAX", "overall", M::prefix, I::none, kInteger, false, S::not_run},
    {"NB BULK ITE FOR GOOD CONV", "overall", M::prefix, I::none, kInteger, false, S::not_run},
    {"NB BULK ITE FOR BAD CONV", "overall", M::prefix, I::none, kInteger, false, S::not_run},
    {"NB INC FOR GOODORBAD CONV", "overall", M::prefix, I::none, kInteger, false, S::not_run},
    {"CHECK NL CONVERGENCE", "overall", M::prefix, I::none, kReal, false, S::not_run},
    {"COMPUTE TIME STEP", "overall", M::prefix, I::none, kNone, false, S::not_run},
    {"INCREMENT STEP", "overall", M::prefix, I::none, kNone},
    {"UPDATE DOF", "overall", M::prefix, I::none, kNone},
    {"UPDATE THERM DOF", "overall", M::prefix, I::none, kNone, false, S::multiphysics},
    {"USE VERLET INTEGRATOR", "overall", M::prefix, I::none, kNone, false, S::not_run},
    {"USE GEAR INTEGRATOR", "overall", M::prefix, I::none, kNone, false, S::not_run},
    {"XXL COMPUTATION", "overall", M::prefix, I::none, kNone, false, S::not_run},
    {"DISPLAY TIMES", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"SELECT PROX TACTORS", "overall", M::prefix, I::step_or_dtps, kNone},
    {"FD SELECT PROX TACTORS", "overall", M::prefix, I::step_or_dtps, kNone},
    {"WCP SELECT PROX TACTORS", "overall", M::prefix, I::step_or_dtps, kNone},
    {"COMPUTE BOX", "overall", M::prefix, I::none, kNone},
    {"DISPLAY PROX TACTORS", "overall", M::prefix, I::none, kNone, false, S::not_written},
    // Reading and writing.
    {"READ BODIES", "overall", M::prefix, I::none, kNone},
    {"READ BEHAVIOURS", "overall", M::prefix, I::none, kNone},
    {"READ MODELS", "overall", M::prefix, I::none, kNone, false, S::deformable},
    {"READ DRIVEN DOF", "overall", M::prefix, I::none, kNone},
    {"READ INI DOF", "overall", M::prefix, I::none, kNone},
    {"READ INI Vloc Rloc", "overall", M::prefix, I::none, kNone},
    {"READ INI GPV", "overall", M::prefix, I::none, kNone, false, S::deformable},
    {"READ MP BEHAVIOURS", "overall", M::prefix, I::none, kNone, false, S::multiphysics},
    {"WRITE BODIES", "overall", M::prefix, I::none, kNone, false, S::written},
    {"WRITE BEHAVIOURS", "overall", M::prefix, I::none, kNone, false, S::written},
    {"WRITE MODELS", "overall", M::prefix, I::none, kNone, false, S::deformable},
    {"WRITE DRIVEN DOF", "overall", M::prefix, I::none, kNone, false, S::written},
    {"WRITE MP BEHAVIOURS", "overall", M::prefix, I::none, kNone, false, S::multiphysics},
    {"WRITE LAST DOF", "overall", M::prefix, I::none, kNone, false, S::written},
    {"WRITE LAST Vloc Rloc", "overall", M::prefix, I::none, kNone, false, S::written},
    {"WRITE LAST GPV", "overall", M::prefix, I::none, kNone, false, S::deformable},
    {"WRITE LAST Rnod", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"WRITE OUT DOF", "overall", M::prefix, I::step_or_dtps, kNone, false, S::written},
    {"WRITE OUT Vloc Rloc", "overall", M::prefix, I::step_or_dtps, kNone, false, S::written},
    {"WRITE OUT GPV", "overall", M::prefix, I::step_or_dtps, kNone, false, S::deformable},
    {"WRITE OUT Rnod", "overall", M::prefix, I::step_or_dtps, kNone, false, S::not_written},
    {"WRITE OUT MP VALUES", "overall", M::prefix, I::step_or_dtps, kNone, false, S::multiphysics},
    {"FROM TO", "overall", M::prefix, I::text, kNone, false, S::not_written},
    {"DISPLAY OUT DOF", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY OUT Vloc Rloc", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY OUT Rnod", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"BINARY WRITE LAST DOF", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"BINARY WRITE OUT DOF", "overall", M::prefix, I::step_or_dtps, kNone, false, S::not_written},
    {"BINARY READ INI DOF", "overall", M::prefix, I::none, kNone, false, S::not_run},
    {"CLEAN BODIES.OUT", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"REBUILD BODIES.DAT", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"CLEARED WRITE BODIES", "overall", M::prefix, I::none, kNone, false, S::not_written},
    {"WRITE OUT TIMER", "overall", M::prefix, I::none, kNone, false, S::not_written},
    // Finite-element models.
    {"LOAD BEHAVIOURS", "models", M::prefix, I::none, kNone, false, S::deformable},
    {"LOAD MODELS", "models", M::prefix, I::none, kNone, false, S::deformable},
    {"INIT MODELS", "models", M::prefix, I::none, kNone, false, S::deformable},
    {"INIT EXTERNAL MODELS", "models", M::prefix, I::none, kNone, false, S::deformable},
    {"STORE PROPERTIES", "models", M::prefix, I::none, kNone, false, S::deformable},
    {"PUSH PROPERTIES", "models", M::prefix, I::none, kNone, false, S::deformable},
    {"CHECK PROPERTIES", "models", M::prefix, I::none, kNone, false, S::deformable},
    // Bodies (RBDY2, RBDY3, mecaMAILx, therMAILx: each acts when it has bodies).
    {"COMPUTE MASS", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE Fext", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE BULK", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE NL BULK", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"COMPUTE Fint", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"COMPUTE FREE VELOCITY", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE NL FREE VELOCITY", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"COMPUTE DOF", "bodies", M::prefix, I::none, kNone},
    {"ASSEMB KT", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"ASSEMB RHS", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"ASSEMB NL KT", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"ASSEMB NL RHS", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"UPDATE BULK", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"UPDATE NL BULK", "bodies", M::prefix, I::none, kNone, false, S::deformable},
    {"FATAL DAMPING", "bodies", M::prefix, I::step_or_dtps, kNone, false, S::first_only},
    {"PARTIAL DAMPING", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"CHECK EQUILIBRIUM STATE", "bodies", M::prefix, I::none, kNone, false, S::not_run},
    {"NEW ROTATION SCHEME", "bodies", M::prefix, I::none, kNone},
    {"INI V DOF NULL", "bodies", M::prefix, I::none, kNone, false, S::first_only},
    {"INI X DOF NULL", "bodies", M::prefix, I::none, kNone, false, S::not_run},
    {"PERIODIC CONDITION", "bodies", M::prefix, I::none, kReal},
    {"XPERIODIC CONDITION", "bodies", M::prefix, I::none, kReal},
    {"YPERIODIC CONDITION", "bodies", M::prefix, I::none, kReal},
    {"INIT INF BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT SUP BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT LEFT BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT RIGHT BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT FRONT BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT BACK BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT XMIN BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT XMAX BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT YMIN BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT YMAX BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT ZMIN BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT ZMAX BOUNDARY", "bodies", M::prefix, I::none, kReal, false, S::not_run},
    {"INIT SOURCE POINT", "bodies", M::prefix, I::none, kSourcePoint},
    {"FD INIT SOURCE POINT", "bodies", M::prefix, I::none, kSourcePoint},
    {"CHECK SOURCE POINT", "bodies", M::prefix, I::none, kNone},
    {"GHOST TO INVISIBLE", "bodies", M::prefix, I::none, kNone, false, S::not_run},
    {"INIT CONSTRUCT WALL", "bodies", M::prefix, I::none, kTwoReals, false, S::not_run},
    {"BIAXIAL DEF WALLS", "bodies", M::prefix, I::none, kBiaxialWalls, false, S::not_run},
    {"UPDATE WSvsT", "bodies", M::prefix, I::none, kNone, false, S::not_run},
    {"INCREMENT WSvsT", "bodies", M::prefix, I::none, kNone, false, S::not_run},
    // Contact and solver (contact modules, nlgs).
    {"RECUP Rloc", "contact", M::prefix, I::none, kNone},
    {"SET TOL NEW RECUP Rloc", "contact", M::prefix, I::none, kReal, false, S::warm_start},
    {"STOCK Rloc", "contact", M::prefix, I::none, kNone},
    {"SMOOTH FORCE COMPUTATION", "contact", M::prefix, I::none, kNone, false, S::not_run},
    {"REFERENCE RADIUS", "contact", M::prefix, I::none, kReal, false, S::not_written},
    {"LOW SIZE ARRAY POLYR", "contact", M::prefix, I::none, kInteger},
    {"CUNDALL ITERATION", "contact", M::prefix, I::none, kInteger},
    {"DIAGONAL RESOLUTION", "contact", M::prefix, I::none, kNone},
    {"FLIP ORIENTATION CSxxx", "contact", M::prefix, I::none, kNone, false, S::deformable},
    {"NLGS CHECK TYPE", "nlgs", M::prefix, I::none, kNlgsCheck},
    {"EX PREP NLGS", "nlgs", M::prefix, I::none, kWord},
    {"EX ITER NLGS", "nlgs", M::prefix, I::none, kNone},
    {"AFTER ITER CHECK", "nlgs", M::prefix, I::none, kNone},
    {"DISPLAY AFTER ITER CHECK", "nlgs", M::prefix, I::none, kNone, false, S::not_written},
    {"EX POST NLGS", "nlgs", M::prefix, I::none, kNone},
    {"EX NLGS SOLVER", "nlgs", M::prefix, I::none, kNlgsSolver, false, S::not_run},
    {"UPDATE TACT BEHAV", "nlgs", M::prefix, I::none, kNone},
    {"INIT COHESIVE BEHAV", "nlgs", M::prefix, I::none, kNone, false, S::not_run},
    {"SCRAMBLE", "nlgs", M::prefix, I::none, kNone, false, S::not_run},
    {"quickSCRAMBLE", "nlgs", M::prefix, I::none, kNone},
    {"REVERSE", "nlgs", M::prefix, I::none, kNone, false, S::not_run},
    {"BIMODAL LIST", "nlgs", M::prefix, I::none, kNone, false, S::not_run},
    {"SCALE NLGS Rloc", "nlgs", M::prefix, I::none, kNone, false, S::not_run},
    {"Rnod = [H] Rloc", "nlgs", M::prefix, I::none, kNone, false, S::not_run},
    {"DISPLAY RlocN SUM", "nlgs", M::prefix, I::none, kNone, false, S::not_written},
    {"NLGS NORM CHECK", "nlgs", M::prefix, I::none, kNone, false, S::not_written},
    // Post-processing (reads POSTPRO.DAT) and display.
    {"INIT POST", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"INIT POST 3D", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"START POSTPRO", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"POSTPRO DURING COMPUTATION", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"UPDATE POST", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"UPDATE POST 3D", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"POSTPRO AFTER COMPUTATION", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"CLOSE POSTPRO FILES", "postpro", M::prefix, I::none, kNone, false, S::written},
    {"INIT GMV", "display", M::prefix, I::none, kNone, false, S::written},
    {"WRITE OUTPUT GMV", "display", M::prefix, I::step_or_dtps, kNone, false, S::written},
    {"WRITE LAST GMV", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY TACTOR", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY TACTORS", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY POSITION", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY AVERAGE VELOCITY", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY STRESS", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY STRAIN", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY DISPLACEMENT", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY FORCES", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY HEAT", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY MECHANICAL GPV", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY TACT POINT", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY TACT POINTS", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY INTERACTION", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY WITH VTK", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY BEFORE COMPUTATION", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY DURING COMPUTATION", "display", M::prefix, I::none, kNone, false, S::not_written},
    {"DISPLAY AFTER COMPUTATION", "display", M::prefix, I::none, kNone, false, S::not_written},
    // CHIC's own words (mod_chic: CHIC_comp, CHIC_comd, CHECK_CHIC_COMMAND).
    {"APPEL", "chic", M::prefix, I::text, kNone, true,
     S::control},  // 'APPELLE name': CHIC tests 5 characters
    {"SUB ", "chic", M::prefix, I::text, kNone, true, S::control},
    {"RETOUR", "chic", M::exact, I::none, kNone, true, S::control},
    {"REPETE", "chic", M::prefix, I::text, kNone, true, S::control},
    {"DEPUIS", "chic", M::prefix, I::text, kNone, true, S::control},
    {"STOP REPETE SI IOK =", "chic", M::prefix, I::text, kNone, true, S::control},
    {"CAP SI IOK =", "chic", M::prefix, I::text, kNone, true, S::control},
    {"SUR ", "chic", M::prefix, I::text, kNone, true, S::control},
    {"IOK =", "chic", M::prefix, I::text, kNone, true, S::control},
    {"ROK =", "chic", M::prefix, I::text, kNone, true, S::control},
    {"FLAG", "chic", M::prefix, I::text, kNone, true, S::control},
    {"DRAP", "chic", M::prefix, I::text, kNone, true, S::control},
    {"INTO ", "chic", M::prefix, I::text, kNone, true, S::control},
    {"OCCURENCE", "chic", M::prefix, I::text, kNone, true, S::control},
    {"ECHO ON", "chic", M::exact, I::none, kNone, true, S::control},
    {"ECHO OFF", "chic", M::exact, I::none, kNone, true, S::control},
    {"PAUSE", "chic", M::prefix, I::none, kNone, true, S::control},
    {"TOTALISATEURS A ZERO", "chic", M::exact, I::none, kNone, true, S::control},
    {"AFFICHE TOTALISATEURS", "chic", M::exact, I::none, kNone, true, S::control},
    {"AFFICHE COMPTEURS", "chic", M::exact, I::none, kNone, true, S::control},
    {"ECRIT TOTALISATEURS", "chic", M::exact, I::none, kNone, true, S::control},
    {"ECRIT COMPTEURS", "chic", M::exact, I::none, kNone, true, S::control},
    {"ECRIT DRAP TS LES", "chic", M::exact, I::none, kWord, true, S::control},
    {"OUVRE", "chic", M::prefix, I::text, kNone, true, S::control},
    {"FERME", "chic", M::prefix, I::text, kNone, true, S::control},
    {"FIN DU PROGRAMME", "chic", M::exact, I::none, kNone, true, S::control},
    {"FIN_DU_PROGRAMME", "chic", M::exact, I::none, kNone, true, S::control},
    {"FIN DU FICHIER", "chic", M::exact, I::none, kNone, true, S::control},
    {"FIN_DU_FICHIER", "chic", M::exact, I::none, kNone, true, S::control},
    {"NO CHECK CHIC COMMAND", "chic", M::exact, I::none, kNone, true, S::control},
};

}  // namespace

std::string_view support_name(CommandSupport support) {
  switch (support) {
    case CommandSupport::run:
      return "run";
    case CommandSupport::written:
      return "written";
    case CommandSupport::not_written:
      return "not written";
    case CommandSupport::warm_start:
      return "warm start differs";
    case CommandSupport::first_only:
      return "before the time loop only";
    case CommandSupport::script_only:
      return "when the script runs (lmgc-run)";
    case CommandSupport::not_run:
      return "not run";
    case CommandSupport::multiphysics:
      return "not run (multi-physics)";
    case CommandSupport::deformable:
      return "MAILx only";
    case CommandSupport::control:
      return "control";
  }
  return "run";
}

std::span<const CommandKeyword> command_catalogue() {
  return kKeywords;
}

const CommandKeyword* find_command_keyword(std::string_view text) {
  const CommandKeyword* best = nullptr;
  for (const CommandKeyword& k : kKeywords) {
    const bool matches =
        k.match == CommandMatch::exact ? text == k.keyword : text.substr(0, k.keyword.size()) == k.keyword;
    if (matches && (!best || k.keyword.size() > best->keyword.size())) best = &k;
  }
  return best;
}

}  // namespace lmgc::grammar
