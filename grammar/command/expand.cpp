// CHIC's compilation and execution of COMMAND.DAT (module CHIC: CHIC_comp, REPETE, STOPREP,
// IOKEGAL, FLAGEGAL, CAPSUR). docs/lmgc90-facts/state-and-outputs.md §2.1.2.
#include "grammar/command/expand.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>

#include "grammar/command/catalogue.hpp"
#include "grammar/command/chic_text.hpp"

namespace lmgc::grammar {
namespace {

using chic::from;
using chic::starts_with;

constexpr std::size_t kMaxCommands = 1000;  // NTXZZZ
constexpr std::size_t kMaxLoops = 50;       // NBXZZZ

class Compiler {
 public:
  Compiler(const CommandFile& file, DiagnosticSink& sink, const std::string& path)
      : file_(file), sink_(sink), path_(path) {}

  std::optional<CommandProgram> compile() {
    const std::size_t count = file_.lines.size();
    std::size_t main_end = count, file_end = count;
    for (std::size_t i = 0; i < count && main_end == count; ++i)
      if (text(i) == "FIN DU PROGRAMME" || text(i) == "FIN_DU_PROGRAMME") main_end = i;
    for (std::size_t i = main_end + 1; i < count && file_end == count; ++i)
      if (text(i) == "FIN DU FICHIER" || text(i) == "FIN_DU_FICHIER") file_end = i;
    if (main_end == count || file_end == count) {
      report_file("L1012", "the program has no 'FIN DU PROGRAMME' or 'FIN DU FICHIER' line");
      return std::nullopt;
    }
    CommandProgram program;
    for (std::size_t i = 0; i <= main_end; ++i) program.entries.push_back(i);
    // Deployment: replace every APPELLE until none remains (nested calls need several passes).
    for (bool again = true; again;) {
      again = false;
      std::vector<std::size_t> deployed;
      for (std::size_t entry : program.entries) {
        if (!starts_with(text(entry), "APPEL")) {
          deployed.push_back(entry);
        } else {
          again = true;
          // CRZZZ = 'SUB ' // CHZZZ(9:30) with its last characters blanked: names of 22 characters.
          std::string target = "SUB " + std::string(from(text(entry), 8).substr(0, 22));
          while (!target.empty() && target.back() == ' ') target.pop_back();
          std::size_t sub = file_end;
          for (std::size_t s = main_end + 1; s < file_end && sub == file_end; ++s)
            if (text(s) == target) sub = s;
          if (sub == file_end) {
            report("L1012", entry,
                   "'" + target + "' not found after 'FIN DU PROGRAMME' (LMGC90: introuvable)");
            return std::nullopt;
          }
          deployed.push_back(sub);
          std::size_t s = sub + 1;
          for (; s < file_end && text(s) != "RETOUR"; ++s) deployed.push_back(s);
          if (s >= file_end) {
            report("L1012", sub, "'" + target + "' has no 'RETOUR' line before 'FIN DU FICHIER'");
            return std::nullopt;
          }
          deployed.push_back(s);
        }
        if (deployed.size() > kMaxCommands) {
          report("L1003", entry, "more than 1000 commands once APPELLE calls are expanded (CHIC's limit)");
          return std::nullopt;
        }
      }
      program.entries = std::move(deployed);
    }
    const std::size_t n = program.entries.size();
    // Occurrences: an 'OCCURENCE m' entry numbers the entry before it.
    program.occurrence.assign(n, 0);
    for (std::size_t k = 1; k < n; ++k)
      if (starts_with(deployed_text(program, k), "OCCURENCE"))
        program.occurrence[k - 1] = chic::list_integer(from(deployed_text(program, k), 9)).value_or(0);
    // Loops: 'REPETE n FOIS' / 'DEPUIS label' [/ 'DEPUIS OCCURENCE m'], label searched backwards.
    for (std::size_t k = 0; k < n; ++k) {
      if (!starts_with(deployed_text(program, k), "REPETE")) continue;
      const std::size_t line = program.entries[k];
      if (program.loops.size() == kMaxLoops) {
        report("L1003", line, "more than 50 REPETE loops once APPELLE calls are expanded (CHIC's limit)");
        return std::nullopt;
      }
      const auto count_of = chic::repete_count(deployed_text(program, k));
      if (!count_of || k + 1 >= n) {
        report("L1013", line, "'REPETE n FOIS' must hold a count and be followed by 'DEPUIS label'");
        return std::nullopt;
      }
      const std::string label(from(deployed_text(program, k + 1), 7));
      std::int64_t occurrence = 0;
      if (k + 2 < n && starts_with(deployed_text(program, k + 2), "DEPUIS OCCURENCE"))
        occurrence = chic::list_integer(from(deployed_text(program, k + 2), 16)).value_or(0);
      std::size_t found = n;
      for (std::size_t back = k; back-- > 0 && found == n;)
        if (deployed_text(program, back) == label && program.occurrence[back] == occurrence) found = back;
      if (found == n) {
        report("L1012", program.entries[k + 1],
               "loop label '" + label + "' not found before the REPETE line (LMGC90: introuvable)");
        return std::nullopt;
      }
      program.loops.push_back(CommandLoop{k, found, *count_of});
    }
    return program;
  }

 private:
  const std::string& text(std::size_t line) const { return file_.lines[line].text.value; }
  const std::string& deployed_text(const CommandProgram& p, std::size_t k) const {
    return text(p.entries[k]);
  }
  void report(std::string_view code, std::size_t line, std::string message) {
    sink_.report(code, Location{path_, file_.lines[line].text.span}, std::move(message));
  }
  void report_file(std::string_view code, std::string message) {
    sink_.report(code, Location{path_, SourceSpan{}}, std::move(message));
  }

  const CommandFile& file_;
  DiagnosticSink& sink_;
  const std::string& path_;
};

// The first deployed entry with this text and occurrence (CHIC's target search); n if none.
std::size_t find_entry(const CommandFile& file, const CommandProgram& p, std::string_view target,
                       std::int64_t occurrence) {
  for (std::size_t k = 0; k < p.entries.size(); ++k)
    if (file.lines[p.entries[k]].text.value == target && p.occurrence[k] == occurrence) return k;
  return p.entries.size();
}

}  // namespace

std::optional<CommandProgram> compile_command_program(const CommandFile& file, DiagnosticSink& sink,
                                                      const std::string& path) {
  return Compiler(file, sink, path).compile();
}

std::size_t run_command_program(const CommandFile& file, std::size_t max_commands, DiagnosticSink& sink,
                                std::span<const CommandFlagRule> rules,
                                const std::function<void(const ExecutedCommand&)>& visit) {
  std::size_t executed = 0;
  const auto compiled = compile_command_program(file, sink);
  if (!compiled) return executed;
  const CommandProgram& p = *compiled;
  const std::size_t n_entries = p.entries.size();
  auto text = [&](std::size_t k) -> std::string_view {
    return k < n_entries ? std::string_view(file.lines[p.entries[k]].text.value) : std::string_view();
  };
  // 'INTO target' [+ 'INTO OCCURENCE m'] (or SUR) on the entries after k: the entry it names.
  auto target_of = [&](std::size_t k, std::size_t cut, std::string_view occurrence_word) {
    const std::string_view target = from(text(k + 1), cut);
    std::int64_t occurrence = 0;
    if (starts_with(text(k + 2), occurrence_word))
      occurrence = chic::list_integer(from(text(k + 2), occurrence_word.size())).value_or(0);
    return find_entry(file, p, target, occurrence);
  };

  // Each entry's command module and arguments, and the kind of each control line, looked up once:
  // loops run the same lines many times (a 100 000-step script is millions of lines).
  std::vector<std::optional<ExecutedCommand>> prepared(n_entries);
  enum class Control : std::uint8_t { other, end, repete, stop_repete, cap, iok, flag, rok, drap };
  std::vector<Control> control(n_entries, Control::other);
  for (std::size_t k = 0; k < n_entries; ++k) {
    const std::string_view t = text(k);
    if (t == "FIN DU PROGRAMME" || t == "FIN_DU_PROGRAMME")
      control[k] = Control::end;
    else if (starts_with(t, "REPETE"))
      control[k] = Control::repete;
    else if (starts_with(t, "STOP REPETE SI IOK ="))
      control[k] = Control::stop_repete;
    else if (starts_with(t, "CAP SI IOK ="))
      control[k] = Control::cap;
    else if (starts_with(t, "IOK ="))
      control[k] = Control::iok;
    else if (starts_with(t, "FLAG"))
      control[k] = Control::flag;
    else if (starts_with(t, "ROK ="))
      control[k] = Control::rok;
    else if (starts_with(t, "DRAP"))
      control[k] = Control::drap;
  }
  std::vector<std::int64_t> counter(p.loops.size());
  for (std::size_t l = 0; l < p.loops.size(); ++l) counter[l] = p.loops[l].count;
  std::map<std::pair<std::size_t, std::int64_t>, std::int64_t> flags;  // IFLZZZ(entry, f)
  std::map<std::pair<std::size_t, std::int64_t>, double> draps;        // DRPZZZ(entry, f)
  std::int64_t iok = 0;
  double rok = 0.0;
  // Control lines cost no command: bound the work so that a loop of control lines ends.
  const std::size_t step_limit = 1000000 + 64 * max_commands;
  std::size_t steps = 0;
  for (std::size_t k = 0; k < n_entries && executed < max_commands && steps < step_limit; ++k, ++steps) {
    const CommandLine& line = file.lines[p.entries[k]];
    const std::string_view t = line.text.value;
    if (control[k] == Control::end) break;
    if (line.kind == CommandLineKind::keyword) {
      if (!prepared[k]) {
        ExecutedCommand& command = prepared[k].emplace();
        command.keyword = line.keyword;
        const CommandKeyword* kind = find_command_keyword(t);
        command.module = kind ? std::string(kind->module) : std::string();
        command.text = line.text.value;
        command.parameter = line.parameter;
        for (std::size_t a = p.entries[k] + 1;
             a < file.lines.size() && file.lines[a].kind == CommandLineKind::argument; ++a)
          if (file.lines[a].value) command.arguments.push_back(*file.lines[a].value);
        command.line = line.text.span.line;
        command.deployed = k;
      }
      const ExecutedCommand& command = *prepared[k];
      for (const CommandFlagRule& rule : rules)
        if (rule.keyword == command.keyword) flags[{k, rule.flag}] = rule.value;
      ++executed;
      visit(command);
      continue;
    }
    if (control[k] == Control::repete) {
      for (std::size_t l = 0; l < p.loops.size(); ++l) {
        if (p.loops[l].repete != k) continue;
        if (counter[l] > 0) {
          k = p.loops[l].label - 1;  // the label line runs next
          --counter[l];
        } else {
          counter[l] = p.loops[l].count;  // reset so the loop can be entered again
        }
        break;
      }
    } else if (control[k] == Control::stop_repete) {
      if (chic::list_integer(from(t, 20)) == iok) {
        // Leave through the next REPETE line with its counter at zero.
        for (std::size_t i = k + 1; i < n_entries; ++i) {
          if (!starts_with(text(i), "REPETE")) continue;
          const auto loop = std::find_if(p.loops.begin(), p.loops.end(),
                                         [&](const CommandLoop& c) { return c.repete == i; });
          if (loop != p.loops.end()) {
            counter[static_cast<std::size_t>(loop - p.loops.begin())] = 0;
            k = i - 1;
          }
          break;
        }
      }
    } else if (control[k] == Control::cap) {
      if (chic::list_integer(from(t, 12)) == iok) {
        const std::size_t m = target_of(k, 4, "SUR OCCURENCE");
        // Counters of the loops left by the jump are reset.
        for (std::size_t l = 0; l < p.loops.size(); ++l) {
          const bool encloses_here = p.loops[l].repete >= k && p.loops[l].label <= k;
          const bool encloses_target = p.loops[l].repete >= m && p.loops[l].label <= m;
          if (encloses_here && !encloses_target) counter[l] = p.loops[l].count;
        }
        if (m >= n_entries) break;  // no such line: CHIC runs off the end of its list
        k = m - 1;
      }
    } else if (control[k] == Control::iok) {
      const std::string_view rest = from(t, 5);
      if (starts_with(rest, " FLAG")) {
        const std::int64_t f = chic::list_integer(from(rest, 5)).value_or(0);
        const auto it = flags.find({target_of(k, 5, "INTO OCCURENCE"), f});
        iok = it == flags.end() ? 0 : it->second;
      } else if (starts_with(rest, " ?")) {
        iok = 0;  // keyboard input: not available here
      } else {
        iok = chic::list_integer(rest).value_or(iok);
      }
    } else if (control[k] == Control::flag) {
      if (const auto f = chic::flag_number(t, "= IOK")) flags[{target_of(k, 5, "INTO OCCURENCE"), *f}] = iok;
    } else if (control[k] == Control::rok) {
      const std::string_view rest = from(t, 5);
      if (starts_with(rest, " DRAP")) {
        const std::int64_t f = chic::list_integer(from(rest, 5)).value_or(0);
        const auto it = draps.find({target_of(k, 5, "INTO OCCURENCE"), f});
        rok = it == draps.end() ? 0.0 : it->second;
      } else if (!starts_with(rest, " ?")) {
        const auto items = chic::list_items(rest);
        const auto v = items.empty() ? std::nullopt : read_list_directed_real(items[0]);
        if (v && v->error == NumberError::none) rok = v->value;
      }
    } else if (control[k] == Control::drap) {
      if (const auto f = chic::flag_number(t, "= ROK")) draps[{target_of(k, 5, "INTO OCCURENCE"), *f}] = rok;
    }
  }
  return executed;
}

std::vector<ExecutedCommand> expand_command_program(const CommandFile& file, std::size_t max_commands,
                                                    DiagnosticSink& sink,
                                                    std::span<const CommandFlagRule> rules) {
  std::vector<ExecutedCommand> executed;
  run_command_program(file, max_commands, sink, rules,
                      [&](const ExecutedCommand& c) { executed.push_back(c); });
  return executed;
}

CommandRunParameters command_run_parameters(const CommandFile& file, DiagnosticSink& sink) {
  CommandRunParameters p;
  // Loop structure, in file order: the REPETE after EX ITER NLGS gives the sweeps per check,
  // the next one the checks (n + 1 passes each).
  for (std::size_t i = 0; i < file.lines.size(); ++i) {
    if (file.lines[i].keyword != "EX ITER NLGS") continue;
    int found = 0;
    for (std::size_t j = i + 1; j < file.lines.size() && found < 2; ++j) {
      if (file.lines[j].keyword != "REPETE") continue;
      const std::int64_t passes = chic::repete_count(file.lines[j].text.value).value_or(0) + 1;
      const int clamped = static_cast<int>(std::clamp<std::int64_t>(passes, -1, 1'000'000'000));
      (found == 0 ? p.gs_it1 : p.gs_it2) = clamped;
      p.lines[found == 0 ? "gs_it1" : "gs_it2"] = file.lines[j].text.span.line;
      ++found;
    }
    break;
  }
  // Values: the first one met in execution order (every flag 0: NLGS loops stop at their first
  // check); steps: every INCREMENT STEP of the bounded run.
  auto first_real = [](const ExecutedCommand& c, std::size_t k, double& value) {
    if (k < c.arguments.size() && !c.arguments[k].reals.empty()) value = c.arguments[k].reals[0].value;
  };
  // The line holding argument k of a command (its own line when it has none).
  auto argument_line = [](const ExecutedCommand& c, std::size_t k) {
    if (k < c.arguments.size() && !c.arguments[k].reals.empty()) return c.arguments[k].reals[0].span.line;
    return c.line;
  };
  const auto set = [&](std::string_view name, std::uint32_t line) {
    p.lines.emplace(std::string(name), line);
  };
  // A line met again (a loop) changes nothing but the step count: remember which lines count steps.
  enum class Seen : std::uint8_t { not_yet, step, done };
  std::vector<Seen> seen;
  p.lines["nb_steps"] = 0;
  run_command_program(file, 10'000'000, sink, {}, [&](const ExecutedCommand& c) {
    if (c.deployed >= seen.size()) seen.resize(c.deployed + 1, Seen::not_yet);
    if (seen[c.deployed] == Seen::step) {
      ++p.steps;
      return;
    }
    if (seen[c.deployed] == Seen::done) return;
    const std::string& k = c.keyword;
    seen[c.deployed] = k == "INCREMENT STEP" ? Seen::step : Seen::done;
    if (k == "INCREMENT STEP") {
      if (p.steps == 0) p.lines["nb_steps"] = c.line;
      ++p.steps;
    } else if (k == "TIME STEP" && !p.lines.count("dt")) {
      first_real(c, 0, p.dt);
      set("dt", argument_line(c, 0));
    } else if (k == "THETA") {
      first_real(c, 0, p.theta);
      p.lines["theta"] = argument_line(c, 0);
    } else if (k == "NLGS CHECK TYPE" && p.norm.empty() && c.arguments.size() >= 2) {
      p.norm = c.arguments[0].word.value;
      first_real(c, 0, p.tolerance);
      first_real(c, 1, p.relax);
      set("norm", argument_line(c, 0));
      set("tol", argument_line(c, 0));
      set("relax", argument_line(c, 1));
    } else if (k == "EX PREP NLGS" && p.storage.empty() && !c.arguments.empty()) {
      p.storage = c.arguments[0].word.value;
      set("solver_type", c.arguments[0].word.span.line);
    } else if (k == "WRITE OUT DOF" && p.write_every == 0 && starts_with(c.parameter, "STEP")) {
      p.write_every = chic::list_integer(from(c.parameter, 4)).value_or(0);
      set("freq_write", c.line);
    } else if (k == "WRITE OUTPUT GMV" && p.display_every == 0 && starts_with(c.parameter, "STEP")) {
      p.display_every = chic::list_integer(from(c.parameter, 4)).value_or(0);
      set("freq_display", c.line);
    } else if (k == "quickSCRAMBLE") {
      p.quick_scramble = true;
      set("quick_scramble", c.line);
    } else if (k == "INIT YMIN BOUNDARY") {
      first_real(c, 0, p.y_min);
      p.has_y_min = true;
      set("ymin_boundary", argument_line(c, 0));
    } else if (k == "INIT YMAX BOUNDARY") {
      first_real(c, 0, p.y_max);
      set("ymax_boundary", argument_line(c, 0));
    } else if (k == "INIT XMIN BOUNDARY") {
      first_real(c, 0, p.x_min);
      set("xmin_boundary", argument_line(c, 0));
    } else if (k == "INIT XMAX BOUNDARY") {
      first_real(c, 0, p.x_max);
      set("xmax_boundary", argument_line(c, 0));
    } else if (k == "PERIODIC CONDITION" || k == "XPERIODIC CONDITION") {
      first_real(c, 0, p.x_period);
      set("xperiod", argument_line(c, 0));
    } else if (k == "YPERIODIC CONDITION") {
      first_real(c, 0, p.y_period);
      set("yperiod", argument_line(c, 0));
    } else if (k == "NEW ROTATION SCHEME") {
      p.new_rotation_scheme = true;
      set("new_rotation_scheme", c.line);
    } else if (k == "DIAGONAL RESOLUTION") {
      p.diagonal_resolution = true;
      set("diagonal_resolution", c.line);
    } else if ((k == "FATAL DAMPING" || k == "INI V DOF NULL") && p.steps == 0) {
      p.zero_initial_velocity = true;
      set("zero_initial_velocity", c.line);
    } else if (k == "CUNDALL ITERATION" && !c.arguments.empty()) {
      p.cundall_iterations = static_cast<long>(c.arguments[0].integer.value);
      set("cundall_iterations", c.arguments[0].integer.span.line);
    } else if ((k == "FD INIT SOURCE POINT" || k == "INIT SOURCE POINT") && c.arguments.size() >= 3 &&
               c.arguments[2].reals.size() >= 3) {
      p.has_source_point = true;
      p.source_point_absolute = k == "FD INIT SOURCE POINT";
      p.source_first = c.arguments[0].integer.value;
      first_real(c, 1, p.source_radius);
      for (int d = 0; d < 3; ++d) p.source_point[d] = c.arguments[2].reals[static_cast<std::size_t>(d)].value;
      set("source_point", c.arguments[0].integer.span.line);
    }
  });
  return p;
}

}  // namespace lmgc::grammar
