// Round trip of MODELS.DAT: parse(write(ast)) == ast for generated models.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/models/parser.hpp"
#include "grammar/models/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

ModelsFile generated() {
  ModelsFile f;
  for (int i = 0, n = *rc::gen::inRange(1, 5); i < n; ++i) {
    Model m;
    m.nickname = Word{*test::gen_word()};
    m.kind = Word{*rc::gen::elementOf(std::vector<std::string>{"MECAx", "THERM", "POROx"})};
    m.element = Word{*rc::gen::elementOf(std::vector<std::string>{"Q4xxx", "T3xxx", "H8xxx", "TE4xx"})};
    for (int k = 0, no = *rc::gen::inRange(0, 6); k < no; ++k) {
      ModelOption o;
      o.id = Word{*rc::gen::elementOf(std::vector<std::string>{"isext", "kine_", "form_", "mater", "extvf"})};
      o.value = Word{*test::gen_word(*rc::gen::inRange(1, 20))};
      if (o.id.value == "extvf") o.vfield_size = Integer{*rc::gen::inRange(0, 99999)};
      m.options.push_back(o);
    }
    f.models.push_back(m);
  }
  return f;
}

RC_GTEST_PROP(ModelsRoundTrip, ParseOfWriteIsIdentity, ()) {
  const ModelsFile f = generated();
  DiagnosticSink sink;
  RC_ASSERT(parse_models(SourceText("MODELS.DAT", write_models(f)), sink) == f);
  RC_ASSERT(!sink.has_errors());
}

RC_GTEST_PROP(ModelsRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const std::string text = write_models(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_models(parse_models(SourceText("MODELS.DAT", text), sink)) == text);
}

}  // namespace
}  // namespace lmgc::grammar
