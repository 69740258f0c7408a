// Round trip of BULK_BEHAV: parse(write(ast)) == ast for generated files of every law type and
// every option case of the catalogue; write(parse(text)) == text for canonical text.
// docs/lmgc90-facts/datbox-inputs.md §2.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/bulk_behav/catalogue.hpp"
#include "grammar/bulk_behav/parser.hpp"
#include "grammar/bulk_behav/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

Real real() {
  return Real{*test::gen_d14_real()};
}

// Values for one line of `layout` (`count` values: 2 or 3 for DISCRETE, by dimension).
BulkValues values(const BulkValueLayout& layout, int count) {
  BulkValues line;
  if (layout.field_allowed && *rc::gen::inRange(0, 4) == 0) {
    line.field = true;
    return line;
  }
  for (int k = 0; k < count; ++k) line.values.push_back(real());
  return line;
}

void add_lines(BulkBlock& block, std::span<const BulkValueLayout> layouts, int dimension) {
  for (const BulkValueLayout& layout : layouts)
    block.lines.push_back(values(layout, layout.by_dimension ? dimension : layout.count));
}

// A supported option case, chosen at random (unsupported ones are errors in LMGC90).
const BulkOptionCase& pick(std::span<const BulkOptionCase> cases) {
  std::vector<const BulkOptionCase*> supported;
  for (const BulkOptionCase& c : cases)
    if (c.supported) supported.push_back(&c);
  return **rc::gen::elementOf(supported);
}

BulkBlock generated_block(BulkBlockKind kind, const std::string& anisotropy, int dimension) {
  BulkBlock block;
  block.kind = kind;
  for (const BulkStep& step : bulk_block_info(kind).steps) {
    bool stop = false;
    switch (step.kind) {
      case BulkStepKind::marker:
        break;
      case BulkStepKind::option: {
        std::vector<const BulkOptionCase*> cases;
        for (const BulkOptionCase& c : step.cases)
          if (c.supported && !(step.label == "ani_:" && kind == BulkBlockKind::elas && c.value != anisotropy))
            cases.push_back(&c);
        const BulkOptionCase& chosen = cases.empty() ? pick(step.cases) : **rc::gen::elementOf(cases);
        block.options.push_back(Word{std::string(chosen.value)});
        add_lines(block, chosen.lines, dimension);
        stop = chosen.ends_block;
        break;
      }
      case BulkStepKind::values:
        add_lines(block, step.lines, dimension);
        break;
      case BulkStepKind::anisotropy_values:
        for (const BulkOptionCase& c : step.cases)
          if (c.value == anisotropy) add_lines(block, c.lines, dimension);
        break;
      case BulkStepKind::file_name:
        block.file_name = Word{*test::gen_word(*rc::gen::inRange(1, 51))};
        break;
    }
    if (stop) break;
  }
  return block;
}

BulkBehavFile generated() {
  BulkBehavFile f;
  f.has_gravity = true;
  f.gravity = {real(), real(), real()};
  const auto kinds = bulk_law_catalogue();
  for (int i = 0, n = *rc::gen::inRange(0, 6); i < n; ++i) {
    const BulkLawKind& kind = kinds[*rc::gen::inRange<std::size_t>(0, kinds.size())];
    BulkLaw law;
    law.nickname = Word{*test::gen_word()};
    law.law_type = Word{std::string(kind.law_type)};
    const int dimension = *rc::gen::inRange(2, 4);
    if (kind.first_line == BulkFirstLine::umas) {
      law.density_field = *rc::gen::inRange(0, 5) == 0;
      if (!law.density_field) law.density = real();
    } else {
      const int count = kind.first_values.by_dimension ? dimension : kind.first_values.count;
      for (int k = 0; k < count; ++k) law.first_line_values.push_back(real());
    }
    // CPLT (ELAS_DILA, THERMO_ELAS*) is not defined for anisotropic elasticity.
    bool has_cplt = false;
    for (BulkBlockKind b : kind.blocks) has_cplt |= b == BulkBlockKind::cplt;
    const std::string anisotropy =
        has_cplt ? *rc::gen::elementOf(std::vector<std::string>{"isotropic", "orthotropic"})
                 : *rc::gen::elementOf(std::vector<std::string>{"isotropic", "orthotropic", "anisotropic"});
    for (BulkBlockKind b : kind.blocks) law.blocks.push_back(generated_block(b, anisotropy, dimension));
    f.laws.push_back(std::move(law));
  }
  return f;
}

RC_GTEST_PROP(BulkBehavRoundTrip, ParseOfWriteIsIdentity, ()) {
  const BulkBehavFile f = generated();
  DiagnosticSink sink;
  const BulkBehavFile again = parse_bulk_behav(SourceText("BULK_BEHAV.DAT", write_bulk_behav(f)), sink);
  RC_ASSERT(sink.items().empty());
  RC_ASSERT(again == f);
}

RC_GTEST_PROP(BulkBehavRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const std::string text = write_bulk_behav(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_bulk_behav(parse_bulk_behav(SourceText("BULK_BEHAV.DAT", text), sink)) == text);
}

// Every law type of the catalogue is generated and survives the round trip on its own.
TEST(BulkBehavRoundTrip, EveryLawTypeOfTheCatalogueRoundTrips) {
  for (const BulkLawKind& kind : bulk_law_catalogue()) {
    SCOPED_TRACE(std::string(kind.law_type));
    const bool ok = rc::check(std::string(kind.law_type), [&kind] {
      BulkBehavFile f;
      f.has_gravity = true;
      BulkLaw law;
      law.nickname = Word{"LAW01"};
      law.law_type = Word{std::string(kind.law_type)};
      if (kind.first_line == BulkFirstLine::umas)
        law.density = real();
      else
        for (int k = 0; k < kind.first_values.count; ++k) law.first_line_values.push_back(real());
      for (BulkBlockKind b : kind.blocks) law.blocks.push_back(generated_block(b, "isotropic", 3));
      f.laws.push_back(law);
      DiagnosticSink sink;
      RC_ASSERT(parse_bulk_behav(SourceText("BULK_BEHAV.DAT", write_bulk_behav(f)), sink) == f);
      RC_ASSERT(sink.items().empty());
    });
    EXPECT_TRUE(ok);
  }
}

// The parser never throws nor crashes: canonical text with random bytes overwritten, lines cut
// short or dropped still parses (diagnostics are allowed).
RC_GTEST_PROP(BulkBehavRobustness, ParserNeverCrashesOnDamagedText, ()) {
  const std::string text = test::damaged_text(write_bulk_behav(generated()));
  DiagnosticSink sink;
  parse_bulk_behav(SourceText("DAMAGED", text), sink);
  RC_SUCCEED();
}

}  // namespace
}  // namespace lmgc::grammar
