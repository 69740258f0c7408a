#include "grammar/command/keyword_catalogue.hpp"

namespace lmgc::grammar {
namespace {

using A = CommandArgument;
constexpr A kReal[] = {A::real};
constexpr A kInteger[] = {A::integer};
constexpr A kWord[] = {A::word};
constexpr A kCheckType[] = {A::type_tolerance, A::real};
constexpr A kSolver[] = {A::word, A::type_tolerance, A::real, A::integer, A::integer};
constexpr A kLabel[] = {A::label};
constexpr A kSourcePoint[] = {A::integer, A::real, A::word};
constexpr A kCommand[] = {A::command};
constexpr std::span<const A> none() { return {}; }

constexpr CommandKeyword kKeywords[] = {
    // Time, integrator, global (chic_command_overall).
    {"DIME", kWord}, {"TIME STEP", kReal}, {"THETA", kReal}, {"THERMAL THETA", kReal}, {"FINAL TIME", kReal},
    {"MIN TIME STEP", kReal}, {"MAX TIME STEP", kReal}, {"NB BULK ITER MAX", kInteger},
    {"NB BULK ITE FOR GOOD CONV", kInteger}, {"NB BULK ITE FOR BAD CONV", kInteger},
    {"NB INC FOR GOODORBAD CONV", kInteger}, {"CHECK NL CONVERGENCE", kReal}, {"COMPUTE TIME STEP", none()},
    {"INCREMENT STEP", none()}, {"UPDATE DOF", none()}, {"UPDATE THERM DOF", none()},
    {"USE VERLET INTEGRATOR", none()}, {"USE GEAR INTEGRATOR", none()}, {"XXL COMPUTATION", none()},
    {"DISPLAY TIMES", none()}, {"SELECT PROX TACTORS", none()}, {"FD SELECT PROX TACTORS", none()},
    {"WCP SELECT PROX TACTORS", none()}, {"COMPUTE BOX", none()}, {"DISPLAY PROX TACTORS", none()},
    // Reading and writing.
    {"READ BODIES", none()}, {"READ BEHAVIOURS", none()}, {"READ MODELS", none()}, {"READ DRIVEN DOF", none()},
    {"READ INI DOF", none()}, {"READ INI Vloc Rloc", none()}, {"READ INI GPV", none()},
    {"READ MP BEHAVIOURS", none()}, {"WRITE BODIES", none()}, {"WRITE BEHAVIOURS", none()},
    {"WRITE MODELS", none()}, {"WRITE DRIVEN DOF", none()}, {"WRITE MP BEHAVIOURS", none()},
    {"LOAD BEHAVIOURS", none()}, {"LOAD MODELS", none()}, {"INIT MODELS", none()},
    {"INIT EXTERNAL MODELS", none()}, {"STORE PROPERTIES", none()}, {"PUSH PROPERTIES", none()},
    {"CHECK PROPERTIES", none()}, {"WRITE LAST DOF", none()}, {"WRITE LAST Vloc Rloc", none()},
    {"WRITE LAST GPV", none()}, {"WRITE LAST Rnod", none()}, {"WRITE OUT DOF", none()},
    {"WRITE OUT Vloc Rloc", none()}, {"WRITE OUT GPV", none()}, {"WRITE OUT Rnod", none()},
    {"WRITE OUT MP VALUES", none()}, {"DISPLAY OUT DOF", none()}, {"DISPLAY OUT Vloc Rloc", none()},
    {"DISPLAY OUT Rnod", none()}, {"BINARY WRITE LAST DOF", none()}, {"BINARY WRITE OUT DOF", none()},
    {"BINARY READ INI DOF", none()}, {"CLEAN BODIES.OUT", none()}, {"REBUILD BODIES.DAT", none()},
    {"CLEARED WRITE BODIES", none()}, {"WRITE OUT TIMER", none()},
    // Bodies.
    {"COMPUTE MASS", none()}, {"COMPUTE Fext", none()}, {"COMPUTE BULK", none()}, {"COMPUTE NL BULK", none()},
    {"COMPUTE FREE VELOCITY", none()}, {"COMPUTE NL FREE VELOCITY", none()}, {"COMPUTE DOF", none()},
    {"ASSEMB KT", none()}, {"ASSEMB RHS", none()}, {"ASSEMB NL KT", none()}, {"ASSEMB NL RHS", none()},
    {"UPDATE BULK", none()}, {"UPDATE NL BULK", none()}, {"FATAL DAMPING", none()}, {"PARTIAL DAMPING", kReal},
    {"CHECK EQUILIBRIUM STATE", none()}, {"NEW ROTATION SCHEME", none()}, {"INI V DOF NULL", none()},
    {"XPERIODIC CONDITION", kReal}, {"YPERIODIC CONDITION", kReal}, {"PERIODIC CONDITION", kReal},
    {"INIT YMIN BOUNDARY", kReal}, {"INIT YMAX BOUNDARY", kReal}, {"INIT XMIN BOUNDARY", kReal},
    {"INIT XMAX BOUNDARY", kReal}, {"INIT INF BOUNDARY", kReal}, {"INIT SUP BOUNDARY", kReal},
    {"INIT BACK BOUNDARY", kReal}, {"INIT FRONT BOUNDARY", kReal}, {"INIT LEFT BOUNDARY", kReal},
    {"INIT RIGHT BOUNDARY", kReal}, {"BIAXIAL DEF WALLS", none()}, {"CHECK SOURCE POINT", none()},
    {"INIT SOURCE POINT", kSourcePoint}, {"FD INIT SOURCE POINT", kSourcePoint}, {"GHOST TO INVISIBLE", none()},
    {"CONSTRUCT WALL", none()}, {"UPDATE WSvsT", none()}, {"INCREMENT WSvsT", none()},
    // Contact and solver.
    {"RECUP Rloc", none()}, {"SET TOL NEW RECUP Rloc", kReal}, {"STOCK Rloc", none()},
    {"SMOOTH FORCE COMPUTATION", none()}, {"REFERENCE RADIUS", kReal}, {"LOW SIZE ARRAY POLYR", kInteger},
    {"CUNDALL ITERATION", kInteger}, {"DIAGONAL RESOLUTION", none()}, {"FLIP ORIENTATION CSxxx", none()},
    {"NLGS CHECK TYPE", kCheckType}, {"EX PREP NLGS", kWord}, {"EX ITER NLGS", none()},
    {"AFTER ITER CHECK", none()}, {"DISPLAY AFTER ITER CHECK", none()}, {"EX POST NLGS", none()},
    {"EX NLGS SOLVER", kSolver}, {"UPDATE TACT BEHAV", none()}, {"INIT COHESIVE BEHAV", none()},
    {"SCRAMBLE", none()}, {"quickSCRAMBLE", none()}, {"REVERSE", none()}, {"BIMODAL LIST", none()},
    {"SCALE NLGS Rloc", none()}, {"Rnod = [H] Rloc", none()}, {"DISPLAY RlocN SUM", none()},
    {"NLGS NORM CHECK", none()},
    // Post-processing and display.
    {"INIT POST 3D", none()}, {"INIT POST", none()}, {"START POSTPRO", none()},
    {"POSTPRO DURING COMPUTATION", none()}, {"UPDATE POST 3D", none()}, {"UPDATE POST", none()},
    {"POSTPRO AFTER COMPUTATION", none()}, {"CLOSE POSTPRO FILES", none()}, {"INIT GMV", none()},
    {"WRITE OUTPUT GMV", none()}, {"WRITE LAST GMV", none()}, {"DISPLAY TACTORS", none()},
    {"DISPLAY TACTOR", none()}, {"DISPLAY POSITION", none()}, {"DISPLAY AVERAGE VELOCITY", none()},
    {"DISPLAY STRESS", none()}, {"DISPLAY STRAIN", none()}, {"DISPLAY DISPLACEMENT", none()},
    {"DISPLAY FORCES", none()}, {"DISPLAY HEAT", none()}, {"DISPLAY MECHANICAL GPV", none()},
    {"DISPLAY TACT POINTS", none()}, {"DISPLAY TACT POINT", none()}, {"DISPLAY INTERACTION", none()},
    {"DISPLAY WITH VTK", none()}, {"DISPLAY BEFORE COMPUTATION", none()}, {"DISPLAY DURING COMPUTATION", none()},
    {"DISPLAY AFTER COMPUTATION", none()},
    // Control structures (CHIC).
    {"APPELLE", none()}, {"SUB", none()}, {"RETOUR", none()}, {"REPETE", kLabel}, {"DEPUIS", none()},
    {"STOP REPETE SI IOK", none()}, {"IOK = FLAG", kCommand}, {"IOK =", none()}, {"FLAG", kCommand},
    {"ROK =", none()}, {"DRAP", kCommand}, {"CAP SI IOK", kCommand}, {"INTO", none()}, {"SUR", none()},
    {"OCCURENCE", none()}, {"ECHO ON", none()}, {"ECHO OFF", none()}, {"PAUSE", none()},
    {"TOTALISATEURS A ZERO", none()}, {"AFFICHE TOTALISATEURS", none()}, {"AFFICHE COMPTEURS", none()},
    {"ECRIT COMPTEURS", none()}, {"ECRIT TOTALISATEURS", none()}, {"OUVRE", none()}, {"FERME", none()},
    {"ECRIT DRAP TS LES", none()}, {"NO CHECK CHIC COMMAND", none()}, {"FIN DU PROGRAMME", none()},
    {"FIN_DU_PROGRAMME", none()}, {"FIN DU FICHIER", none()},
};

}  // namespace

std::span<const CommandKeyword> command_keyword_catalogue() { return kKeywords; }

const CommandKeyword* match_command_keyword(std::string_view statement) {
  const CommandKeyword* best = nullptr;
  for (const CommandKeyword& k : kKeywords)
    if (statement.substr(0, k.keyword.size()) == k.keyword && (!best || k.keyword.size() > best->keyword.size()))
      best = &k;
  return best;
}

}  // namespace lmgc::grammar
