// COMMAND.DAT reader. docs/lmgc90-facts/state-and-outputs.md §2.1 (lexical rules, control structures,
// keyword reference).
#include "grammar/command/parser.hpp"

#include <set>
#include <string>

#include "grammar/command/catalogue.hpp"
#include "grammar/command/chic_text.hpp"
#include "grammar/command/expand.hpp"
#include "grammar/common/card_reader.hpp"

namespace lmgc::grammar {
namespace {

using chic::from;
using chic::starts_with;

constexpr std::size_t kSignificantColumns = 30;  // READ(1,'(A30)')
constexpr std::size_t kMaxLines = 1000;          // NTXZZZ

bool is_program_end(std::string_view t) {
  return t == "FIN DU PROGRAMME" || t == "FIN_DU_PROGRAMME";
}
bool is_file_end(std::string_view t) {
  return t == "FIN DU FICHIER" || t == "FIN_DU_FICHIER";
}

// Characters where a control word's label or name starts (CHIC's CHZZZ(k:30) cuts).
std::optional<std::size_t> label_offset(std::string_view keyword) {
  if (keyword == "APPEL") return 8;  // 'APPELLE name': name = CHZZZ(9:30)
  if (keyword == "SUB ") return 4;
  if (keyword == "DEPUIS") return 7;  // CKZZZ = CHLZZZ(N+1)(8:30)
  if (keyword == "SUR ") return 4;    // CHLZZZ(N+1)(5:30)
  if (keyword == "INTO ") return 5;   // CHLZZZ(N+1)(6:30)
  return std::nullopt;
}

class CommandParser {
 public:
  CommandParser(const SourceText& source, DiagnosticSink& sink) : source_(source), sink_(sink) {}

  CommandFile parse() {
    CommandFile file;
    const std::size_t errors_before = sink_.error_count();
    file.final_newline = source_.has_final_newline();
    split(file);
    if (source_.lines().empty()) {
      sink_.report("L1009", Location{source_.path(), SourceSpan{}}, "file is empty");
      return file;
    }
    CardReader(source_, sink_).check_records();

    // Sections: main program up to FIN DU PROGRAMME, subroutines up to FIN DU FICHIER.
    const std::size_t count = file.lines.size();
    std::size_t main_end = count, file_end = count;
    for (std::size_t i = 0; i < count && main_end == count; ++i)
      if (is_program_end(file.lines[i].text.value)) main_end = i;
    for (std::size_t i = main_end + 1; i < count && file_end == count; ++i)
      if (is_file_end(file.lines[i].text.value)) file_end = i;
    if (main_end == count) {
      at_end("L1012", "no 'FIN DU PROGRAMME' line: LMGC90 reads past the end of the file and stops");
    } else if (file_end == count) {
      at_end("L1012",
             "no 'FIN DU FICHIER' line after 'FIN DU PROGRAMME': LMGC90 reads past the end of the file and "
             "stops");
    }
    if (main_end != count && main_end + 1 > kMaxLines)
      report("L1003", file.lines[kMaxLines], "more than 1000 lines before 'FIN DU PROGRAMME' (CHIC's limit)");
    if (file_end != count && file_end - main_end > kMaxLines)
      report("L1003", file.lines[main_end + kMaxLines], "more than 1000 lines of subroutines (CHIC's limit)");

    for (std::size_t i = file_end + 1; i < count; ++i) file.lines[i].kind = CommandLineKind::after_end;
    const std::size_t last = file_end == count ? count : file_end + 1;  // classified lines: [0, last)
    classify(file, 0, std::min(main_end + 1, last));
    if (main_end + 1 < last) classify(file, main_end + 1, last);
    resolve_labels(file, last);
    check_chic_command(file, std::min(main_end + 1, count));
    if (main_end != count && file_end != count && sink_.error_count() == errors_before)
      compile_command_program(file, sink_, source_.path());
    return file;
  }

 private:
  void split(CommandFile& file) {
    const std::string& all = source_.text();
    for (const Line& line : source_.lines()) {
      CommandLine out;
      const std::string_view raw = line.text;
      const std::size_t end = static_cast<std::size_t>(raw.data() - all.data()) + raw.size();
      out.crlf = end < all.size() && all[end] == '\r';
      const std::string_view significant = raw.substr(0, std::min(raw.size(), kSignificantColumns));
      std::size_t indent = 0;
      while (indent < significant.size() && significant[indent] == ' ') ++indent;
      std::string_view text = significant.substr(indent);
      while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
      out.indent = static_cast<std::uint32_t>(indent);
      out.text = Word{std::string(text),
                      make_span(line.number, indent + 1, indent + std::max<std::size_t>(text.size(), 1))};
      out.trailer = std::string(raw.substr(indent + text.size()));
      file.lines.push_back(std::move(out));
    }
  }

  void report(std::string_view code, const CommandLine& line, std::string message, std::string hint = {}) {
    sink_.report(code, Location{source_.path(), line.text.span}, std::move(message), std::move(hint));
  }
  void report_at(std::string_view code, const CommandLine& line, std::size_t offset, std::size_t length,
                 std::string message) {
    const std::uint32_t number = line.text.span.line;
    const std::size_t first = line.indent + offset + 1;
    sink_.report(
        code,
        Location{source_.path(), make_span(number, first, first + std::max<std::size_t>(length, 1) - 1)},
        std::move(message));
  }
  void at_end(std::string_view code, std::string message) {
    const auto& lines = source_.lines();
    const std::uint32_t number = lines.empty() ? 0 : lines.back().number;
    const std::size_t column = lines.empty() ? 0 : lines.back().text.size() + 1;
    SourceSpan span = make_span(number, column, column);
    span.end_column = span.column;
    sink_.report(code, Location{source_.path(), span}, std::move(message));
  }

  // Lines [begin, end) of one section (main program or subroutines).
  void classify(CommandFile& file, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      CommandLine& line = file.lines[i];
      const std::string_view text = line.text.value;
      if (text.empty()) {
        line.kind = CommandLineKind::blank;
        continue;
      }
      if (text[0] == '#') {
        line.kind = CommandLineKind::comment;
        continue;
      }
      if (text[0] == '.') {
        line.kind = CommandLineKind::message;
        continue;
      }
      const CommandKeyword* keyword = find_command_keyword(text);
      if (!keyword) {
        line.kind = CommandLineKind::unknown;
        continue;
      }
      line.kind = keyword->control ? CommandLineKind::control : CommandLineKind::keyword;
      line.keyword = std::string(keyword->keyword);
      if (const auto offset = label_offset(keyword->keyword))
        line.parameter = std::string(from(text, *offset));
      else
        line.parameter = std::string(chic::trim_blanks(from(text, keyword->keyword.size())));
      check_inline(file, i, end, *keyword);
      // Arguments: the following lines, whatever they hold (CHLZZZ(NZZZ+1), ...).
      const auto arguments = keyword->arguments;
      for (std::size_t k = 0; k < arguments.size(); ++k) {
        if (i + 1 >= end) {
          report("L1006", line,
                 "'" + std::string(keyword->keyword) + "' needs " + std::to_string(arguments.size()) +
                     " argument line(s); the " + (end == file.lines.size() ? "file" : "section") +
                     " ends first");
          break;
        }
        ++i;
        read_argument(file.lines[i], arguments[k], keyword->keyword);
      }
    }
  }

  void check_inline(CommandFile& file, std::size_t i, std::size_t end, const CommandKeyword& keyword) {
    const CommandLine& line = file.lines[i];
    const std::string_view text = line.text.value;
    const std::string_view parameter = line.parameter;
    const std::size_t parameter_offset = text.size() - parameter.size();
    auto next_starts = [&](std::string_view word, std::string_view what) {
      if (i + 1 >= end || !starts_with(file.lines[i + 1].text.value, word)) {
        const CommandLine& where = i + 1 < end ? file.lines[i + 1] : line;
        report("L1013", where,
               "'" + std::string(keyword.keyword) + "' must be followed by a '" + std::string(word) +
                   "' line (" + std::string(what) + ")");
      }
    };
    if (keyword.inline_part == CommandInline::step_or_dtps) {
      if (parameter.empty()) {
        if (starts_with(keyword.keyword, "WRITE OUT ") || starts_with(keyword.keyword, "BINARY WRITE OUT "))
          report("L1015", line,
                 "'" + std::string(keyword.keyword) + "' needs 'STEP n' or 'DTPS dt' (LMGC90 stops)");
      } else if (starts_with(parameter, "STEP")) {
        const auto n = chic::list_integer(from(parameter, 4));
        if (!n)
          report_at("L1004", line, parameter_offset, parameter.size(),
                    "'STEP' must be followed by an integer");
        else if (*n < 1)
          report_at("L1003", line, parameter_offset, parameter.size(), "'STEP' period must be >= 1");
      } else if (starts_with(parameter, "DTPS")) {
        const auto items = chic::list_items(from(parameter, 4));
        const auto value = items.empty() ? std::nullopt : read_list_directed_real(items[0]);
        if (!value || value->error != NumberError::none)
          report_at("L1002", line, parameter_offset, parameter.size(), "'DTPS' must be followed by a real");
      } else {
        sink_.report(Diagnostic{"L1019",
                                Severity::warning,
                                Location{source_.path(), line.text.span},
                                "'" + std::string(parameter) + "' after '" + std::string(keyword.keyword) +
                                    "' is neither 'STEP n' nor 'DTPS dt'; LMGC90 ignores it",
                                {},
                                {}});
      }
      return;
    }
    const std::string_view k = keyword.keyword;
    if (k == "DEPUIS") {
      // Only the line after a REPETE (or its DEPUIS line, for 'DEPUIS OCCURENCE m') is read as a
      // loop label; elsewhere CHIC ignores the line (mecaMAILx_2D/taylor lost its REPETE).
      const std::string_view before =
          i > 0 ? std::string_view(file.lines[i - 1].text.value) : std::string_view();
      const bool read = starts_with(before, "REPETE") ||
                        (starts_with(parameter, "OCCURENCE") && starts_with(before, "DEPUIS"));
      if (!read)
        sink_.report(Diagnostic{
            "L1019",
            Severity::warning,
            Location{source_.path(), line.text.span},
            "'DEPUIS' does not follow a 'REPETE n FOIS' line: no loop ends here and LMGC90 ignores it",
            {},
            {}});
    } else if (k == "REPETE") {
      if (!chic::repete_count(text))
        report("L1004", line, "'REPETE n FOIS' needs an integer n and the word FOIS");
      next_starts("DEPUIS", "the loop label");
    } else if (k == "STOP REPETE SI IOK =" || k == "CAP SI IOK =") {
      if (!chic::list_integer(parameter))
        report_at("L1004", line, parameter_offset, parameter.size(),
                  "'" + std::string(k) + "' must be followed by an integer");
      if (k == "CAP SI IOK =") next_starts("SUR ", "the jump target");
    } else if (k == "IOK =" || k == "ROK =") {
      if (starts_with(parameter, "FLAG") || starts_with(parameter, "DRAP")) {
        const auto f = chic::list_integer(from(parameter, 4));
        if (!f || *f < 1 || *f > 15)
          report_at("L1003", line, parameter_offset, parameter.size(),
                    "flag number must be an integer from 1 to 15");
        next_starts("INTO ", "the command whose flag is read");
      } else if (parameter != "?") {
        const bool ok = k == "IOK =" ? chic::list_integer(parameter).has_value() : [&] {
          const auto items = chic::list_items(parameter);
          const auto v = items.empty() ? std::nullopt : read_list_directed_real(items[0]);
          return v && v->error == NumberError::none;
        }();
        if (!ok)
          report_at(k == "IOK =" ? "L1004" : "L1002", line, parameter_offset, parameter.size(),
                    "'" + std::string(k) + "' must be followed by a value, 'FLAG f'/'DRAP f' or '?'");
      }
    } else if (k == "FLAG" || k == "DRAP") {
      const auto f = chic::flag_number(text, k == "FLAG" ? "= IOK" : "= ROK");
      if (!f || *f < 1 || *f > 15)
        report("L1003", line,
               "'" + std::string(k) + " f = " + (k == "FLAG" ? "IOK" : "ROK") +
                   "' needs a flag number from 1 to 15");
      next_starts("INTO ", "the command whose flag is set");
    }
  }

  void read_argument(CommandLine& line, CommandArgumentKind kind, std::string_view keyword) {
    line.kind = CommandLineKind::argument;
    CommandValue value;
    value.kind = kind;
    const std::string_view text = line.text.value;
    const std::string what = "argument of '" + std::string(keyword) + "'";
    auto real_at = [&](std::string_view item) -> std::optional<Real> {
      const std::size_t offset = static_cast<std::size_t>(item.data() - text.data());
      const auto v = read_list_directed_real(item);
      if (!v || v->error != NumberError::none) {
        report_at(v && v->error == NumberError::out_of_range ? "L1003" : "L1002", line, offset, item.size(),
                  what + ": '" + std::string(item) + "' is not a real");
        return std::nullopt;
      }
      const std::size_t first = line.indent + offset + 1;
      return Real{v->value, make_span(line.text.span.line, first, first + item.size() - 1)};
    };
    switch (kind) {
      case CommandArgumentKind::word:
        value.word = line.text;
        break;
      case CommandArgumentKind::integer: {
        const auto items = chic::list_items(text);
        if (items.empty()) {
          report("L1015", line, what + ": an integer is expected");
          break;
        }
        const auto v = read_list_directed_integer(items[0]);
        const std::size_t offset = static_cast<std::size_t>(items[0].data() - text.data());
        if (!v || v->error != NumberError::none) {
          report_at(v && v->error == NumberError::out_of_range ? "L1003" : "L1004", line, offset,
                    items[0].size(), what + ": '" + std::string(items[0]) + "' is not an integer");
          break;
        }
        const std::size_t first = line.indent + offset + 1;
        value.integer = Integer{v->value, make_span(line.text.span.line, first, first + items[0].size() - 1)};
        break;
      }
      case CommandArgumentKind::real:
      case CommandArgumentKind::reals: {
        const auto items = chic::list_items(text);
        if (items.empty()) {
          report("L1015", line, what + ": a real is expected");
          break;
        }
        for (std::size_t k = 0; k < (kind == CommandArgumentKind::real ? 1 : items.size()); ++k) {
          const auto r = real_at(items[k]);
          if (!r) break;
          value.reals.push_back(*r);
        }
        break;
      }
      case CommandArgumentKind::type_tol: {
        // 'Quad 0.1666D-04': the type is characters 1-5, the tolerance is read from 6-30.
        std::string_view type = text.substr(0, std::min<std::size_t>(5, text.size()));
        while (!type.empty() && type.back() == ' ') type.remove_suffix(1);
        value.word =
            Word{std::string(type), make_span(line.text.span.line, line.indent + 1, line.indent + 5)};
        const auto items = chic::list_items(from(text, 5));
        if (items.empty()) {
          report("L1015", line, what + ": a check type and a tolerance are expected");
          break;
        }
        if (const auto r = real_at(items[0])) value.reals.push_back(*r);
        break;
      }
    }
    line.value = std::move(value);
  }

  // A line that matches no keyword is a jump target when a DEPUIS or SUR line names it; otherwise
  // CHIC offers it to every handler, none acts, and it is ignored.
  void resolve_labels(CommandFile& file, std::size_t last) {
    std::set<std::string> targets;
    for (std::size_t i = 0; i < last; ++i) {
      const CommandLine& line = file.lines[i];
      if ((line.keyword == "DEPUIS" || line.keyword == "SUR ") && !starts_with(line.parameter, "OCCURENCE"))
        targets.insert(line.parameter);
    }
    for (std::size_t i = 0; i < last; ++i) {
      CommandLine& line = file.lines[i];
      if (line.kind != CommandLineKind::unknown) continue;
      if (targets.count(line.text.value)) {
        line.kind = CommandLineKind::label;
      } else {
        sink_.report(
            Diagnostic{"L1019",
                       Severity::warning,
                       Location{source_.path(), line.text.span},
                       "'" + line.text.value +
                           "' matches no COMMAND.DAT keyword and no DEPUIS or SUR line "
                           "names it; LMGC90 ignores it",
                       {},
                       "check the spelling (keywords are case-sensitive), or start the line with '#'"});
      }
    }
  }

  // CHECK_CHIC_COMMAND: the main program must hold 'COMPUTE BOX' and 'COMPUTE MASS' unless it
  // holds 'NO CHECK CHIC COMMAND' (exact texts).
  void check_chic_command(const CommandFile& file, std::size_t main_last) {
    bool no_check = false, box = false, mass = false;
    for (std::size_t i = 0; i < main_last; ++i) {
      const std::string& t = file.lines[i].text.value;
      no_check = no_check || t == "NO CHECK CHIC COMMAND";
      box = box || t == "COMPUTE BOX";
      mass = mass || t == "COMPUTE MASS";
    }
    if (no_check) return;
    if (!box)
      at_end("L1012",
             "the main program has no 'COMPUTE BOX' line (LMGC90 stops; write 'NO CHECK CHIC COMMAND' to "
             "skip this check)");
    if (!mass)
      at_end("L1012",
             "the main program has no 'COMPUTE MASS' line (LMGC90 stops; write 'NO CHECK CHIC COMMAND' to "
             "skip this check)");
  }

  const SourceText& source_;
  DiagnosticSink& sink_;
};

}  // namespace

CommandFile parse_command(const SourceText& source, DiagnosticSink& sink) {
  return CommandParser(source, sink).parse();
}

}  // namespace lmgc::grammar
