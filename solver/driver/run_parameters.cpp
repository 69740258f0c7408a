#include "solver/driver/run_parameters.hpp"

#include <fmt/format.h>

#include <cmath>

namespace lmgc::solver {
namespace {

std::string real(double x) {
  return fmt::format("{}", x);
}
std::string yes_no(bool b) {
  return b ? "1" : "0";
}
std::string_view norm_name(NlgsNorm n) {
  switch (n) {
    case NlgsNorm::quad:
      return "Quad";
    case NlgsNorm::quad_normal:
      return "QuaN";
    case NlgsNorm::maxm:
      return "Maxm";
    case NlgsNorm::qm16:
      return "QM/16";
  }
  return "Quad";
}

using O = const RunOptions&;
using N = std::optional<double>;

// One row per parameter; COMMAND.DAT keywords and chipy calls as LMGC90 spells them.
constexpr RunParameter kParameters[] = {
    {"dt", "--dt", "TIME STEP", "TimeEvolution_SetTimeStep", 0, "", [](O o) { return real(o.dt); },
     [](O o) -> N { return o.dt; }},
    {"theta", "--theta", "THETA", "Integrator_InitTheta", 0, "", [](O o) { return real(o.theta); },
     [](O o) -> N { return o.theta; }},
    {"nb_steps", "--steps", "INCREMENT STEP", "IncrementStep", -1, "",
     [](O o) { return std::to_string(o.steps); }, [](O o) -> N { return static_cast<double>(o.steps); }},
    {"solver_type", "--solver", "EX PREP NLGS", "ExSolver", 0, "",
     [](O o) {
       return std::string(o.nlgs.storage == NlgsStorage::stored_delassus_loops ? "Stored_Delassus_Loops"
                                                                               : "Exchange_Local_Global");
     },
     [](O) -> N { return std::nullopt; }},
    {"norm", "--norm", "NLGS CHECK TYPE", "ExSolver", 1, "",
     [](O o) { return std::string(norm_name(o.nlgs.norm)); }, [](O) -> N { return std::nullopt; }},
    {"tol", "--tol", "NLGS CHECK TYPE", "ExSolver", 2, "", [](O o) { return real(o.nlgs.tolerance); },
     [](O o) -> N { return o.nlgs.tolerance; }},
    {"relax", "--relax", "NLGS CHECK TYPE", "ExSolver", 3, "", [](O o) { return real(o.nlgs.relax); },
     [](O o) -> N { return o.nlgs.relax; }},
    {"gs_it1", "--gs-it1", "REPETE (after EX ITER NLGS)", "ExSolver", 4, "",
     [](O o) { return std::to_string(o.nlgs.gs_it1); }, [](O o) -> N { return o.nlgs.gs_it1; }},
    {"gs_it2", "--gs-it2", "REPETE (the checks' loop)", "ExSolver", 5, "",
     [](O o) { return std::to_string(o.nlgs.gs_it2); }, [](O o) -> N { return o.nlgs.gs_it2; }},
    {"quick_scramble", "--quick-scramble", "quickSCRAMBLE", "nlgs_SetWithQuickScramble", -1, "",
     [](O o) { return yes_no(o.nlgs.quick_scramble); }, [](O o) -> N { return o.nlgs.quick_scramble; }},
    {"scramble_seed", "--scramble-seed", "", "", -1, "",
     [](O o) { return std::to_string(o.nlgs.scramble_seed); }, [](O) -> N { return std::nullopt; }},
    {"diagonal_resolution", "--diagonal-resolution", "DIAGONAL RESOLUTION", "nlgs_3D_DiagonalResolution", -1,
     "", [](O o) { return yes_no(o.nlgs.diagonal_resolution); },
     [](O o) -> N { return o.nlgs.diagonal_resolution; }},
    {"residual_target", "--residual-target", "", "", -1, "", [](O o) { return real(o.nlgs.residual_target); },
     [](O) -> N { return std::nullopt; }},
    {"freq_write", "--write-every", "WRITE OUT DOF STEP", "WriteOut", 0, "nsteps",
     [](O o) { return std::to_string(o.write_every); },
     [](O o) -> N { return static_cast<double>(o.write_every); }, 1.0},
    {"freq_display", "--display-every", "WRITE OUTPUT GMV STEP", "WriteDisplayFiles", 0, "freq",
     [](O o) { return std::to_string(o.display_every); },
     [](O o) -> N { return static_cast<double>(o.display_every); }, 1.0},
    {"ymin_boundary", "--ymin-boundary", "INIT YMIN BOUNDARY", "RBDY2_SetYminBoundary", 0, "",
     [](O o) { return real(o.y_min); }, [](O o) -> N { return o.y_min; }},
    {"ymax_boundary", "--ymax-boundary", "INIT YMAX BOUNDARY", "RBDY2_SetYmaxBoundary", 0, "",
     [](O o) { return real(o.y_max); }, [](O o) -> N { return o.y_max; }},
    {"xmin_boundary", "--xmin-boundary", "INIT XMIN BOUNDARY", "RBDY2_SetXminBoundary", 0, "",
     [](O o) { return real(o.x_min); }, [](O o) -> N { return o.x_min; }},
    {"xmax_boundary", "--xmax-boundary", "INIT XMAX BOUNDARY", "RBDY2_SetXmaxBoundary", 0, "",
     [](O o) { return real(o.x_max); }, [](O o) -> N { return o.x_max; }},
    {"xperiod", "--xperiod", "PERIODIC CONDITION, XPERIODIC CONDITION", "SetPeriodicCondition", 0, "xperiod",
     [](O o) { return real(o.x_period); }, [](O o) -> N { return o.x_period; }},
    {"yperiod", "--yperiod", "YPERIODIC CONDITION", "SetPeriodicCondition", 1, "yperiod",
     [](O o) { return real(o.y_period); }, [](O o) -> N { return o.y_period; }},
    {"new_rotation_scheme", "--new-rotation-scheme", "NEW ROTATION SCHEME", "RBDY3_NewRotationScheme", -1, "",
     [](O o) { return yes_no(o.new_rotation_scheme); }, [](O o) -> N { return o.new_rotation_scheme; }},
    {"cundall_iterations", "--cundall-iterations", "CUNDALL ITERATION", "PRPRx_UseCpCundallDetection", 0,
     "nb_iter", [](O o) { return std::to_string(o.cundall_iterations); },
     [](O o) -> N { return o.cundall_iterations; }},
    {"zero_initial_velocity", "", "FATAL DAMPING, INI V DOF NULL (before the first step)", "", -1, "",
     [](O o) { return yes_no(o.zero_initial_velocity); }, [](O) -> N { return std::nullopt; }},
    {"source_point", "--source-point", "INIT SOURCE POINT, FD INIT SOURCE POINT",
     "RBDY3_SetSourcePointWithIni", -1, "",
     [](O o) {
       return o.source_first > 0
                  ? fmt::format("{},{},{},{},{}{}", o.source_first, real(o.source_radius),
                                real(o.source_point[0]), real(o.source_point[1]), real(o.source_point[2]),
                                o.source_point_absolute ? "" : " relative")
                  : std::string("none");
     },
     [](O) -> N { return std::nullopt; }},
    {"ptpt3_network", "--ptpt3-network", "", "PTPT3_LoadNetwork", -1, "",
     [](O o) { return yes_no(o.ptpt3_network); }, [](O o) -> N { return o.ptpt3_network; }},
    {"ptpt3_current_nonuc0", "--ptpt3-current-nonuc0", "", "PTPT3_UseCurrentNonuc0", 0, "",
     [](O o) { return yes_no(o.ptpt3_current_nonuc0); }, [](O o) -> N { return o.ptpt3_current_nonuc0; }},
};

std::string trimmed(std::string s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
  while (!s.empty() && s.front() == ' ') s.erase(s.begin());
  return s;
}

bool same_number(double a, double b) {
  return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

std::string literal_text(const grammar::ScriptValue& v) {
  if (v.text) return fmt::format("'{}'", *v.text);
  return fmt::format("{}", *v.number);
}

}  // namespace

std::string_view source_name(ParameterSource source) {
  switch (source) {
    case ParameterSource::default_value:
      return "default";
    case ParameterSource::command_dat:
      return "COMMAND.DAT";
    case ParameterSource::flag:
      return "flag";
  }
  return "default";
}

std::span<const RunParameter> run_parameters() {
  return kParameters;
}

const RunParameter* find_run_parameter(std::string_view name) {
  for (const RunParameter& p : kParameters)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<ScriptDifference> script_differences(const RunOptions& options,
                                                 const grammar::CommandScript& script) {
  std::vector<ScriptDifference> out;
  auto differ = [&](const RunParameter& p, std::string script_value, std::uint32_t line,
                    std::uint16_t column) {
    out.push_back({&p, p.text(options), std::move(script_value), line, column});
  };
  for (const RunParameter& p : kParameters) {
    if (p.chipy.empty()) continue;
    if (p.name == "nb_steps") {
      const grammar::ScriptLoop* loop = script.step_loop();
      if (loop && loop->count && *loop->count != options.steps)
        differ(p, std::to_string(*loop->count), loop->line, 1);
      continue;
    }
    // 2D and 3D spellings of the NLGS calls.
    std::vector<const grammar::ScriptCall*> calls = script.calls_to(p.chipy);
    if (p.chipy == "nlgs_SetWithQuickScramble")
      for (const grammar::ScriptCall* c : script.calls_to("nlgs_3D_SetWithQuickScramble")) calls.push_back(c);
    if (p.chipy == "WriteOut")
      for (const grammar::ScriptCall* c : script.calls_to("WriteOutDof")) calls.push_back(c);
    const auto number = p.number(options);
    if (p.argument < 0 && p.name != "source_point") {
      // Set by the call's presence: on when the script calls it (the last call's line is shown).
      const bool called = !calls.empty();
      if (number && called != (*number != 0.0))
        differ(p, called ? "called" : "not called", called ? calls.back()->line : 0,
               called ? calls.back()->column : 0);
      continue;
    }
    if (calls.empty()) continue;
    const grammar::ScriptCall& call = *calls.back();
    if (p.name == "source_point") {
      std::string values;
      bool resolved = true;
      for (std::size_t k = 0; k < 5; ++k) {
        const grammar::ScriptArgument* a = grammar::script_argument(call, k, "");
        if (!a || !a->value.number)
          resolved = false;
        else
          values += fmt::format("{}{}", k ? "," : "", *a->value.number);
      }
      if (resolved && values != p.text(options)) differ(p, values, call.line, call.column);
      continue;
    }
    const grammar::ScriptArgument* a =
        grammar::script_argument(call, static_cast<std::size_t>(p.argument), p.keyword);
    grammar::ScriptValue value;
    if (a) {
      value = a->value;
    } else if (p.call_default) {
      value.number = *p.call_default;
    }
    if (!value.resolved()) continue;
    bool same = true;
    if (number && value.number) {
      same = same_number(*number, *value.number);
    } else if (value.text) {
      // Strings: the NLGS storage and norm, compared as LMGC90 reads them (trailing blanks dropped).
      const std::string run = p.text(options), given = trimmed(*value.text);
      same = run == given || (p.name == "norm" && given == "MaxM" && run == "Quad");
    }
    if (!same) differ(p, literal_text(value), call.line, call.column);
  }
  return out;
}

std::string run_parameters_csv(const RunOptions& options, const ParameterSources& sources) {
  std::string csv = "name,value,source,flag,command_dat,chipy\n";
  for (const RunParameter& p : kParameters) {
    const auto it = sources.find(p.name);
    const ParameterSource source = it == sources.end() ? ParameterSource::default_value : it->second;
    csv += fmt::format("{},\"{}\",{},{},\"{}\",{}\n", p.name, p.text(options), source_name(source), p.flag,
                       p.command_dat, p.chipy);
  }
  return csv;
}

}  // namespace lmgc::solver
