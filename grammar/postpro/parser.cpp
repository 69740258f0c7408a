// POSTPRO.DAT reader. docs/lmgc90-facts/datbox-inputs.md §8 (reading rules and arguments).
#include "grammar/postpro/parser.hpp"

#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"
#include "grammar/common/list_directed.hpp"
#include "grammar/postpro/catalogue.hpp"

namespace lmgc::grammar {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

class PostproParser {
 public:
  PostproParser(const SourceText& source, DiagnosticSink& sink, int dimension)
      : source_(source), reader_(source, sink), dimension_(dimension) {}

  PostproFile parse() {
    PostproFile file;
    if (!reader_.check_records()) return file;
    const auto& lines = source_.lines();
    while (index_ < lines.size()) {
      const Line& line = lines[index_++];
      // spec §8: one record read as A30; only columns 1-30 matter.
      const std::string_view head = columns(line.text, 1, 30);
      if (starts_with(head, "END")) return file;
      const std::string_view name = trim_right(head);
      const PostproCommandKind* kind = find_postpro_command(name);
      if (kind && kind->available_in(dimension_)) {
        if (auto command = parse_command(*kind, line)) file.commands.push_back(std::move(*command));
        continue;
      }
      if (starts_with(head, "STEP") || starts_with(head, "#")) continue;
      if (name.empty()) {
        reader_.report("L1013", line, 1, 1,
                       "blank line in POSTPRO.DAT; LMGC90 stops on it ('Command does not exist')");
      } else if (kind) {
        reader_.report(
            "L1001", line, 1, static_cast<int>(name.size()),
            "POSTPRO command '" + std::string(name) + "' exists only in LMGC90's " +
                (dimension_ == 2 ? "3D" : "2D") + " post-processor",
            "LMGC90 stops here ('Command ... does not exist'); the lines up to the next command are "
            "not checked");
        skip_to_next_command();
      } else {
        reader_.report("L1001", line, 1, static_cast<int>(name.size()),
                       "unknown POSTPRO command '" + std::string(name) + "'",
                       "names are case-sensitive and start in column 1; LMGC90 stops here ('Command ... does "
                       "not exist'); the lines up to the next command are not checked");
        skip_to_next_command();
      }
    }
    reader_.report_at_end("L1012", "POSTPRO.DAT has no 'END' line");
    return file;
  }

 private:
  // After an unknown command: its STEP and argument lines, whose layout is not known, are skipped
  // up to the next line that names a command (of either dimension) or starts with END.
  void skip_to_next_command() {
    const auto& lines = source_.lines();
    while (index_ < lines.size()) {
      const std::string_view head = columns(lines[index_].text, 1, 30);
      if (starts_with(head, "END") || find_postpro_command(trim_right(head))) return;
      ++index_;
    }
  }

  // The next raw line, read as the argument `what` (no comment skipping: spec §8).
  const Line* next(std::string_view what) {
    if (index_ >= source_.lines().size()) {
      reader_.report_at_end("L1006", "file ends where " + std::string(what) + " is expected");
      return nullptr;
    }
    const Line* line = &source_.lines()[index_++];
    // No look-ahead in LMGC90: a command name read as an argument is consumed and never runs
    // (RIGID_2D/500PL_PerioBoxJC does this).
    const std::string_view head = trim_right(columns(line->text, 1, 30));
    if (find_postpro_command(head) || starts_with(head, "END"))
      reader_.report("L1019", *line, 1, static_cast<int>(std::max<std::size_t>(head.size(), 1)),
                     "'" + std::string(head) + "' is read as " + std::string(what) +
                         " of the command before; LMGC90 consumes this line and never runs it as a command");
    return line;
  }

  bool list_integers(const Line& line, std::size_t count, PostproArgument& argument, std::string_view what) {
    // List-directed input reads the whole record, not only columns 1-30.
    const std::string_view text = columns(line.text, 1, static_cast<int>(kRecordLength));
    const auto items = list_items(text, count);
    if (items.size() < count) {
      reader_.report("L1015", line, 1, static_cast<int>(std::max<std::size_t>(text.size(), 1)),
                     std::string(what) + ": " + std::to_string(count) + " integer(s) expected, " +
                         std::to_string(items.size()) + " found",
                     "LMGC90 would go on reading the next line; write all values on one line");
      return false;
    }
    for (std::string_view item : items) {
      const int first = static_cast<int>(item.data() - line.text.data()) + 1;
      const int last = first + static_cast<int>(item.size()) - 1;
      auto value = read_list_directed_integer(item);
      if (!value || value->error != NumberError::none) {
        reader_.report(value && value->error == NumberError::out_of_range ? "L1003" : "L1004", line, first,
                       last, std::string(what) + ": '" + std::string(item) + "' is not an integer");
        return false;
      }
      argument.integers.push_back(Integer{value->value, reader_.span(line, first, last)});
    }
    return true;
  }

  bool list_real(const Line& line, PostproArgument& argument, std::string_view what) {
    const std::string_view text = columns(line.text, 1, static_cast<int>(kRecordLength));
    const auto items = list_items(text, 1);
    if (items.empty()) {
      reader_.report("L1015", line, 1, 1, std::string(what) + ": a real value is expected");
      return false;
    }
    const int first = static_cast<int>(items[0].data() - line.text.data()) + 1;
    const int last = first + static_cast<int>(items[0].size()) - 1;
    auto value = read_list_directed_real(items[0]);
    if (!value || value->error != NumberError::none) {
      reader_.report(value && value->error == NumberError::out_of_range ? "L1003" : "L1002", line, first,
                     last, std::string(what) + ": '" + std::string(items[0]) + "' is not a real");
      return false;
    }
    argument.reals.push_back(Real{value->value, reader_.span(line, first, last)});
    return true;
  }

  // Reads one argument line with its format.
  bool read_line(const PostproStep& step, PostproArgument& argument) {
    const Line* line = next(step.what);
    if (!line) return false;
    argument.format = step.format;
    const std::size_t errors = reader_.sink().error_count();
    switch (step.format) {
      // Fixed-column integers: LMGC90 reads only the field's columns, so a value spilling out of
      // them is read cut (L1011).
      case PostproLineFormat::i5:
        argument.integers.push_back(reader_.integer(*line, 1, 5));
        break;
      case PostproLineFormat::i7:
        argument.integers.push_back(reader_.integer(*line, 1, 7));
        break;
      case PostproLineFormat::a5:
        argument.word = reader_.word(*line, 1, 5);
        break;
      case PostproLineFormat::a12:
        argument.word = reader_.word(*line, 1, 12);
        break;
      case PostproLineFormat::i7_x_i3:
        argument.integers.push_back(reader_.integer(*line, 1, 7));
        argument.integers.push_back(reader_.integer(*line, 9, 11));
        break;
      case PostproLineFormat::i7_x_i7:
        argument.integers.push_back(reader_.integer(*line, 1, 7));
        argument.integers.push_back(reader_.integer(*line, 9, 15));
        break;
      case PostproLineFormat::list_integer:
        return list_integers(*line, 1, argument, step.what);
      case PostproLineFormat::list_integer_pair:
        return list_integers(*line, 2, argument, step.what);
      case PostproLineFormat::list_integer_quad:
        return list_integers(*line, 4, argument, step.what);
      case PostproLineFormat::list_real:
        return list_real(*line, argument, step.what);
      case PostproLineFormat::es14_7:
        argument.reals.push_back(reader_.real(*line, 1, 14));
        break;
      case PostproLineFormat::dense_sample: {
        // Always consumes one line; 'INTER' in columns 1-5 names an interior body (columns 7-13).
        const std::string_view text = trim_right(columns(line->text, 1, 30));
        argument.word = Word{std::string(text), reader_.span(*line, 1, 30)};
        if (starts_with(text, "INTER")) argument.integers.push_back(reader_.integer(*line, 7, 13));
        break;
      }
    }
    return reader_.sink().error_count() == errors;
  }

  // Runs a layout: each step reads one line; a repeating step reads its body `count` times.
  bool run(std::span<const PostproStep> steps, PostproCommand& command) {
    std::size_t i = 0;
    while (i < steps.size()) {
      const PostproStep& step = steps[i];
      PostproArgument argument;
      if (!read_line(step, argument)) return false;
      std::int64_t count = 0;
      if (step.repeat == PostproRepeat::last_integer && !argument.integers.empty()) {
        count = argument.integers.back().value;
      } else if (step.repeat == PostproRepeat::compacity_model) {
        count = postpro_compacity_ids(argument.word.value);
        if (count < 0) {
          reader_.report("L1017", source_.lines()[index_ - 1], 1, 12,
                         "compacity model '" + argument.word.value +
                             "' is not one of SMOOTH BOX, ROUGH BOX, COUETTE, CLUSTER BOX, SELECTION");
          return false;
        }
      }
      command.arguments.push_back(std::move(argument));
      const std::size_t body =
          std::min<std::size_t>(static_cast<std::size_t>(step.body), steps.size() - i - 1);
      // A Fortran DO with a count below 1 runs no pass; each pass reads at least one line, so
      // the loop ends at the end of the file whatever the count.
      for (std::int64_t k = 0; k < count; ++k)
        if (!run(steps.subspan(i + 1, body), command)) return false;
      i += 1 + body;
    }
    return true;
  }

  std::optional<PostproCommand> parse_command(const PostproCommandKind& kind, const Line& name_line) {
    PostproCommand command;
    command.name =
        Word{std::string(kind.name), reader_.span(name_line, 1, static_cast<int>(kind.name.size()))};
    if (index_ >= source_.lines().size()) {
      reader_.report_at_end("L1006",
                            "file ends after '" + std::string(kind.name) + "'; a 'STEP n' line is expected");
      return std::nullopt;
    }
    const Line& step = source_.lines()[index_];
    if (!starts_with(step.text, "STEP")) {
      // LMGC90: "Keyword STEP is missing for command ..." (fatal). The line is left to the
      // command loop so that what follows is still checked.
      reader_.report("L1013", step, 1, 4, "the line after '" + std::string(kind.name) + "' must be 'STEP n'");
      return std::nullopt;
    }
    ++index_;
    // The period is read list-directed from columns 5-30 of the STEP line.
    const std::string_view field = columns(step.text, 5, 30);
    const auto items = list_items(field, 1);
    if (items.empty()) {
      reader_.report("L1015", step, 5, 30, "the period of 'STEP' is missing");
      return std::nullopt;
    }
    const int first = static_cast<int>(items[0].data() - step.text.data()) + 1;
    const int last = first + static_cast<int>(items[0].size()) - 1;
    auto period = read_list_directed_integer(items[0]);
    if (!period || period->error != NumberError::none) {
      reader_.report("L1004", step, first, last, "the period of 'STEP' is not an integer");
      return std::nullopt;
    }
    command.period = Integer{period->value, reader_.span(step, first, last)};
    if (period->value < 1)
      reader_.report("L1003", step, first, last,
                     "'STEP' period must be >= 1 (LMGC90 runs the command when Nstep mod n == 0)");
    if (!run(kind.layout(dimension_), command)) return std::nullopt;
    return command;
  }

  const SourceText& source_;
  CardReader reader_;
  int dimension_;
  std::size_t index_ = 0;
};

}  // namespace

PostproFile parse_postpro(const SourceText& source, DiagnosticSink& sink, int dimension) {
  return PostproParser(source, sink, dimension).parse();
}

}  // namespace lmgc::grammar
