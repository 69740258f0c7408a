// Round trip of MODELS.DAT: parse(write(ast)) == ast for generated models.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/models/parser.hpp"
#include "grammar/models/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

// An option value as LMGC90 keeps it: up to 30 characters, no trailing blank.
std::string option_value() {
  std::string v = *test::gen_word(*rc::gen::inRange(1, 25));
  if (*rc::gen::inRange(0, 4) == 0) v = " " + v;  // leading blanks are part of the A30 value
  return v;
}

ModelsFile generated() {
  ModelsFile f;
  // At least one model: an empty file is reported (L1009).
  for (int i = 0, n = *rc::gen::inRange(1, 5); i < n; ++i) {
    Model m;
    m.nickname = Word{*test::gen_word()};
    m.kind = Word{*rc::gen::elementOf(std::vector<std::string>{"MECAx", "THERM", "POROx", "MULTI"})};
    m.element =
        Word{*rc::gen::elementOf(std::vector<std::string>{"Q4xxx", "T3xxx", "H8xxx", "TE4xx", "Q4P0x"})};
    if (*rc::gen::inRange(0, 4) == 0) m.user_model = Word{*test::gen_word(*rc::gen::inRange(1, 51))};
    bool extvf_after_mdlty_line = false;
    for (int k = 0, no = *rc::gen::inRange(0, 6); k < no; ++k) {
      ModelOption o;
      o.id = Word{*rc::gen::elementOf(
          std::vector<std::string>{"isext", "kine_", "form_", "mater", "extvf", "extsf", "mstrg"})};
      o.value = Word{option_value()};
      extvf_after_mdlty_line |= o.id.value == "extvf" && (k > 0 || !m.user_model.value.empty());
      m.options.push_back(o);
    }
    // LMGC90 writes the size only on 'extvf' lines after the mdlty line.
    if (extvf_after_mdlty_line) m.vfield_max_size = Integer{*rc::gen::inRange(0, 99999)};
    f.models.push_back(m);
  }
  return f;
}

RC_GTEST_PROP(ModelsRoundTrip, ParseOfWriteIsIdentity, ()) {
  const ModelsFile f = generated();
  DiagnosticSink sink;
  RC_ASSERT(parse_models(SourceText("MODELS.DAT", write_models(f)), sink) == f);
  RC_ASSERT(sink.items().empty());
}

RC_GTEST_PROP(ModelsRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const std::string text = write_models(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_models(parse_models(SourceText("MODELS.DAT", text), sink)) == text);
}

// The parser never throws nor crashes: canonical text with random bytes overwritten, lines cut
// short or dropped still parses (diagnostics are allowed).
RC_GTEST_PROP(ModelsRobustness, ParserNeverCrashesOnDamagedText, ()) {
  const std::string text = test::damaged_text(write_models(generated()));
  DiagnosticSink sink;
  parse_models(SourceText("DAMAGED", text), sink);
  RC_SUCCEED();
}

}  // namespace
}  // namespace lmgc::grammar
