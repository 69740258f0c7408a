// Round trip of COMMAND.DAT: parse(write(ast)) == ast for generated programs (keywords of the
// catalogue with their argument lines, comments, messages, blank lines, loops, a subroutine
// call, comments after column 30, CRLF lines, text after FIN DU FICHIER), and
// write(parse(text)) == text for their text.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/command/catalogue.hpp"
#include "grammar/command/parser.hpp"
#include "grammar/command/writer.hpp"
#include "grammar/common/fortran_format.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

// A line whose significant text is `text`: random leading blanks, and a trailer that is either
// nothing or blanks up to column 30 then ':' and an optional comment.
CommandLine line_of(CommandLineKind kind, std::string text) {
  CommandLine line;
  line.kind = kind;
  const std::size_t room = text.size() <= 30 ? 30 - text.size() : 0;
  line.indent =
      static_cast<std::uint32_t>(*rc::gen::inRange<std::size_t>(0, std::min<std::size_t>(room, 4) + 1));
  if (*rc::gen::arbitrary<bool>()) {
    line.trailer.assign(30 - line.indent - text.size(), ' ');
    line.trailer += ':';
    if (*rc::gen::arbitrary<bool>()) line.trailer += " " + *test::gen_word(6) + " " + *test::gen_word(3);
  }
  line.crlf = *rc::gen::inRange(0, 8) == 0;
  line.text = Word{std::move(text)};
  return line;
}

CommandLine control(std::string text, std::string keyword, std::string parameter) {
  CommandLine line = line_of(CommandLineKind::control, std::move(text));
  line.keyword = std::move(keyword);
  line.parameter = std::move(parameter);
  return line;
}

std::string d_text(double value) {
  return std::string(trim(fortran_d(value)));
}

CommandLine argument(CommandArgumentKind kind) {
  CommandValue value;
  value.kind = kind;
  std::string text;
  switch (kind) {
    case CommandArgumentKind::real: {
      const double v = *test::gen_d14_real();
      text = d_text(v);
      value.reals.push_back(Real{v});
      break;
    }
    case CommandArgumentKind::integer: {
      const std::int64_t v = *rc::gen::inRange<std::int64_t>(-99999, 1000000);
      text = std::to_string(v);
      value.integer = Integer{v};
      break;
    }
    case CommandArgumentKind::word:
      text = *rc::gen::elementOf(
          std::vector<std::string>{"3D", "2D PSTRAIN", "Stored_Delassus_Loops", "Exchange_Local_Global"});
      value.word = Word{text};
      break;
    case CommandArgumentKind::type_tol: {
      const std::string type = *rc::gen::elementOf(std::vector<std::string>{"Quad", "Maxm", "QM/16", "QuaN"});
      const double v = *test::gen_d14_real();
      text = type + std::string(5 - type.size() + 1, ' ') + d_text(v);
      value.word = Word{type};
      value.reals.push_back(Real{v});
      break;
    }
    case CommandArgumentKind::reals: {
      for (int k = 0; k < 2; ++k) {
        const double v = *test::gen_d14_real();
        text += (k ? " " : "") + d_text(v);
        value.reals.push_back(Real{v});
      }
      break;
    }
  }
  CommandLine line = line_of(CommandLineKind::argument, text);
  line.value = value;
  return line;
}

void add_keyword(std::vector<CommandLine>& lines) {
  std::vector<const CommandKeyword*> keywords;
  for (const auto& k : command_catalogue())
    if (!k.control && k.inline_part != CommandInline::text) keywords.push_back(&k);
  const CommandKeyword* k = *rc::gen::elementOf(keywords);
  std::string text(k->keyword);
  std::string parameter;
  if (k->inline_part == CommandInline::step_or_dtps &&
      (*rc::gen::arbitrary<bool>() || text.rfind("WRITE OUT ", 0) == 0 ||
       text.rfind("BINARY WRITE OUT ", 0) == 0)) {
    parameter = "STEP " + std::to_string(*rc::gen::inRange(1, 1000));
    if (text.size() + 1 + parameter.size() > 30) return;
    text += " " + parameter;
  }
  CommandLine line = line_of(CommandLineKind::keyword, text);
  line.keyword = std::string(k->keyword);
  line.parameter = parameter;
  lines.push_back(line);
  for (CommandArgumentKind a : k->arguments) lines.push_back(argument(a));
}

void add_body(std::vector<CommandLine>& lines, int count) {
  for (int i = 0; i < count; ++i) {
    switch (*rc::gen::inRange(0, 8)) {
      case 0:
        lines.push_back(line_of(CommandLineKind::comment, "#" + *test::gen_word(4)));
        break;
      case 1:
        lines.push_back(line_of(CommandLineKind::message, "." + *test::gen_word(8)));
        break;
      case 2: {
        CommandLine blank;  // all blank: leading blanks only, or 30 blanks and a comment
        blank.indent = static_cast<std::uint32_t>(*rc::gen::element(0, 3, 30));
        if (blank.indent == 30 && *rc::gen::arbitrary<bool>()) blank.trailer = ": " + *test::gen_word(4);
        lines.push_back(blank);
        break;
      }
      default:
        add_keyword(lines);
    }
  }
}

CommandFile generated() {
  CommandFile f;
  auto& lines = f.lines;
  lines.push_back(control("NO CHECK CHIC COMMAND", "NO CHECK CHIC COMMAND", ""));
  const std::string label = ">" + *test::gen_word(6);
  lines.push_back(line_of(CommandLineKind::label, label));
  add_body(lines, *rc::gen::inRange(0, 6));
  const std::string sub = *test::gen_word(5) + " " + *test::gen_word(4);
  lines.push_back(control("APPELLE " + sub, "APPEL", sub));
  add_body(lines, *rc::gen::inRange(0, 4));
  const std::string count = std::to_string(*rc::gen::inRange(0, 100));
  lines.push_back(control("REPETE " + count + " FOIS", "REPETE", count + " FOIS"));
  lines.push_back(control("DEPUIS " + label, "DEPUIS", label));
  lines.push_back(control("FIN DU PROGRAMME", "FIN DU PROGRAMME", ""));
  lines.push_back(control("SUB " + sub, "SUB ", sub));
  add_body(lines, *rc::gen::inRange(0, 6));
  lines.push_back(control("RETOUR", "RETOUR", ""));
  lines.push_back(control("FIN DU FICHIER", "FIN DU FICHIER", ""));
  for (int i = 0, n = *rc::gen::inRange(0, 3); i < n; ++i) {
    CommandLine after = line_of(CommandLineKind::after_end, *test::gen_word(7));
    lines.push_back(after);
  }
  f.final_newline = *rc::gen::arbitrary<bool>();
  return f;
}

RC_GTEST_PROP(CommandRoundTrip, ParseOfWriteIsIdentity, ()) {
  const CommandFile f = generated();
  DiagnosticSink sink;
  const CommandFile back = parse_command(SourceText("COMMAND.DAT", write_command(f)), sink);
  if (!sink.items().empty()) RC_FAIL(write_command(f) + "\n" + sink.items()[0].message);
  RC_ASSERT(back == f);
}

RC_GTEST_PROP(CommandRoundTrip, WriteOfParseIsIdentity, ()) {
  const std::string text = write_command(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_command(parse_command(SourceText("COMMAND.DAT", text), sink)) == text);
}

// Any text at all comes back unchanged (the echo keeps what CHIC ignores).
RC_GTEST_PROP(CommandRoundTrip, WriteOfParseOfAnyTextIsIdentity, ()) {
  const std::string text =
      *rc::gen::container<std::string>(rc::gen::elementOf(std::string("AB #.:\r\n 0123FINDUPROGAMESTC")));
  DiagnosticSink sink;
  RC_ASSERT(write_command(parse_command(SourceText("COMMAND.DAT", text), sink)) == text);
}

}  // namespace
}  // namespace lmgc::grammar
