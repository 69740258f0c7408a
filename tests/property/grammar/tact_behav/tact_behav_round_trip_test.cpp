// parse(write(ast)) == ast for generated TACT_BEHAV ASTs: random laws of the catalogue with
// random parameters, random see rows. The echo holds the see table in LMGC90's order (merged,
// sorted), so the see rows come back as lmgc90_see_order(ast.sees); the quirk laws come back
// with the values their reader takes from the echo (values_read_back_from_echo).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <string>
#include <vector>

#include "grammar/tact_behav/law_catalogue.hpp"
#include "grammar/tact_behav/parser.hpp"
#include "grammar/tact_behav/see_table.hpp"
#include "grammar/tact_behav/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

// A 5-character word that is not a card keyword (columns 2-6 of a law or see line).
std::string gen_name() {
  return *rc::gen::suchThat(test::gen_word(5),
                            [](const std::string& w) { return w != "behav" && w != "seety"; });
}

std::vector<const LawKind*> readable_kinds() {
  std::vector<const LawKind*> kinds;
  for (const LawKind& kind : law_catalogue())
    if (kind.readable) kinds.push_back(&kind);
  return kinds;
}

TactLaw gen_law() {
  static const std::vector<const LawKind*> kinds = readable_kinds();
  const LawKind& kind = **rc::gen::elementOf(kinds);
  std::vector<double> values;
  for (std::size_t i = 0; i < kind.parameters.size(); ++i) values.push_back(*test::gen_d14_real());
  TactLaw law;
  law.nickname = gen_name();
  law.keyword = std::string(kind.keyword);
  for (double v : values_read_back_from_echo(kind, values)) law.parameters.push_back(Real{v});
  return law;
}

SeeEntry gen_see() {
  const auto body = [] {
    return *rc::gen::oneOf(rc::gen::element<std::string>("RBDY2", "RBDY3", "MAILx"),
                           rc::gen::just(gen_name()));
  };
  // Known contactor names drive LMGC90's sort; a few unknown ones (id -99) too.
  const auto contactor = [] {
    return *rc::gen::oneOf(rc::gen::element<std::string>("DISKx", "POLYG", "JONCx", "SPHER", "PLANx", "POLYR",
                                                         "CLxxx", "ALpxx", "CSxxx", "ASpxx"),
                           rc::gen::just(gen_name()));
  };
  // Few colours, so that ties and duplicates (LMGC90 merges them) are frequent.
  const auto colour = [] { return *rc::gen::element<std::string>("BLEUx", "REDxx", "VERTx", "WALLx"); };
  SeeEntry see;
  see.candidate_body = body();
  see.candidate_contactor = contactor();
  see.candidate_colour = colour();
  see.law_nickname = gen_name();
  see.antagonist_body = body();
  see.antagonist_contactor = contactor();
  see.antagonist_colour = colour();
  see.alert = *test::gen_d14_real();
  // LMGC90 prints the global alert only when it is non-zero and below 1e20.
  if (*rc::gen::arbitrary<bool>())
    see.global_alert =
        Real{*rc::gen::suchThat(test::gen_d14_real(), [](double v) { return v != 0.0 && v < 1.0e20; })};
  return see;
}

RC_GTEST_PROP(TactBehavRoundTrip, ParseOfWriteIsIdentityUpToLmgc90SeeOrder, ()) {
  TactBehavFile file;
  const int law_count = *rc::gen::inRange(0, 6);
  for (int i = 0; i < law_count; ++i) file.laws.push_back(gen_law());
  const int see_count = *rc::gen::inRange(0, 8);
  for (int i = 0; i < see_count; ++i) file.sees.push_back(gen_see());

  const std::string text = write_tact_behav(file);
  DiagnosticSink sink;
  const TactBehavFile back = parse_tact_behav(SourceText("echo", text), sink);
  RC_ASSERT(!sink.has_errors());
  RC_ASSERT(back.laws == file.laws);
  RC_ASSERT(back.sees == lmgc90_see_order(file.sees));
}

// LMGC90's see order keeps one entry per pair (candidate/antagonist possibly swapped) and
// never grows the table.
RC_GTEST_PROP(TactBehavSeeOrder, MergesEveryDuplicatePair, ()) {
  std::vector<SeeEntry> sees;
  const int see_count = *rc::gen::inRange(0, 8);
  for (int i = 0; i < see_count; ++i) sees.push_back(gen_see());
  const std::vector<SeeEntry> order = lmgc90_see_order(sees);
  RC_ASSERT(order.size() <= sees.size());
  // No two entries of the result name the same pair.
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size(); ++j) RC_ASSERT(!same_see_pair(order[i], order[j]));
}

}  // namespace
}  // namespace lmgc::grammar
