// docs/architecture.md's recipes name files and symbols; they must exist, so that a recipe cannot
// point to what has moved or been renamed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

const std::filesystem::path kRoot = LMGC_SOURCE_DIR;

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string architecture_doc() {
  // Without the code fences (their backticks would pair with the quotes), lines joined, so that a
  // name and its file may sit on two lines of the page.
  const std::string text =
      std::regex_replace(read(kRoot / "docs" / "architecture.md"), std::regex("```"), "");
  return std::regex_replace(text, std::regex(R"(\s+)"), " ");
}

// A repository path as the page writes it: a folder or a file below the root, no placeholder.
bool is_repository_path(const std::string& token) {
  return token.find('/') != std::string::npos && token.find(' ') == std::string::npos &&
         token.find('<') == std::string::npos && token.find("..") != 0 &&
         token.find('*') == std::string::npos && token.find("::") == std::string::npos &&
         token.find('.') != std::string::npos;
}

TEST(ArchitectureDoc, EveryFileItNamesExists) {
  const std::string doc = architecture_doc();
  const std::regex quoted("`([^`]+)`");
  int checked = 0;
  for (std::sregex_iterator it(doc.begin(), doc.end(), quoted), end; it != end; ++it) {
    const std::string token = (*it)[1];
    if (!is_repository_path(token)) continue;
    ++checked;
    EXPECT_TRUE(std::filesystem::exists(kRoot / token)) << "docs/architecture.md names " << token;
  }
  EXPECT_GT(checked, 20);
}

TEST(ArchitectureDoc, EverySymbolItPlacesInAFileIsThere) {
  const std::string doc = architecture_doc();
  // "`name` in `file`" and "`name` (`file`)".
  const std::regex placed(R"(`([A-Za-z_][A-Za-z0-9_]*)` (?:in |\()`([^`]+)`)");
  int checked = 0;
  for (std::sregex_iterator it(doc.begin(), doc.end(), placed), end; it != end; ++it) {
    const std::string symbol = (*it)[1], file = (*it)[2];
    if (!is_repository_path(file) || !std::filesystem::is_regular_file(kRoot / file)) continue;
    ++checked;
    EXPECT_NE(read(kRoot / file).find(symbol), std::string::npos)
        << "docs/architecture.md places " << symbol << " in " << file;
  }
  EXPECT_GT(checked, 10);
}

}  // namespace
