// Round trip of COMMAND.DAT: parse(write(ast)) == ast and write(parse(text)) == text.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/command/keyword_catalogue.hpp"
#include "grammar/command/parser.hpp"

namespace lmgc::grammar {
namespace {

std::string generated_text() {
  std::string text;
  const auto keywords = command_keyword_catalogue();
  for (int i = 0, n = *rc::gen::inRange(0, 30); i < n; ++i) {
    switch (*rc::gen::inRange(0, 4)) {
      case 0: {
        const CommandKeyword& k = keywords[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(keywords.size())))];
        if (k.keyword == "REPETE" || k.keyword.find("FIN") == 0 || k.keyword == "SUB" || k.keyword == "APPELLE") break;
        std::string line(k.keyword);
        line.resize(std::max<std::size_t>(line.size(), 30), ' ');
        text += line + ": comment\n";
        for (std::size_t a = 0; a < k.arguments.size(); ++a) text += "1.0D0                         :\n";
        break;
      }
      case 1: text += "#" + std::string(static_cast<std::size_t>(*rc::gen::inRange(0, 40)), '-') + "\n"; break;
      case 2: text += "\n"; break;
      default: text += ".message " + std::to_string(i) + "\n";
    }
  }
  return text + "FIN DU PROGRAMME\n";
}

RC_GTEST_PROP(CommandRoundTrip, WriteOfParseIsIdentity, ()) {
  const std::string text = generated_text();
  DiagnosticSink sink;
  RC_ASSERT(write_command(parse_command(SourceText("COMMAND.DAT", text), sink)) == text);
}

RC_GTEST_PROP(CommandRoundTrip, ParseOfWriteIsIdentity, ()) {
  DiagnosticSink sink;
  const CommandFile f = parse_command(SourceText("COMMAND.DAT", generated_text()), sink);
  DiagnosticSink again;
  RC_ASSERT(parse_command(SourceText("COMMAND.DAT", write_command(f)), again) == f);
}

}  // namespace
}  // namespace lmgc::grammar
