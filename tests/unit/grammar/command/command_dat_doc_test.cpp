// docs/command-dat.md lists every COMMAND.DAT keyword of the catalogue with what lmgc-solve does
// with it, in catalogue order. When they differ, the expected table is written to
// build/.../test_scratch/command-dat.table.md: review it and paste it into the document.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "grammar/command/catalogue.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"

namespace lmgc::grammar {
namespace {

std::string expected_table() {
  std::string table = "| keyword | module | lmgc-solve |\n| --- | --- | --- |\n";
  for (const CommandKeyword& k : command_catalogue())
    table += "| `" + std::string(k.keyword) + "` | " + std::string(k.module) + " | " +
             std::string(support_name(k.support)) + " |\n";
  return table;
}

TEST(CommandDatDoc, ListsEveryKeywordWithWhatLmgcSolveDoesWithIt) {
  const std::string doc = test::read_file(std::filesystem::path(LMGC_SOURCE_DIR) / "docs" / "command-dat.md");
  const std::string table = expected_table();
  const bool listed = doc.find(table) != std::string::npos;
  if (!listed) std::ofstream(test::scratch_dir("command_dat_doc") / "command-dat.table.md") << table;
  EXPECT_TRUE(listed) << "docs/command-dat.md does not hold the catalogue's table (expected table written to "
                         "test_scratch/command_dat_doc/command-dat.table.md)";
}

}  // namespace
}  // namespace lmgc::grammar
