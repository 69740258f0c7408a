// COMMAND.DAT reader and symbolic interpreter. spec: state-and-outputs.md §2.1.
#include "grammar/command/parser.hpp"

#include <map>
#include <set>
#include <string>

#include "grammar/command/keyword_catalogue.hpp"
#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"

namespace lmgc::grammar {
namespace {

std::string significant(std::string_view line) { return std::string(trim(line.substr(0, std::min<std::size_t>(line.size(), 30)))); }

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// Statements of the main program and of each subroutine, with their argument lines.
struct Program {
  std::vector<ExecutedCommand> main;
  std::map<std::string, std::vector<ExecutedCommand>> subroutines;
};

Program split_program(const CommandFile& file) {
  Program p;
  std::vector<ExecutedCommand>* target = &p.main;
  bool in_main = true;
  for (std::size_t i = 0; i < file.lines.size(); ++i) {
    const CommandLine& l = file.lines[i];
    if (l.kind != CommandLineKind::statement) continue;
    if (starts_with(l.text, "FIN DU PROGRAMME") || starts_with(l.text, "FIN_DU_PROGRAMME")) {
      in_main = false;
      target = nullptr;
      continue;
    }
    if (starts_with(l.text, "FIN DU FICHIER")) break;
    if (starts_with(l.text, "SUB ")) {
      target = &p.subroutines[significant(std::string_view(l.text).substr(4))];
      continue;
    }
    if (starts_with(l.text, "RETOUR")) {
      target = in_main ? &p.main : nullptr;
      continue;
    }
    if (!target) continue;
    ExecutedCommand c{l.text, {}, l.number};
    for (std::size_t j = i + 1; j < file.lines.size(); ++j) {
      const CommandLineKind k = file.lines[j].kind;
      if (k == CommandLineKind::argument) c.arguments.push_back(file.lines[j].text);
      else if (k != CommandLineKind::comment && k != CommandLineKind::blank) break;
    }
    target->push_back(std::move(c));
  }
  return p;
}

// 'REPETE n FOIS' -> n.
long repeat_count(const std::string& statement) {
  auto r = read_list_directed_integer(std::string_view(statement).substr(6));
  return r && r->error == NumberError::none ? r->value : 0;
}

}  // namespace

CommandFile parse_command(const SourceText& source, DiagnosticSink& sink) {
  CommandFile file;
  file.final_newline = source.has_final_newline();
  CardReader reader(source, sink);
  reader.check_records();
  const auto& lines = source.lines();
  std::set<std::string> labels_used;
  for (const Line& l : lines) {
    const std::string s = significant(l.text);
    if (starts_with(s, "DEPUIS ")) labels_used.insert(significant(std::string_view(s).substr(7)));
  }
  std::size_t pending = 0;  // argument lines still to be read by the last statement
  bool end_of_program = false;
  std::set<std::string> subroutines;
  for (const Line& l : lines) {
    CommandLine c;
    c.raw = std::string(l.text);
    c.number = l.number;
    c.text = significant(l.text);
    // Comment and blank lines are skipped by the driver, also between a keyword and its arguments.
    if (pending > 0 && !c.text.empty() && c.text[0] != '#') {
      c.kind = CommandLineKind::argument;
      --pending;
    } else if (c.text.empty()) {
      c.kind = CommandLineKind::blank;
    } else if (c.text[0] == '#') {
      c.kind = CommandLineKind::comment;
    } else if (c.text[0] == '.') {
      c.kind = CommandLineKind::message;
    } else {
      c.kind = CommandLineKind::statement;
      if (const CommandKeyword* k = match_command_keyword(c.text)) {
        pending = k->arguments.size();
        if (starts_with(c.text, "FIN DU PROGRAMME") || starts_with(c.text, "FIN_DU_PROGRAMME")) end_of_program = true;
        if (starts_with(c.text, "SUB ")) subroutines.insert(significant(std::string_view(c.text).substr(4)));
      } else if (!labels_used.count(c.text)) {
        const int last = static_cast<int>(std::min<std::size_t>(l.text.size(), 30));
        reader.report("L1019", l, 1, std::max(last, 1),
                      "'" + c.text + "' is neither a keyword of LMGC90's driver nor a loop label; LMGC90 ignores it");
      }
    }
    file.lines.push_back(std::move(c));
  }
  if (pending > 0) reader.report_at_end("L1006", "file ends where an argument line is expected");
  if (!end_of_program) reader.report_at_end("L1012", "no 'FIN DU PROGRAMME' line ends the main program");
  // Loops and calls name things that exist.
  for (std::size_t i = 0; i < file.lines.size(); ++i) {
    const CommandLine& c = file.lines[i];
    if (c.kind != CommandLineKind::statement) continue;
    const Line& l = lines[c.number - 1];
    if (starts_with(c.text, "REPETE")) {
      const bool depuis = i + 1 < file.lines.size() && starts_with(file.lines[i + 1].text, "DEPUIS");
      if (!depuis) reader.report("L1013", l, 1, 6, "'REPETE' must be followed by a 'DEPUIS <label>' line");
      if (!starts_with(c.text.substr(std::min<std::size_t>(c.text.size(), 6)), " ") || repeat_count(c.text) <= 0)
        reader.report("L1003", l, 1, static_cast<int>(std::min<std::size_t>(c.raw.size(), 30)),
                      "'REPETE n FOIS' needs a count n >= 1");
    }
    if (starts_with(c.text, "APPELLE")) {
      const std::string name = significant(std::string_view(c.text).substr(std::min<std::size_t>(c.text.size(), 8)));
      if (!subroutines.count(name))
        reader.report("L1013", l, 9, 30, "no 'SUB " + name + "' is defined for this 'APPELLE'");
    }
  }
  return file;
}

std::string write_command(const CommandFile& file) {
  std::string out;
  for (std::size_t i = 0; i < file.lines.size(); ++i) {
    out += file.lines[i].raw;
    if (i + 1 < file.lines.size() || file.final_newline) out += '\n';
  }
  return out;
}

namespace {

// Runs the program, handing every executed command to `visit` (no copies).
void run_program(const CommandFile& file, std::size_t max_commands, DiagnosticSink& sink, const CommandFlag& flag,
                 const std::function<void(const ExecutedCommand&)>& visit) {
  const Program program = split_program(file);
  // Inline APPELLE (nested calls allowed; a recursion guard stops cycles).
  std::vector<ExecutedCommand> code;
  std::function<void(const std::vector<ExecutedCommand>&, int)> inline_calls = [&](const std::vector<ExecutedCommand>& body,
                                                                                  int depth) {
    for (const ExecutedCommand& c : body) {
      if (starts_with(c.statement, "APPELLE") && depth < 32) {
        auto it = program.subroutines.find(significant(std::string_view(c.statement).substr(std::min<std::size_t>(c.statement.size(), 8))));
        if (it != program.subroutines.end()) inline_calls(it->second, depth + 1);
        continue;
      }
      code.push_back(c);
    }
  };
  inline_calls(program.main, 0);

  std::size_t executed = 0;
  std::vector<long> counters(code.size(), 0);
  long iok = 0;
  auto find_label_before = [&](std::size_t from, const std::string& label) -> std::size_t {
    for (std::size_t k = from; k-- > 0;)
      if (code[k].statement == label) return k;
    return code.size();
  };
  std::size_t pc = 0;
  while (pc < code.size()) {
    if (executed >= max_commands) {
      sink.report("L1019", Location{"COMMAND.DAT", {}},
                  "program expansion stopped after " + std::to_string(max_commands) + " commands");
      break;
    }
    const ExecutedCommand& c = code[pc];
    const std::string& s = c.statement;
    if (starts_with(s, "REPETE")) {
      const std::string label = c.arguments.empty() ? std::string()
                                                    : significant(std::string_view(c.arguments[0]).substr(std::min<std::size_t>(c.arguments[0].size(), 7)));
      const std::size_t target = find_label_before(pc, label);
      if (target < code.size() && counters[pc] < repeat_count(s)) {
        ++counters[pc];
        pc = target;
        continue;
      }
      counters[pc] = 0;
      ++pc;
      continue;
    }
    if (starts_with(s, "STOP REPETE SI IOK")) {
      const auto k = read_list_directed_integer(std::string_view(s).substr(s.find('=') == std::string::npos ? s.size() : s.find('=') + 1));
      if (k && k->value == iok) {
        // Leave the next enclosing REPETE: skip past it with its counter reset.
        std::size_t next = pc + 1;
        while (next < code.size() && !starts_with(code[next].statement, "REPETE")) ++next;
        if (next < code.size()) counters[next] = 0;
        pc = next + 1;
        continue;
      }
      ++pc;
      continue;
    }
    if (starts_with(s, "IOK = FLAG")) {
      const auto f = read_list_directed_integer(std::string_view(s).substr(10));
      const std::string into = c.arguments.empty() ? std::string() : significant(std::string_view(c.arguments[0]).substr(std::min<std::size_t>(c.arguments[0].size(), 5)));
      iok = flag ? flag(into, f ? static_cast<int>(f->value) : 1) : 0;
    } else if (starts_with(s, "IOK =")) {
      const auto k = read_list_directed_integer(std::string_view(s).substr(5));
      if (k) iok = k->value;
    } else if (starts_with(s, "CAP SI IOK")) {
      const auto k = read_list_directed_integer(std::string_view(s).substr(s.find('=') == std::string::npos ? s.size() : s.find('=') + 1));
      if (k && k->value == iok && !c.arguments.empty()) {
        const std::string target = significant(std::string_view(c.arguments[0]).substr(std::min<std::size_t>(c.arguments[0].size(), 4)));
        for (std::size_t t = 0; t < code.size(); ++t)
          if (code[t].statement == target) {
            visit(c);
            ++executed;
            pc = t;
            break;
          }
        continue;
      }
    }
    if (match_command_keyword(s)) {
      visit(c);
      ++executed;
    }
    ++pc;
  }
}

}  // namespace

std::vector<ExecutedCommand> expand_command_program(const CommandFile& file, std::size_t max_commands,
                                                    DiagnosticSink& sink, const CommandFlag& flag) {
  std::vector<ExecutedCommand> executed;
  run_program(file, max_commands, sink, flag, [&](const ExecutedCommand& c) { executed.push_back(c); });
  return executed;
}

CommandRunParameters command_run_parameters(const CommandFile& file, DiagnosticSink& sink) {
  CommandRunParameters p;
  auto real_of = [](const std::string& text, double& value) {
    auto r = read_list_directed_real(text);
    if (r && r->error == NumberError::none) value = r->value;
  };
  // Structure: the REPETE around EX ITER NLGS sets gs_it1, the next one gs_it2 (n + 1 passes each).
  const Program program = split_program(file);
  std::vector<const ExecutedCommand*> all;
  for (const auto& c : program.main) all.push_back(&c);
  for (const auto& [name, body] : program.subroutines)
    for (const auto& c : body) all.push_back(&c);
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!starts_with(all[i]->statement, "EX ITER NLGS")) continue;
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (starts_with(all[j]->statement, "REPETE")) {
        p.gs_it1 = static_cast<int>(repeat_count(all[j]->statement) + 1);
        for (std::size_t k = j + 1; k < all.size(); ++k)
          if (starts_with(all[k]->statement, "REPETE")) {
            p.gs_it2 = static_cast<int>(repeat_count(all[k]->statement) + 1);
            break;
          }
        break;
      }
    break;
  }
  // Values: the first occurrence in execution order (NLGS loops stop at their first check).
  run_program(file, 10'000'000, sink, {}, [&](const ExecutedCommand& c) {
    const std::string& s = c.statement;
    if (s == "INCREMENT STEP") ++p.steps;
    else if (starts_with(s, "TIME STEP") && !c.arguments.empty() && p.dt == 0.0) real_of(c.arguments[0], p.dt);
    else if (s == "THETA" && !c.arguments.empty()) real_of(c.arguments[0], p.theta);
    else if (starts_with(s, "NLGS CHECK TYPE") && c.arguments.size() >= 2 && p.norm.empty()) {
      p.norm = c.arguments[0].substr(0, std::min<std::size_t>(5, c.arguments[0].size()));
      real_of(c.arguments[0].size() > 5 ? c.arguments[0].substr(5) : std::string(), p.tolerance);
      real_of(c.arguments[1], p.relax);
    } else if (starts_with(s, "EX PREP NLGS") && !c.arguments.empty() && p.storage.empty()) {
      p.storage = c.arguments[0];
    } else if (starts_with(s, "WRITE OUT DOF STEP") && p.write_every == 0) {
      auto n = read_list_directed_integer(std::string_view(s).substr(18));
      if (n) p.write_every = n->value;
    } else if (starts_with(s, "WRITE OUTPUT GMV STEP") && p.display_every == 0) {
      auto n = read_list_directed_integer(std::string_view(s).substr(21));
      if (n) p.display_every = n->value;
    } else if (s == "quickSCRAMBLE") {
      p.quick_scramble = true;
    } else if (starts_with(s, "INIT YMIN BOUNDARY") && !c.arguments.empty()) {
      real_of(c.arguments[0], p.y_min);
      p.has_y_min = true;
    }
  });
  return p;
}

}  // namespace lmgc::grammar
