// Every Vloc_Rloc file LMGC90 wrote for the examples (.LAST and .OUT.n, .gz included) is
// reproduced byte for byte by write(parse(file)); every DATBOX/Vloc_Rloc.INI parses.
#include <gtest/gtest.h>

#include "grammar/vloc_rloc/parser.hpp"
#include "grammar/vloc_rloc/writer.hpp"
#include "tests/support/gzip.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

TEST(VlocRlocConformance, LmgcOutputsAreReproducedByteForByte) {
  LMGC_REQUIRE_SHARED();
  int compared = 0;
  for (const auto& dir : test::example_cases()) {
    const auto outbox = dir / "reference_lmgc90" / "OUTBOX";
    if (!std::filesystem::is_directory(outbox)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(outbox)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("Vloc_Rloc.", 0) != 0) continue;
      SCOPED_TRACE(entry.path().string());
      const std::string text = test::read_maybe_gzip(entry.path());
      DiagnosticSink sink;
      const VlocRlocFile f = parse_vloc_rloc(SourceText(name, text), sink);
      EXPECT_FALSE(sink.has_errors());
      EXPECT_TRUE(write_vloc_rloc(f) == text);
      ++compared;
    }
  }
  EXPECT_GE(compared, 400);
}

TEST(VlocRlocConformance, EveryInitialFileParses) {
  LMGC_REQUIRE_SHARED();
  for (const auto& path : test::example_files("Vloc_Rloc.INI")) {
    SCOPED_TRACE(path.string());
    DiagnosticSink sink;
    parse_vloc_rloc(SourceText(path.string(), test::read_file(path)), sink);
    EXPECT_FALSE(sink.has_errors());
  }
}

}  // namespace
}  // namespace lmgc::grammar
