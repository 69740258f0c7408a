// parse(write(ast)) == ast and write(parse(write(ast))) == write(ast) for generated DOF ASTs
// (RBDY2, RBDY3 with frame, MAILx MECAx/POROx with optional rigid part, MAILx THERM).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <string>
#include <vector>

#include "grammar/dof/parser.hpp"
#include "grammar/dof/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

std::vector<Real> gen_reals(int count) {
  std::vector<Real> values;
  for (int i = 0; i < count; ++i) values.push_back(*test::gen_d14_real());
  return values;
}

DofNode gen_node(const std::string& type, int number, int count, bool with_velocity, bool with_frame) {
  DofNode node;
  node.node_type = type;
  node.number = number;
  node.x = gen_reals(count);
  if (with_velocity) node.v = gen_reals(count);
  if (with_frame) node.frame = gen_reals(9);
  return node;
}

DofBody gen_body() {
  DofBody body;
  switch (*rc::gen::inRange(0, 4)) {
    case 0:
      body.body_type = std::string("RBDY2");
      body.number = *rc::gen::inRange(1, 10000000);
      body.nodes.push_back(gen_node("NO3xx", 1, 3, true, false));
      break;
    case 1:
      body.body_type = std::string("RBDY3");
      body.number = *rc::gen::inRange(1, 10000000);
      body.nodes.push_back(gen_node("NO6xx", 1, 6, true, true));
      break;
    case 2: {
      body.body_type = std::string("MAILx");
      body.number = *rc::gen::inRange(1, 10000000);
      body.model = std::string(*rc::gen::arbitrary<bool>() ? "MECAx" : "POROx");
      const int dimension = *rc::gen::inRange(2, 4);
      const int count = *rc::gen::inRange(1, 6);
      for (int i = 0; i < count; ++i)
        body.nodes.push_back(gen_node(dimension == 3 ? "NO3xx" : "NO2xx", *rc::gen::inRange(1, 1000000),
                                      dimension, true, false));
      if (*rc::gen::inRange(0, 3) == 0)
        body.rigid_part =
            dimension == 3 ? gen_node("NO6xx", 0, 6, true, true) : gen_node("NO3xx", 0, 3, true, false);
      break;
    }
    default: {
      body.body_type = std::string("MAILx");
      body.number = *rc::gen::inRange(1, 10000000);
      body.model = std::string("THERM");
      const int count = *rc::gen::inRange(1, 6);
      for (int i = 0; i < count; ++i)
        body.nodes.push_back(gen_node("NO1xx", *rc::gen::inRange(1, 1000000), 1, false, false));
      break;
    }
  }
  return body;
}

DofFile gen_dof_file() {
  DofFile file;
  file.step = *rc::gen::inRange(0, 10000000);
  file.time = *test::gen_d14_real();
  const int sections = *rc::gen::inRange(0, 4);
  for (int s = 0; s < sections; ++s) {
    DofSection section;
    const int bodies = *rc::gen::inRange(0, 4);
    for (int b = 0; b < bodies; ++b) section.bodies.push_back(gen_body());
    // Only the last section may be open, and an open section holds bodies.
    section.closed = s + 1 < sections || section.bodies.empty() || *rc::gen::arbitrary<bool>();
    file.sections.push_back(section);
  }
  return file;
}

RC_GTEST_PROP(DofRoundTrip, ParseOfWriteIsIdentity, ()) {
  const DofFile file = gen_dof_file();
  const std::string text = write_dof(file);
  DiagnosticSink sink;
  const DofFile parsed = parse_dof(SourceText("DOF.OUT.1", text), sink);
  RC_ASSERT(sink.items().empty());
  RC_ASSERT(parsed == file);
  RC_ASSERT(write_dof(parsed) == text);
}

}  // namespace
}  // namespace lmgc::grammar
