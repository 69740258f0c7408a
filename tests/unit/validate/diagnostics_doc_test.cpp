// docs/diagnostics.md and the diagnostic catalogue list the same codes, with the same severity.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "grammar/common/diagnostic_catalogue.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(DiagnosticsDoc, ListsExactlyTheCatalogueWithItsSeverities) {
  const std::string doc = test::read_file(std::filesystem::path(LMGC_SOURCE_DIR) / "docs" / "diagnostics.md");
  ASSERT_FALSE(doc.empty());
  const std::regex entry(R"(## (L\d{4})\n\*\*(error|warning|note) — )");
  std::set<std::string> documented;
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), entry); it != std::sregex_iterator(); ++it) {
    const std::string code = (*it)[1];
    documented.insert(code);
    const DiagnosticKind* kind = find_diagnostic_kind(code);
    ASSERT_NE(kind, nullptr) << code << " is documented but not in the catalogue";
    EXPECT_EQ(std::string(severity_name(kind->severity)), std::string((*it)[2])) << code;
  }
  for (const auto& kind : diagnostic_catalogue()) {
    if (!kind.removed) {
      EXPECT_TRUE(documented.count(std::string(kind.code))) << kind.code << " is not documented";
    }
  }
}

TEST(DiagnosticCatalogue, IsSortedWithUniqueCodesAndCompleteTexts) {
  const auto catalogue = diagnostic_catalogue();
  for (std::size_t i = 0; i < catalogue.size(); ++i) {
    EXPECT_TRUE(std::regex_match(std::string(catalogue[i].code), std::regex(R"(L\d{4})")))
        << catalogue[i].code;
    EXPECT_FALSE(catalogue[i].summary.empty());
    EXPECT_FALSE(catalogue[i].explanation.empty());
    if (i > 0) {
      EXPECT_LT(catalogue[i - 1].code, catalogue[i].code);
    }
  }
}

}  // namespace
}  // namespace lmgc::grammar
