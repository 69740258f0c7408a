// parse(write(ast)) == ast for generated DRV_DOF and evolution ASTs in canonical form (the echo
// sorts bodies, nodes and dofs, so generated ASTs are sorted the same way).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "grammar/drv_dof/parser.hpp"
#include "grammar/drv_dof/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

// Sorted distinct integers in [low, high], at least one.
rc::Gen<std::vector<int>> gen_sorted_distinct(int low, int high, int most) {
  return rc::gen::map(rc::gen::container<std::vector<int>>(rc::gen::inRange(low, high + 1)),
                      [=](std::vector<int> drawn) {
                        std::set<int> values(drawn.begin(), drawn.end());
                        if (values.empty()) values.insert(low);
                        std::vector<int> out(values.begin(), values.end());
                        if (static_cast<int>(out.size()) > most) out.resize(static_cast<std::size_t>(most));
                        return out;
                      });
}

DrivenDof gen_dof(const std::string& kind, int number) {
  DrivenDof dof;
  dof.kind = kind;
  dof.dof = number;
  dof.uses_evolution = *rc::gen::inRange(0, 4) == 0;
  if (dof.uses_evolution) {
    const int length = *rc::gen::inRange(1, 41);
    dof.evolution_file = *test::gen_word(length);
  } else {
    for (auto& parameter : dof.parameters) parameter = *test::gen_d14_real();
  }
  return dof;
}

// Dofs sorted by number; per number the first kind, the second kind, or both in that order.
std::vector<DrivenDof> gen_dofs(int count, const std::string& first, const std::string& second) {
  std::vector<DrivenDof> dofs;
  for (int number : *gen_sorted_distinct(1, count, count)) {
    const int which = *rc::gen::inRange(0, 3);
    if (which != 1) dofs.push_back(gen_dof(first, number));
    if (which != 0) dofs.push_back(gen_dof(second, number));
  }
  return dofs;
}

DrvDofFile gen_drv_dof_file() {
  DrvDofFile file;
  const bool three_d = *rc::gen::arbitrary<bool>();
  const int dimension = three_d ? 3 : 2;
  // RBDY3 echo writes the rank (1X,A5,I7), i.e. in columns 7-13, but the reader takes 9-15: a
  // rank of 6 or 7 digits does not read back (LMGC90's own echo has the same limit).
  for (int rank : *gen_sorted_distinct(1, three_d ? 99999 : 9999999, 4)) {
    DrvDofBody body;
    body.body_type = std::string(three_d ? "RBDY3" : "RBDY2");
    body.rank = rank;
    DrvDofNode node;
    node.node_type = std::string(three_d ? "NO6xx" : "NO3xx");
    node.number = 1;
    node.dofs = gen_dofs(three_d ? 6 : 3, "vlocy", "force");
    body.nodes.push_back(node);
    file.bodies.push_back(body);
  }
  struct ModelKind {
    const char* model;
    const char* first;
    const char* second;
  };
  for (const ModelKind kind : {ModelKind{"MECAx", "vlocy", "force"}, ModelKind{"THERM", "temp", "flux"},
                               ModelKind{"POROx", "vlocy", "force"}}) {
    if (*rc::gen::inRange(0, 3) == 0) continue;
    for (int rank : *gen_sorted_distinct(1, 9999999, 3)) {
      DrvDofBody body;
      body.body_type = std::string("MAILx");
      body.rank = rank;
      body.model = std::string(kind.model);
      const bool thermal = std::string(kind.model) == "THERM";
      for (int number : *gen_sorted_distinct(1, 9999999, 4)) {
        DrvDofNode node;
        node.node_type = std::string(thermal ? "NO1xx" : (dimension == 3 ? "NO3xx" : "NO2xx"));
        node.number = number;
        node.dofs = gen_dofs(thermal ? 1 : dimension, kind.first, kind.second);
        body.nodes.push_back(node);
      }
      file.bodies.push_back(body);
    }
  }
  return file;
}

RC_GTEST_PROP(DrvDofRoundTrip, ParseOfWriteIsIdentity, ()) {
  const DrvDofFile file = gen_drv_dof_file();
  const std::string text = write_drv_dof(file);
  DiagnosticSink sink;
  const DrvDofFile parsed = parse_drv_dof(SourceText("DRV_DOF.OUT", text), sink);
  RC_ASSERT(sink.items().empty());
  RC_ASSERT(parsed == file);
  RC_ASSERT(write_drv_dof(parsed) == text);
}

RC_GTEST_PROP(EvolutionRoundTrip, ParseOfWriteIsIdentity, ()) {
  // Any finite doubles: 17 significant digits read back exactly.
  auto times = *rc::gen::container<std::set<double>>(
      rc::gen::suchThat(rc::gen::arbitrary<double>(), [](double x) { return std::isfinite(x); }));
  times.insert(0.0);
  times.insert(1.0);
  EvolutionFile file;
  for (double time : times) {
    double value =
        *rc::gen::suchThat(rc::gen::arbitrary<double>(), [](double x) { return std::isfinite(x); });
    if (value == 0.0) value = 0.0;  // -0.0 is written as 0
    file.points.push_back(EvolutionPoint{time == 0.0 ? 0.0 : time, value});
  }
  const std::string text = write_evolution(file);
  DiagnosticSink sink;
  const EvolutionFile parsed = parse_evolution(SourceText("evolution", text), sink);
  RC_ASSERT(sink.items().empty());
  RC_ASSERT(parsed == file);
  RC_ASSERT(write_evolution(parsed) == text);
}

}  // namespace
}  // namespace lmgc::grammar
