// POSTPRO.DAT reader. spec: datbox-inputs.md §8 (reading rules and arguments).
#include "grammar/postpro/parser.hpp"

#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"
#include "grammar/postpro/catalogue.hpp"

namespace lmgc::grammar {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

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
      const std::string_view head = trim_right(columns(line.text, 1, 30));
      if (starts_with(head, "END")) return file;
      if (const PostproCommandKind* kind = find_postpro_command(head)) {
        if (auto command = parse_command(*kind, line)) file.commands.push_back(std::move(*command));
        continue;
      }
      if (starts_with(head, "STEP") || starts_with(head, "#")) continue;
      if (head.empty()) {
        reader_.report("L1013", line, 1, 1, "blank line in POSTPRO.DAT; LMGC90 stops on it ('Command does not exist')");
      } else {
        reader_.report("L1001", line, 1, static_cast<int>(head.size()),
                       "unknown POSTPRO command '" + std::string(head) + "'");
      }
    }
    reader_.report_at_end("L1012", "POSTPRO.DAT has no 'END' line");
    return file;
  }

 private:
  const Line* next(const char* what) {
    if (index_ >= source_.lines().size()) {
      reader_.report_at_end("L1006", std::string("file ends where ") + what + " is expected");
      return nullptr;
    }
    const Line* line = &source_.lines()[index_++];
    // A command name read as an argument: LMGC90 consumes it (500PL_PerioBoxJC does this).
    const std::string_view head = trim_right(columns(line->text, 1, 30));
    if (find_postpro_command(head))
      reader_.report("L1019", *line, 1, static_cast<int>(head.size()),
                     "command '" + std::string(head) + "' is read as " + what + " of the command before; LMGC90 never runs it");
    return line;
  }

  bool integer(PostproArgument& arg, const char* what, int first = 1, int last = 7) {
    const Line* line = next(what);
    if (!line) return false;
    arg.integers.push_back(reader_.integer(*line, first, last, false));
    return true;
  }

  bool list_integers(PostproArgument& arg, const char* what, int count) {
    const Line* line = next(what);
    if (!line) return false;
    std::string_view rest = columns(line->text, 1, 180);
    for (int k = 0; k < count; ++k) {
      auto value = read_list_directed_integer(rest);
      if (!value || value->error != NumberError::none) {
        reader_.report("L1015", *line, 1, static_cast<int>(line->text.size()) + 1, std::string(what) + ": missing integer");
        return false;
      }
      arg.integers.push_back(Integer{value->value, reader_.span(*line, 1, 30)});
      // Skip the item just read.
      std::size_t p = rest.find_first_not_of(" ,\t");
      p = rest.find_first_of(" ,\t/", p == std::string_view::npos ? rest.size() : p);
      rest = p == std::string_view::npos ? std::string_view() : rest.substr(p);
    }
    return true;
  }

  PostproArgument argument() { return PostproArgument{}; }

  std::optional<PostproCommand> parse_command(const PostproCommandKind& kind, const Line& name_line) {
    PostproCommand command;
    command.name = Word{std::string(kind.name), reader_.span(name_line, 1, static_cast<int>(kind.name.size()))};
    if (index_ >= source_.lines().size()) {
      reader_.report_at_end("L1006", "file ends after '" + std::string(kind.name) + "'; a 'STEP n' line is expected");
      return std::nullopt;
    }
    const Line& step = source_.lines()[index_++];
    if (!starts_with(step.text, "STEP")) {
      reader_.report("L1013", step, 1, 4, "the line after '" + std::string(kind.name) + "' must be 'STEP n'");
      return std::nullopt;
    }
    auto period = read_list_directed_integer(columns(step.text, 5, 30));
    if (!period || period->error != NumberError::none) {
      reader_.report("L1015", step, 5, 30, "the period of 'STEP' is missing or not an integer");
      return std::nullopt;
    }
    command.period = Integer{period->value, reader_.span(step, 5, 30)};
    if (period->value < 1) reader_.report("L1003", step, 5, 30, "'STEP' period must be >= 1");

    auto push = [&](PostproArgument a) { command.arguments.push_back(std::move(a)); };
    auto one_integer = [&](const char* what, int last = 7) {
      PostproArgument a;
      if (!integer(a, what, 1, last)) return false;
      push(std::move(a));
      return true;
    };
    auto word = [&](const char* what, int width) {
      const Line* line = next(what);
      if (!line) return false;
      PostproArgument a;
      a.word = reader_.word(*line, 1, width);
      push(std::move(a));
      return true;
    };
    // A count then that many lines of `each`.
    auto counted = [&](const char* what, auto each) {
      PostproArgument a;
      if (!integer(a, what)) return false;
      const std::int64_t n = a.integers.back().value;
      push(std::move(a));
      for (std::int64_t k = 0; k < n; ++k)
        if (!each()) return false;
      return true;
    };
    bool ok = true;
    switch (kind.arguments) {
      case PostproArguments::none: break;
      case PostproArguments::colour: ok = word("the colour", 5); break;
      case PostproArguments::species:
        ok = counted("the number of species", [&] { return word("a species nickname", 5); });
        break;
      case PostproArguments::sectors_2d:
        if (dimension_ == 2) ok = one_integer("the number of sectors", 5);
        break;
      case PostproArguments::classes: {
        if (dimension_ == 2) {
          ok = one_integer("the number of classes", 5);
        } else {
          PostproArgument a;
          ok = list_integers(a, "the number of classes", 1);
          if (ok) push(std::move(a));
        }
        break;
      }
      case PostproArguments::body_list:
        ok = counted("the number of bodies", [&] { return one_integer("a body number"); });
        break;
      case PostproArguments::mp_tracking:
        ok = counted("the number of bodies", [&] {
          const Line* line = next("a body and contactor");
          if (!line) return false;
          PostproArgument a;
          a.integers.push_back(reader_.integer(*line, 1, 7, false));
          a.integers.push_back(reader_.integer(*line, 9, 11, false));
          push(std::move(a));
          return true;
        });
        break;
      case PostproArguments::dense_sample: {
        const Line* line = next("the 'INTER' line (or any line)");
        if (!line) return std::nullopt;
        PostproArgument a;
        a.word = reader_.word(*line, 1, 5);
        if (a.word.value == "INTER") a.integers.push_back(reader_.integer(*line, 7, 13, false));
        else a.word = Word{std::string(trim_right(columns(line->text, 1, 30))), reader_.span(*line, 1, 30)};
        push(std::move(a));
        break;
      }
      case PostproArguments::doublet:
        ok = word("the interaction type", 5) && one_integer("the first body") && one_integer("the second body");
        break;
      case PostproArguments::extrusion:
      case PostproArguments::fraction:
        for (int k = 0; k < (kind.arguments == PostproArguments::extrusion ? 2 : 1) && ok; ++k) {
          const Line* line = next("a real value");
          if (!line) return std::nullopt;
          PostproArgument a;
          auto value = read_list_directed_real(columns(line->text, 1, 30));
          if (!value || value->error != NumberError::none) {
            reader_.report("L1002", *line, 1, 30, "expected a real value");
            ok = false;
          } else {
            a.reals.push_back(Real{value->value, reader_.span(*line, 1, 30)});
            push(std::move(a));
          }
        }
        break;
      case PostproArguments::meca_sets:
        ok = counted("the number of sets", [&] {
          return counted("the number of members", [&] {
            const Line* line = next("a body and its node count");
            if (!line) return false;
            PostproArgument a;
            a.integers.push_back(reader_.integer(*line, 1, 7, false));
            a.integers.push_back(reader_.integer(*line, 9, 15, false));
            const std::int64_t nodes = a.integers.back().value;
            push(std::move(a));
            for (std::int64_t k = 0; k < nodes; ++k)
              if (!one_integer("a node number")) return false;
            return true;
          });
        });
        break;
      case PostproArguments::dist_sets:
        ok = counted("the number of sets", [&] {
          PostproArgument a;
          if (!list_integers(a, "a body-node pair", 4)) return false;
          push(std::move(a));
          return true;
        });
        break;
      case PostproArguments::rigid_sets:
        ok = counted("the number of sets", [&] { return counted("the set size", [&] { return one_integer("a body number"); }); });
        break;
      case PostproArguments::bounded_sets:
        ok = counted("the number of sets", [&] { return one_integer("idmin") && one_integer("idmax"); });
        break;
      case PostproArguments::compacity: {
        ok = word("the bulk behaviour", 5) && word("the model", 12);
        const std::string model = ok ? command.arguments.back().word.value : std::string();
        const int ids = model == "CLUSTER BOX" ? 4 : model == "COUETTE" ? 2 : 0;
        for (int k = 0; k < ids && ok; ++k) ok = one_integer("a body number");
        break;
      }
      case PostproArguments::clxxx:
      case PostproArguments::pairs: {
        PostproArgument a;
        ok = list_integers(a, "the number of pairs", 1);
        if (!ok) break;
        const std::int64_t n = a.integers.back().value;
        push(std::move(a));
        for (std::int64_t k = 0; k < n && ok; ++k) {
          PostproArgument b;
          ok = list_integers(b, "a pair", 2);
          if (ok) push(std::move(b));
        }
        break;
      }
      case PostproArguments::triaxial:
        for (int k = 0; k < 6 && ok; ++k) ok = one_integer("a wall body number", 5);
        break;
    }
    if (!ok) return std::nullopt;
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
