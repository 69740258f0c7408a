// SourceText keeps its lines pointing at its own text through copies and moves, also for a text
// short enough to live inside the string object (a 15-byte PTPT3_NETWORK.DAT record read through
// the case loader's map once showed a freed buffer).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

#include "grammar/common/source.hpp"

namespace lmgc::grammar {
namespace {

void expect_lines(const SourceText& source, const std::string& first, const std::string& second) {
  ASSERT_EQ(source.lines().size(), 2u);
  EXPECT_EQ(source.lines()[0].text, first);
  EXPECT_EQ(source.lines()[1].text, second);
  // The views lie inside this object's text.
  const char* begin = source.text().data();
  for (const Line& line : source.lines()) {
    EXPECT_GE(line.text.data(), begin);
    EXPECT_LE(line.text.data() + line.text.size(), begin + source.text().size());
  }
}

TEST(SourceText, AShortTextKeepsItsLinesWhenMovedOrCopied) {
  SourceText original("a", " 1 2\r\n3 4\n");  // short: stored inside the string object
  expect_lines(original, " 1 2", "3 4");
  SourceText copy(original);
  expect_lines(copy, " 1 2", "3 4");
  std::map<std::string, SourceText> sources;
  auto [it, inserted] = sources.emplace("a", std::move(copy));
  expect_lines(it->second, " 1 2", "3 4");
  SourceText assigned;
  assigned = it->second;
  expect_lines(assigned, " 1 2", "3 4");
  SourceText moved_into;
  moved_into = std::move(assigned);
  expect_lines(moved_into, " 1 2", "3 4");
  EXPECT_EQ(moved_into.line_text(2), "3 4");
}

TEST(SourceText, SelfAssignmentAndAnEmptyTextAreHarmless) {
  SourceText source("c", "a\nb\n");
  SourceText& same = source;
  source = same;
  expect_lines(source, "a", "b");
  source = std::move(same);
  expect_lines(source, "a", "b");
  SourceText empty("d", "");
  SourceText moved(std::move(empty));
  EXPECT_TRUE(moved.lines().empty());
  EXPECT_EQ(moved.line_text(1), "");
}

// A long text's buffer moves with it: the lines stay where they were.
TEST(SourceText, ALongTextKeepsItsLinesWhenMoved) {
  const std::string first(100, 'x'), second(50, 'y');
  SourceText original("b", first + "\n" + second);
  SourceText moved(std::move(original));
  expect_lines(moved, first, second);
  EXPECT_FALSE(moved.has_final_newline());
}

}  // namespace
}  // namespace lmgc::grammar
