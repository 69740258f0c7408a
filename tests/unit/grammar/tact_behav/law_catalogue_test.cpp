// The law catalogue: 94 LMGC90 ids, names and layouts as in contact-laws.md §0, and every
// readable row round-trips: a card written from the row parses back to the same law.
#include "grammar/tact_behav/law_catalogue.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "grammar/tact_behav/parser.hpp"
#include "grammar/tact_behav/writer.hpp"

namespace lmgc::grammar {
namespace {

TEST(TactLawCatalogue, HasTheNinetyFourIdsInOrder) {
  const auto rows = law_catalogue();
  ASSERT_EQ(rows.size(), 94u);
  std::set<std::string_view> keywords;
  int unreadable = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].id, static_cast<int>(i) + 1);
    EXPECT_TRUE(keywords.insert(rows[i].keyword).second) << rows[i].keyword;
    EXPECT_LE(rows[i].keyword.size(), 30u);
    if (!rows[i].readable) ++unreadable;
    for (std::string_view name : rows[i].parameters) EXPECT_EQ(name.size(), 5u) << rows[i].keyword;
    EXPECT_EQ(find_law_kind(rows[i].keyword), &rows[i]);
  }
  EXPECT_EQ(unreadable, 3);  // WET_CZM, postGAP_IQS_CZM, WET_3C
  EXPECT_EQ(find_law_kind("IQS_CLB_3D"), nullptr);
}

TEST(TactLawCatalogue, EveryParameterIsReadAndWritten) {
  for (const LawKind& kind : law_catalogue()) {
    if (!kind.readable) continue;
    SCOPED_TRACE(std::string(kind.keyword));
    std::vector<int> read(kind.parameters.size(), 0), written(kind.parameters.size(), 0);
    for (const LawField& field : kind.reads)
      for (int slot = 0; slot < field.count; ++slot) ++read.at(field.first + static_cast<std::size_t>(slot));
    for (const LawField& field : kind.writes)
      for (int slot = 0; slot < field.count; ++slot)
        ++written.at(field.first + static_cast<std::size_t>(slot));
    for (std::size_t i = 0; i < kind.parameters.size(); ++i) {
      EXPECT_EQ(read[i], 1) << i;
      EXPECT_EQ(written[i], 1) << i;
    }
  }
}

// Spot checks against the table of contact-laws.md §0 (layout column, names).
TEST(TactLawCatalogue, MatchesTheSpecTable) {
  const LawKind* wet = find_law_kind("IQS_WET_DS_CLB");
  ASSERT_NE(wet, nullptr);
  EXPECT_EQ(wet->read_line_count(), 3);
  EXPECT_EQ(wet->values_on_read_line(0), 2);
  EXPECT_EQ(wet->values_on_read_line(1), 1);
  EXPECT_EQ(wet->values_on_read_line(2), 2);
  EXPECT_EQ(wet->parameters[2], "Wethk");
  const LawKind* gtn = find_law_kind("GTN_CZM");
  ASSERT_NE(gtn, nullptr);
  EXPECT_EQ(gtn->parameters.size(), 17u);
  EXPECT_EQ(gtn->read_line_count(), 9);  // 2 / 2 x 7 lines / 1
  EXPECT_EQ(gtn->values_on_read_line(8), 1);
  const LawKind* perio = find_law_kind("PERIO_DOF");
  ASSERT_NE(perio, nullptr);
  EXPECT_EQ(perio->read_line_count(), 1);
  EXPECT_EQ(perio->values_on_read_line(0), 3);
  EXPECT_FALSE(perio->quirk.empty());
  const LawKind* mac = find_law_kind("MAC_CZM");
  ASSERT_NE(mac, nullptr);
  EXPECT_EQ(mac->internals_2d.count, 5);
  EXPECT_EQ(mac->internals_3d.count, 6);
  ASSERT_EQ(mac->internals_3d.slots.size(), 6u);
  EXPECT_EQ(mac->internals_3d.slots[3].column, 47);
  EXPECT_EQ(mac->internals_3d.slots[3].text, "saut_de_us    ");
  const LawKind* glue = find_law_kind("COUPLED_DOF");
  ASSERT_NE(glue, nullptr);
  EXPECT_TRUE(glue->parameters.empty());
  EXPECT_EQ(find_law_kind("IQS_BW_CLB")->parameters.size(), 7u);
  EXPECT_EQ(find_law_kind("IQS_SGR_CLB_WEAR")->parameters.size(), 4u);
  EXPECT_EQ(find_law_kind("MSMP_CZM")->internals_3d.count, -1);
}

TEST(TactLawCatalogue, HintsForGuideNamesAndTypos) {
  EXPECT_NE(law_keyword_hint("MAC_CZM_3D_nosldt").find("'MAC_CZM_nosldt'"), std::string::npos);
  EXPECT_NE(law_keyword_hint("IQS_MAC_CZM_3D_noslds").find("'IQS_MAC_CZM_noslds'"), std::string::npos);
  EXPECT_NE(law_keyword_hint("DEM_Cohe_Hertz").find("no longer"), std::string::npos);
  EXPECT_NE(law_keyword_hint("ELASTIC_REPEL_CLB").find("'ELASTIC_REPELL_CLB'"), std::string::npos);
  EXPECT_EQ(law_keyword_hint("GAP_SGR_CLBB"), "did you mean 'GAP_SGR_CLB'?");
  // IQS_MAC_CZX is within 2 of IQS_MAC_CZM and IQS_MAL_CZM: no single guess.
  EXPECT_EQ(law_keyword_hint("IQS_MAC_CZX"), "");
  EXPECT_EQ(law_keyword_hint("TOTALLY_UNKNOWN_LAW"), "");
  // Two keywords within distance 2 (MP_CZM, MP3_CZM): no single guess.
  EXPECT_EQ(law_keyword_hint("MPx_CZM"), "");
}

// The catalogue walk: for every readable row, a card written from the row parses back to the
// same keyword and parameters (quirk laws: the values their reader gets back from the echo).
TEST(TactLawCatalogue, EveryRowRoundTripsThroughWriterAndParser) {
  for (const LawKind& kind : law_catalogue()) {
    if (!kind.readable) continue;
    SCOPED_TRACE(std::string(kind.keyword));
    std::vector<double> values;
    for (std::size_t i = 0; i < kind.parameters.size(); ++i)
      values.push_back(0.125 * static_cast<double>(i + 1));
    values = values_read_back_from_echo(kind, values);
    TactBehavFile file;
    TactLaw law;
    law.nickname = std::string("law01");
    law.keyword = std::string(kind.keyword);
    for (double v : values) law.parameters.push_back(Real{v});
    file.laws.push_back(law);
    DiagnosticSink sink;
    const TactBehavFile back = parse_tact_behav(SourceText("echo", write_tact_behav(file)), sink);
    EXPECT_FALSE(sink.has_errors());
    ASSERT_EQ(back.laws.size(), 1u);
    EXPECT_EQ(back.laws[0].keyword.value, kind.keyword);
    ASSERT_EQ(back.laws[0].parameters.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
      EXPECT_EQ(back.laws[0].parameters[i].value, values[i]) << i;
    // A row whose reader takes every printed field exactly once gets all its distinct values back.
    if (kind.quirk.empty() || kind.keyword == "IQS_MAP" || kind.keyword == "IQS_BW_CLB" ||
        kind.keyword == "IQS_SGR_CLB_WEAR") {
      for (std::size_t i = 0; i < values.size(); ++i)
        EXPECT_EQ(values[i], 0.125 * static_cast<double>(i + 1));
    }
  }
}

}  // namespace
}  // namespace lmgc::grammar
