// Round trip of Vloc_Rloc files: parse(write(ast)) == ast for generated interactions of every
// module of the catalogue (normal and xxl layouts), with internal variables laid out as each
// module writes them (6 or 5 per line without names for DKDKx/DKJCx, one line after the '#'
// names line otherwise, up to 17 values so the line passes column 180).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

Real real() {
  return Real{*test::gen_d14_real()};
}

// Largest value an Iw field holds.
std::int64_t largest(int width) {
  std::int64_t value = 1;
  for (int k = 0; k < width && k < 9; ++k) value *= 10;
  return value - 1;
}

VlocRlocInteraction generated_interaction(const InteractionKind& kind) {
  VlocRlocInteraction c;
  c.type = Word{std::string(kind.type)};
  c.xxl = kind.xxl;
  c.number = Integer{*rc::gen::inRange<std::int64_t>(1, largest(kind.icdan_width) + 1)};
  c.title = std::string(kind.title);
  for (const DataItem& item : data_items(kind.data_format)) {
    if (item.kind == 'A') c.words.push_back(Word{*test::gen_word()});
    if (item.kind == 'I')
      c.integers.push_back(Integer{*rc::gen::inRange<std::int64_t>(0, largest(item.width) + 1)});
  }
  for (const VectorLineKind& v : kind.vectors) {
    VlocRlocVector vec;
    for (int k = 0; k < v.count; ++k) {
      vec.labels.emplace_back(v.labels[k]);
      vec.values.push_back(real());
    }
    c.vectors.push_back(vec);
  }
  const int internals = *rc::gen::inRange(0, 18);
  if (internals == 0) return c;
  std::vector<Real> values;
  for (int k = 0; k < internals; ++k) values.push_back(real());
  const std::size_t per_line = kind.internals == InternalLayout2D::per_line_6   ? 6
                               : kind.internals == InternalLayout2D::per_line_5 ? 5
                                                                                : values.size();
  if (kind.internals == InternalLayout2D::one_line_with_comment) {
    c.internal_comment = std::string(285, ' ');
    c.internal_comment.replace(0, 11, "#taille_ele");
  }
  for (std::size_t k = 0; k < values.size(); k += per_line)
    c.internal_lines.emplace_back(
        values.begin() + static_cast<std::ptrdiff_t>(k),
        values.begin() + static_cast<std::ptrdiff_t>(std::min(values.size(), k + per_line)));
  return c;
}

VlocRlocFile generated() {
  VlocRlocFile f;
  f.step = Integer{*rc::gen::inRange(0, 9999999)};
  f.time = real();
  const auto kinds = interaction_catalogue();
  for (int i = 0, n = *rc::gen::inRange(0, 6); i < n; ++i)
    f.interactions.push_back(generated_interaction(
        kinds[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(kinds.size())))]));
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

RC_GTEST_PROP(VlocRlocRoundTrip, InternalValuesAreKeptInOrder, ()) {
  const VlocRlocFile f = generated();
  DiagnosticSink sink;
  const VlocRlocFile back = parse_vloc_rloc(SourceText("Vloc_Rloc.LAST", write_vloc_rloc(f)), sink);
  RC_ASSERT(back.interactions.size() == f.interactions.size());
  for (std::size_t k = 0; k < f.interactions.size(); ++k)
    RC_ASSERT(vloc_rloc_internal_values(back.interactions[k]) ==
              vloc_rloc_internal_values(f.interactions[k]));
}

}  // namespace
}  // namespace lmgc::grammar
