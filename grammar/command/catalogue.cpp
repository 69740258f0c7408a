#include "grammar/command/catalogue.hpp"

namespace lmgc::grammar {
namespace {

using A = CommandArgumentKind;
using M = CommandMatch;
using I = CommandInline;

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
// spec: state-and-outputs.md §2.1.2-2.1.3.
constexpr CommandKeyword kKeywords[] = {
    // Time, integrator, global (overall).
    {"DIME", "overall", M::prefix, I::none, kWord},
    {"TIME STEP", "overall", M::prefix, I::none, kReal},
    {"THETA", "overall", M::prefix, I::none, kReal},
    {"THERMAL THETA", "overall", M::prefix, I::none, kReal},
    {"FINAL TIME", "overall", M::prefix, I::none, kReal},
    {"MIN TIME STEP", "overall", M::prefix, I::none, kReal},
    {"MAX TIME STEP", "overall", M::prefix, I::none, kReal},
    {"NB BULK ITER MAX", "overall", M::prefix, I::none, kInteger},
    {"NB BULK ITE FOR GOOD CONV", "overall", M::prefix, I::none, kInteger},
    {"NB BULK ITE FOR BAD CONV", "overall", M::prefix, I::none, kInteger},
    {"NB INC FOR GOODORBAD CONV", "overall", M::prefix, I::none, kInteger},
    {"CHECK NL CONVERGENCE", "overall", M::prefix, I::none, kReal},
    {"COMPUTE TIME STEP", "overall", M::prefix, I::none, kNone},
    {"INCREMENT STEP", "overall", M::prefix, I::none, kNone},
    {"UPDATE DOF", "overall", M::prefix, I::none, kNone},
    {"UPDATE THERM DOF", "overall", M::prefix, I::none, kNone},
    {"USE VERLET INTEGRATOR", "overall", M::prefix, I::none, kNone},
    {"USE GEAR INTEGRATOR", "overall", M::prefix, I::none, kNone},
    {"XXL COMPUTATION", "overall", M::prefix, I::none, kNone},
    {"DISPLAY TIMES", "overall", M::prefix, I::none, kNone},
    {"SELECT PROX TACTORS", "overall", M::prefix, I::step_or_dtps, kNone},
    {"FD SELECT PROX TACTORS", "overall", M::prefix, I::step_or_dtps, kNone},
    {"WCP SELECT PROX TACTORS", "overall", M::prefix, I::step_or_dtps, kNone},
    {"COMPUTE BOX", "overall", M::prefix, I::none, kNone},
    {"DISPLAY PROX TACTORS", "overall", M::prefix, I::none, kNone},
    // Reading and writing.
    {"READ BODIES", "overall", M::prefix, I::none, kNone},
    {"READ BEHAVIOURS", "overall", M::prefix, I::none, kNone},
    {"READ MODELS", "overall", M::prefix, I::none, kNone},
    {"READ DRIVEN DOF", "overall", M::prefix, I::none, kNone},
    {"READ INI DOF", "overall", M::prefix, I::none, kNone},
    {"READ INI Vloc Rloc", "overall", M::prefix, I::none, kNone},
    {"READ INI GPV", "overall", M::prefix, I::none, kNone},
    {"READ MP BEHAVIOURS", "overall", M::prefix, I::none, kNone},
    {"WRITE BODIES", "overall", M::prefix, I::none, kNone},
    {"WRITE BEHAVIOURS", "overall", M::prefix, I::none, kNone},
    {"WRITE MODELS", "overall", M::prefix, I::none, kNone},
    {"WRITE DRIVEN DOF", "overall", M::prefix, I::none, kNone},
    {"WRITE MP BEHAVIOURS", "overall", M::prefix, I::none, kNone},
    {"WRITE LAST DOF", "overall", M::prefix, I::none, kNone},
    {"WRITE LAST Vloc Rloc", "overall", M::prefix, I::none, kNone},
    {"WRITE LAST GPV", "overall", M::prefix, I::none, kNone},
    {"WRITE LAST Rnod", "overall", M::prefix, I::none, kNone},
    {"WRITE OUT DOF", "overall", M::prefix, I::step_or_dtps, kNone},
    {"WRITE OUT Vloc Rloc", "overall", M::prefix, I::step_or_dtps, kNone},
    {"WRITE OUT GPV", "overall", M::prefix, I::step_or_dtps, kNone},
    {"WRITE OUT Rnod", "overall", M::prefix, I::step_or_dtps, kNone},
    {"WRITE OUT MP VALUES", "overall", M::prefix, I::step_or_dtps, kNone},
    {"FROM TO", "overall", M::prefix, I::text, kNone},
    {"DISPLAY OUT DOF", "overall", M::prefix, I::none, kNone},
    {"DISPLAY OUT Vloc Rloc", "overall", M::prefix, I::none, kNone},
    {"DISPLAY OUT Rnod", "overall", M::prefix, I::none, kNone},
    {"BINARY WRITE LAST DOF", "overall", M::prefix, I::none, kNone},
    {"BINARY WRITE OUT DOF", "overall", M::prefix, I::step_or_dtps, kNone},
    {"BINARY READ INI DOF", "overall", M::prefix, I::none, kNone},
    {"CLEAN BODIES.OUT", "overall", M::prefix, I::none, kNone},
    {"REBUILD BODIES.DAT", "overall", M::prefix, I::none, kNone},
    {"CLEARED WRITE BODIES", "overall", M::prefix, I::none, kNone},
    {"WRITE OUT TIMER", "overall", M::prefix, I::none, kNone},
    // Finite-element models.
    {"LOAD BEHAVIOURS", "models", M::prefix, I::none, kNone},
    {"LOAD MODELS", "models", M::prefix, I::none, kNone},
    {"INIT MODELS", "models", M::prefix, I::none, kNone},
    {"INIT EXTERNAL MODELS", "models", M::prefix, I::none, kNone},
    {"STORE PROPERTIES", "models", M::prefix, I::none, kNone},
    {"PUSH PROPERTIES", "models", M::prefix, I::none, kNone},
    {"CHECK PROPERTIES", "models", M::prefix, I::none, kNone},
    // Bodies (RBDY2, RBDY3, mecaMAILx, therMAILx: each acts when it has bodies).
    {"COMPUTE MASS", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE Fext", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE BULK", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE NL BULK", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE Fint", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE FREE VELOCITY", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE NL FREE VELOCITY", "bodies", M::prefix, I::none, kNone},
    {"COMPUTE DOF", "bodies", M::prefix, I::none, kNone},
    {"ASSEMB KT", "bodies", M::prefix, I::none, kNone},
    {"ASSEMB RHS", "bodies", M::prefix, I::none, kNone},
    {"ASSEMB NL KT", "bodies", M::prefix, I::none, kNone},
    {"ASSEMB NL RHS", "bodies", M::prefix, I::none, kNone},
    {"UPDATE BULK", "bodies", M::prefix, I::none, kNone},
    {"UPDATE NL BULK", "bodies", M::prefix, I::none, kNone},
    {"FATAL DAMPING", "bodies", M::prefix, I::step_or_dtps, kNone},
    {"PARTIAL DAMPING", "bodies", M::prefix, I::none, kReal},
    {"CHECK EQUILIBRIUM STATE", "bodies", M::prefix, I::none, kNone},
    {"NEW ROTATION SCHEME", "bodies", M::prefix, I::none, kNone},
    {"INI V DOF NULL", "bodies", M::prefix, I::none, kNone},
    {"INI X DOF NULL", "bodies", M::prefix, I::none, kNone},
    {"PERIODIC CONDITION", "bodies", M::prefix, I::none, kReal},
    {"XPERIODIC CONDITION", "bodies", M::prefix, I::none, kReal},
    {"YPERIODIC CONDITION", "bodies", M::prefix, I::none, kReal},
    {"INIT INF BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT SUP BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT LEFT BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT RIGHT BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT FRONT BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT BACK BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT XMIN BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT XMAX BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT YMIN BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT YMAX BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT ZMIN BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT ZMAX BOUNDARY", "bodies", M::prefix, I::none, kReal},
    {"INIT SOURCE POINT", "bodies", M::prefix, I::none, kSourcePoint},
    {"FD INIT SOURCE POINT", "bodies", M::prefix, I::none, kSourcePoint},
    {"CHECK SOURCE POINT", "bodies", M::prefix, I::none, kNone},
    {"GHOST TO INVISIBLE", "bodies", M::prefix, I::none, kNone},
    {"INIT CONSTRUCT WALL", "bodies", M::prefix, I::none, kTwoReals},
    {"BIAXIAL DEF WALLS", "bodies", M::prefix, I::none, kBiaxialWalls},
    {"UPDATE WSvsT", "bodies", M::prefix, I::none, kNone},
    {"INCREMENT WSvsT", "bodies", M::prefix, I::none, kNone},
    // Contact and solver (contact modules, nlgs).
    {"RECUP Rloc", "contact", M::prefix, I::none, kNone},
    {"SET TOL NEW RECUP Rloc", "contact", M::prefix, I::none, kReal},
    {"STOCK Rloc", "contact", M::prefix, I::none, kNone},
    {"SMOOTH FORCE COMPUTATION", "contact", M::prefix, I::none, kNone},
    {"REFERENCE RADIUS", "contact", M::prefix, I::none, kReal},
    {"LOW SIZE ARRAY POLYR", "contact", M::prefix, I::none, kInteger},
    {"CUNDALL ITERATION", "contact", M::prefix, I::none, kInteger},
    {"DIAGONAL RESOLUTION", "contact", M::prefix, I::none, kNone},
    {"FLIP ORIENTATION CSxxx", "contact", M::prefix, I::none, kNone},
    {"NLGS CHECK TYPE", "nlgs", M::prefix, I::none, kNlgsCheck},
    {"EX PREP NLGS", "nlgs", M::prefix, I::none, kWord},
    {"EX ITER NLGS", "nlgs", M::prefix, I::none, kNone},
    {"AFTER ITER CHECK", "nlgs", M::prefix, I::none, kNone},
    {"DISPLAY AFTER ITER CHECK", "nlgs", M::prefix, I::none, kNone},
    {"EX POST NLGS", "nlgs", M::prefix, I::none, kNone},
    {"EX NLGS SOLVER", "nlgs", M::prefix, I::none, kNlgsSolver},
    {"UPDATE TACT BEHAV", "nlgs", M::prefix, I::none, kNone},
    {"INIT COHESIVE BEHAV", "nlgs", M::prefix, I::none, kNone},
    {"SCRAMBLE", "nlgs", M::prefix, I::none, kNone},
    {"quickSCRAMBLE", "nlgs", M::prefix, I::none, kNone},
    {"REVERSE", "nlgs", M::prefix, I::none, kNone},
    {"BIMODAL LIST", "nlgs", M::prefix, I::none, kNone},
    {"SCALE NLGS Rloc", "nlgs", M::prefix, I::none, kNone},
    {"Rnod = [H] Rloc", "nlgs", M::prefix, I::none, kNone},
    {"DISPLAY RlocN SUM", "nlgs", M::prefix, I::none, kNone},
    {"NLGS NORM CHECK", "nlgs", M::prefix, I::none, kNone},
    // Post-processing (reads POSTPRO.DAT) and display.
    {"INIT POST", "postpro", M::prefix, I::none, kNone},
    {"INIT POST 3D", "postpro", M::prefix, I::none, kNone},
    {"START POSTPRO", "postpro", M::prefix, I::none, kNone},
    {"POSTPRO DURING COMPUTATION", "postpro", M::prefix, I::none, kNone},
    {"UPDATE POST", "postpro", M::prefix, I::none, kNone},
    {"UPDATE POST 3D", "postpro", M::prefix, I::none, kNone},
    {"POSTPRO AFTER COMPUTATION", "postpro", M::prefix, I::none, kNone},
    {"CLOSE POSTPRO FILES", "postpro", M::prefix, I::none, kNone},
    {"INIT GMV", "display", M::prefix, I::none, kNone},
    {"WRITE OUTPUT GMV", "display", M::prefix, I::step_or_dtps, kNone},
    {"WRITE LAST GMV", "display", M::prefix, I::none, kNone},
    {"DISPLAY TACTOR", "display", M::prefix, I::none, kNone},
    {"DISPLAY TACTORS", "display", M::prefix, I::none, kNone},
    {"DISPLAY POSITION", "display", M::prefix, I::none, kNone},
    {"DISPLAY AVERAGE VELOCITY", "display", M::prefix, I::none, kNone},
    {"DISPLAY STRESS", "display", M::prefix, I::none, kNone},
    {"DISPLAY STRAIN", "display", M::prefix, I::none, kNone},
    {"DISPLAY DISPLACEMENT", "display", M::prefix, I::none, kNone},
    {"DISPLAY FORCES", "display", M::prefix, I::none, kNone},
    {"DISPLAY HEAT", "display", M::prefix, I::none, kNone},
    {"DISPLAY MECHANICAL GPV", "display", M::prefix, I::none, kNone},
    {"DISPLAY TACT POINT", "display", M::prefix, I::none, kNone},
    {"DISPLAY TACT POINTS", "display", M::prefix, I::none, kNone},
    {"DISPLAY INTERACTION", "display", M::prefix, I::none, kNone},
    {"DISPLAY WITH VTK", "display", M::prefix, I::none, kNone},
    {"DISPLAY BEFORE COMPUTATION", "display", M::prefix, I::none, kNone},
    {"DISPLAY DURING COMPUTATION", "display", M::prefix, I::none, kNone},
    {"DISPLAY AFTER COMPUTATION", "display", M::prefix, I::none, kNone},
    // CHIC's own words (mod_chic: CHIC_comp, CHIC_comd, CHECK_CHIC_COMMAND).
    {"APPEL", "chic", M::prefix, I::text, kNone, true},  // 'APPELLE name': CHIC tests 5 characters
    {"SUB ", "chic", M::prefix, I::text, kNone, true},
    {"RETOUR", "chic", M::exact, I::none, kNone, true},
    {"REPETE", "chic", M::prefix, I::text, kNone, true},
    {"DEPUIS", "chic", M::prefix, I::text, kNone, true},
    {"STOP REPETE SI IOK =", "chic", M::prefix, I::text, kNone, true},
    {"CAP SI IOK =", "chic", M::prefix, I::text, kNone, true},
    {"SUR ", "chic", M::prefix, I::text, kNone, true},
    {"IOK =", "chic", M::prefix, I::text, kNone, true},
    {"ROK =", "chic", M::prefix, I::text, kNone, true},
    {"FLAG", "chic", M::prefix, I::text, kNone, true},
    {"DRAP", "chic", M::prefix, I::text, kNone, true},
    {"INTO ", "chic", M::prefix, I::text, kNone, true},
    {"OCCURENCE", "chic", M::prefix, I::text, kNone, true},
    {"ECHO ON", "chic", M::exact, I::none, kNone, true},
    {"ECHO OFF", "chic", M::exact, I::none, kNone, true},
    {"PAUSE", "chic", M::prefix, I::none, kNone, true},
    {"TOTALISATEURS A ZERO", "chic", M::exact, I::none, kNone, true},
    {"AFFICHE TOTALISATEURS", "chic", M::exact, I::none, kNone, true},
    {"AFFICHE COMPTEURS", "chic", M::exact, I::none, kNone, true},
    {"ECRIT TOTALISATEURS", "chic", M::exact, I::none, kNone, true},
    {"ECRIT COMPTEURS", "chic", M::exact, I::none, kNone, true},
    {"ECRIT DRAP TS LES", "chic", M::exact, I::none, kWord, true},
    {"OUVRE", "chic", M::prefix, I::text, kNone, true},
    {"FERME", "chic", M::prefix, I::text, kNone, true},
    {"FIN DU PROGRAMME", "chic", M::exact, I::none, kNone, true},
    {"FIN_DU_PROGRAMME", "chic", M::exact, I::none, kNone, true},
    {"FIN DU FICHIER", "chic", M::exact, I::none, kNone, true},
    {"FIN_DU_FICHIER", "chic", M::exact, I::none, kNone, true},
    {"NO CHECK CHIC COMMAND", "chic", M::exact, I::none, kNone, true},
};

}  // namespace

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
