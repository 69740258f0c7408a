// Round trip of Vloc_Rloc files: parse(write(ast)) == ast for generated interactions of every module.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

Real real() { return Real{*test::gen_d14_real()}; }

VlocRlocFile generated() {
  VlocRlocFile f;
  f.step = Integer{*rc::gen::inRange(0, 9999999)};
  f.time = real();
  const auto kinds = interaction_catalogue();
  for (int i = 0, n = *rc::gen::inRange(0, 6); i < n; ++i) {
    const InteractionKind& kind = kinds[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(kinds.size())))];
    VlocRlocInteraction c;
    c.type = Word{std::string(kind.type)};
    c.number = Integer{*rc::gen::inRange(1, 9999999)};
    c.title = std::string(kind.title);
    for (std::string_view f = kind.data_format; !f.empty();) {
      const std::size_t end = f.find(' ');
      const std::string_view item = f.substr(0, end);
      f = end == std::string_view::npos ? std::string_view() : f.substr(end + 1);
      if (item[0] == 'A') c.words.push_back(Word{*test::gen_word()});
      if (item[0] == 'I') c.integers.push_back(Integer{*rc::gen::inRange(0, 99999)});
    }
    for (const VectorLineKind& v : kind.vectors) {
      VlocRlocVector vec;
      for (int k = 0; k < v.count; ++k) {
        vec.labels.emplace_back(v.labels[k]);
        vec.values.push_back(real());
      }
      c.vectors.push_back(vec);
    }
    if (*rc::gen::arbitrary<bool>()) {
      c.internal_comment = "#taille_ele";
      c.internal_lines.push_back({real(), real()});
    }
    f.interactions.push_back(c);
  }
  return f;
}

RC_GTEST_PROP(VlocRlocRoundTrip, ParseOfWriteIsIdentity, ()) {
  const VlocRlocFile f = generated();
  DiagnosticSink sink;
  RC_ASSERT(parse_vloc_rloc(SourceText("Vloc_Rloc.LAST", write_vloc_rloc(f)), sink) == f);
  RC_ASSERT(!sink.has_errors());
}

RC_GTEST_PROP(VlocRlocRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const std::string text = write_vloc_rloc(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_vloc_rloc(parse_vloc_rloc(SourceText("Vloc_Rloc.LAST", text), sink)) == text);
}

}  // namespace
}  // namespace lmgc::grammar
