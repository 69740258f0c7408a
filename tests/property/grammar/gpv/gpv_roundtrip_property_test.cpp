// Round trip of GPV files: parse(write(ast)) == ast for generated bodies and Gauss-point values.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/gpv/parser.hpp"
#include "grammar/gpv/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

GpvFile generated() {
  GpvFile f;
  f.step = Integer{*rc::gen::inRange(0, 9999999)};
  f.time = Real{*test::gen_d14_real()};
  for (int b = 0, nb = *rc::gen::inRange(0, 3); b < nb; ++b) {
    GpvBody body;
    body.number = Integer{b + 1};
    for (int e = 0, ne = *rc::gen::inRange(1, 4); e < ne; ++e) {
      GpvElement el;
      el.type =
          Word{*rc::gen::elementOf(std::vector<std::string>{"T3xxx", "Q4xxx", "H8xxx", "TE4xx", "PRI15"})};
      el.number = Integer{e + 1};
      GpvModelBlock m;
      m.model = Word{*rc::gen::elementOf(std::vector<std::string>{"MECAx", "THERM", "THMCx", "POROx"})};
      for (int l = 0, nl = *rc::gen::inRange(1, 6); l < nl; ++l) {
        std::vector<Real> line;
        // 0 values: LMGC90 writes an empty record for an empty vector.
        for (int v = 0, nv = *rc::gen::inRange(0, 10); v < nv; ++v)
          line.push_back(Real{*test::gen_d14_real()});
        m.lines.push_back(line);
      }
      el.models.push_back(m);
      body.elements.push_back(el);
    }
    f.bodies.push_back(body);
  }
  return f;
}

RC_GTEST_PROP(GpvRoundTrip, ParseOfWriteIsIdentity, ()) {
  const GpvFile f = generated();
  DiagnosticSink sink;
  RC_ASSERT(parse_gpv(SourceText("GPV.LAST", write_gpv(f)), sink) == f);
  RC_ASSERT(!sink.has_errors());
}

RC_GTEST_PROP(GpvRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const std::string text = write_gpv(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_gpv(parse_gpv(SourceText("GPV.LAST", text), sink)) == text);
}

}  // namespace
}  // namespace lmgc::grammar
