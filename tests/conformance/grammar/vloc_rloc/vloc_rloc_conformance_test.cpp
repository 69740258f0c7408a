// Every Vloc_Rloc file LMGC90 wrote for the examples (.LAST and .OUT.n, the .gz ones through
// `gzip -dc`) is reproduced byte for byte by write(parse(file)); every DATBOX/Vloc_Rloc.INI
// parses without error and survives parse(write(parse(file))) == parse(file).
#include <gtest/gtest.h>

#include <set>

#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "tests/support/gzip.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(VlocRlocConformance, LmgcOutputsAreReproducedByteForByte) {
  LMGC_REQUIRE_SHARED();
  int compared = 0;
  std::set<std::string> modules;
  for (const auto& dir : test::example_cases()) {
    const auto outbox = dir / "reference_lmgc90" / "OUTBOX";
    if (!std::filesystem::is_directory(outbox)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(outbox)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("Vloc_Rloc.", 0) != 0) continue;
      SCOPED_TRACE(entry.path().string());
      const std::string text = test::read_maybe_gzip(entry.path());
      ASSERT_FALSE(text.empty());
      DiagnosticSink sink;
      const VlocRlocFile f = parse_vloc_rloc(SourceText(name, text), sink);
      // No diagnostic at all, not even a warning, on what LMGC90 wrote.
      EXPECT_EQ(sink.items().size(), 0u) << (sink.items().empty() ? "" : sink.items()[0].message);
      EXPECT_TRUE(write_vloc_rloc(f) == text);
      for (const auto& c : f.interactions) modules.insert(c.type.value);
      ++compared;
    }
  }
  EXPECT_GE(compared, 400);
  // The modules the examples exercise (the others are checked against the source in unit tests).
  EXPECT_EQ(modules, (std::set<std::string>{"CLALp", "CLJCx", "CSASx", "DKDKx", "DKJCx", "DKPLx", "PLALp",
                                            "PLJCx", "PLPLx", "PRPLx", "PRPRx", "SPPLx", "SPSPx"}));
}

TEST(VlocRlocConformance, EveryInitialFileParses) {
  LMGC_REQUIRE_SHARED();
  std::size_t interactions = 0;
  for (const auto& path : test::example_files("Vloc_Rloc.INI")) {
    SCOPED_TRACE(path.string());
    DiagnosticSink sink;
    const VlocRlocFile f = parse_vloc_rloc(SourceText(path.string(), test::read_file(path)), sink);
    EXPECT_FALSE(sink.has_errors()) << (sink.items().empty() ? "" : sink.items()[0].message);
    interactions += f.interactions.size();
    DiagnosticSink again;
    EXPECT_TRUE(parse_vloc_rloc(SourceText("echo", write_vloc_rloc(f)), again) == f);
  }
  EXPECT_GT(interactions, 1000u);  // RIGID_2D/500PL_PerioBoxJC holds 1662 PLPLx blocks
}

}  // namespace
}  // namespace lmgc::grammar
