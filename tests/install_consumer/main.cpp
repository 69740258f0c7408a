// Reads a DOF.INI and a disk's contactor with lmgc's grammars and computes the disk's mass
// properties with its solver library: the headers and libraries of an installed lmgc at work.
#include <cstdio>

#include "grammar/dof/parser.hpp"
#include "solver/bodies/lmgc_pi.hpp"

int main() {
  lmgc::grammar::DiagnosticSink sink;
  const lmgc::grammar::DofFile dof = lmgc::grammar::parse_dof(
      lmgc::grammar::SourceText("DOF.INI", "! DOF\n$steps     12                time= 0.1200000D-01\n"),
      sink);
  if (sink.has_errors() || dof.step.value != 12) return 1;
  std::printf("step %lld, pi_g %.10f\n", static_cast<long long>(dof.step.value), lmgc::solver::lmgc_pi);
  return 0;
}
