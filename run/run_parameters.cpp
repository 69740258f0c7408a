#include "run/run_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "grammar/command/expand.hpp"

namespace lmgc::run {
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
using V = const grammar::ScriptValue&;
using C = const grammar::CommandRunParameters&;
grammar::ScriptValue number(double x) {
  return {x, std::nullopt};
}
grammar::ScriptValue text(const std::string& x) {
  return {std::nullopt, x};
}

// The script's literal as a run value (the checks COMMAND.DAT's values get, L4010).
bool positive(V v, double& out) {
  if (!v.number || !std::isfinite(*v.number) || *v.number <= 0.0) return false;
  out = *v.number;
  return true;
}
bool finite(V v, double& out) {
  if (!v.number || !std::isfinite(*v.number)) return false;
  out = *v.number;
  return true;
}
template <class Integer>
bool integer_at_least(V v, long least, Integer& out) {
  if (!v.number || !std::isfinite(*v.number) || *v.number != std::floor(*v.number) || *v.number < least ||
      *v.number > static_cast<double>(std::numeric_limits<Integer>::max() / 2))
    return false;
  out = static_cast<Integer>(*v.number);
  return true;
}
bool switch_on(V v, bool& out) {
  if (!v.number) return false;
  out = *v.number != 0.0;
  return true;
}

// One row per parameter; COMMAND.DAT keywords and chipy calls as LMGC90 spells them.
constexpr RunParameter kParameters[] = {
    {"dt", "--dt", "TIME STEP", "TimeEvolution_SetTimeStep", 0, "", [](O o) { return real(o.dt); },
     [](O o) -> N { return o.dt; }, [](RunOptions& o, V v) { return positive(v, o.dt); }, std::nullopt,
     [](RunOptions& to, O from) { to.dt = from.dt; }, [](C c) { return number(c.dt); }, "time step [s]"},
    {"theta", "--theta", "THETA", "Integrator_InitTheta", 0, "", [](O o) { return real(o.theta); },
     [](O o) -> N { return o.theta; },
     [](RunOptions& o, V v) {
       return v.number && *v.number >= 0.5 && *v.number <= 1.0 && finite(v, o.theta);
     },
     std::nullopt, [](RunOptions& to, O from) { to.theta = from.theta; }, [](C c) { return number(c.theta); },
     "theta of the Moreau-Jean scheme, in [0.5, 1]"},
    {"nb_steps", "--steps", "INCREMENT STEP", "IncrementStep", -1, "",
     [](O o) { return std::to_string(o.steps); }, [](O o) -> N { return static_cast<double>(o.steps); },
     [](RunOptions& o, V v) { return integer_at_least(v, 0, o.steps); }, std::nullopt,
     [](RunOptions& to, O from) { to.steps = from.steps; },
     [](C c) { return number(static_cast<double>(c.steps)); }, "number of steps"},
    {"solver_type", "--solver", "EX PREP NLGS", "ExSolver", 0, "",
     [](O o) {
       return std::string(o.nlgs.storage == NlgsStorage::stored_delassus_loops ? "Stored_Delassus_Loops"
                                                                               : "Exchange_Local_Global");
     },
     [](O) -> N { return std::nullopt; },
     [](RunOptions& o, V v) { return v.text && parse_storage(*v.text, o.nlgs.storage); }, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.storage = from.nlgs.storage; }, [](C c) { return text(c.storage); },
     "NLGS storage: Stored_Delassus_Loops or Exchange_Local_Global; LMGC90's two storages give the same "
     "iterates, and lmgc-solve runs both the same way (every command.py names one)"},
    {"norm", "--norm", "NLGS CHECK TYPE", "ExSolver", 1, "",
     [](O o) { return std::string(norm_name(o.nlgs.norm)); }, [](O) -> N { return std::nullopt; },
     [](RunOptions& o, V v) { return v.text && parse_norm(*v.text, o.nlgs.norm); }, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.norm = from.nlgs.norm; }, [](C c) { return text(c.norm); },
     "NLGS convergence norm: Quad, QuaN, Maxm or QM/16"},
    {"tol", "--tol", "NLGS CHECK TYPE", "ExSolver", 2, "", [](O o) { return real(o.nlgs.tolerance); },
     [](O o) -> N { return o.nlgs.tolerance; },
     [](RunOptions& o, V v) { return positive(v, o.nlgs.tolerance); }, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.tolerance = from.nlgs.tolerance; },
     [](C c) { return number(c.tolerance); }, "NLGS tolerance of the norm"},
    {"relax", "--relax", "NLGS CHECK TYPE", "ExSolver", 3, "", [](O o) { return real(o.nlgs.relax); },
     [](O o) -> N { return o.nlgs.relax; },
     [](RunOptions& o, V v) { return v.number && *v.number <= 2.0 && positive(v, o.nlgs.relax); },
     std::nullopt, [](RunOptions& to, O from) { to.nlgs.relax = from.nlgs.relax; },
     [](C c) { return number(c.relax); }, "NLGS relaxation, in (0, 2]"},
    {"gs_it1", "--gs-it1", "REPETE (after EX ITER NLGS)", "ExSolver", 4, "",
     [](O o) { return std::to_string(o.nlgs.gs_it1); }, [](O o) -> N { return o.nlgs.gs_it1; },
     [](RunOptions& o, V v) { return integer_at_least(v, 1, o.nlgs.gs_it1); }, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.gs_it1 = from.nlgs.gs_it1; }, [](C c) { return number(c.gs_it1); },
     "NLGS sweeps between two convergence checks"},
    {"gs_it2", "--gs-it2", "REPETE (the checks' loop)", "ExSolver", 5, "",
     [](O o) { return std::to_string(o.nlgs.gs_it2); }, [](O o) -> N { return o.nlgs.gs_it2; },
     [](RunOptions& o, V v) { return integer_at_least(v, 1, o.nlgs.gs_it2); }, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.gs_it2 = from.nlgs.gs_it2; }, [](C c) { return number(c.gs_it2); },
     "maximum number of convergence checks"},
    {"quick_scramble", "--quick-scramble", "quickSCRAMBLE", "nlgs_SetWithQuickScramble", -1, "",
     [](O o) { return yes_no(o.nlgs.quick_scramble); }, [](O o) -> N { return o.nlgs.quick_scramble; },
     [](RunOptions& o, V v) { return switch_on(v, o.nlgs.quick_scramble); }, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.quick_scramble = from.nlgs.quick_scramble; },
     [](C c) { return number(c.quick_scramble); },
     "scramble the contact order before each block of sweeps as LMGC90 does"},
    {"scramble_seed", "--scramble-seed", "", "", -1, "",
     [](O o) { return std::to_string(o.nlgs.scramble_seed); }, [](O) -> N { return std::nullopt; }, nullptr,
     std::nullopt, [](RunOptions& to, O from) { to.nlgs.scramble_seed = from.nlgs.scramble_seed; }, nullptr,
     "seed of the quick scramble's random lists (LMGC90's differ from run to run)"},
    {"diagonal_resolution", "--diagonal-resolution", "DIAGONAL RESOLUTION", "nlgs_3D_DiagonalResolution", -1,
     "", [](O o) { return yes_no(o.nlgs.diagonal_resolution); },
     [](O o) -> N { return o.nlgs.diagonal_resolution; },
     [](RunOptions& o, V v) { return switch_on(v, o.nlgs.diagonal_resolution); }, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.diagonal_resolution = from.nlgs.diagonal_resolution; },
     [](C c) { return number(c.diagonal_resolution); },
     "3D: solve each contact with the diagonal of its Delassus block, then project on the Coulomb cone"},
    {"residual_target", "--residual-target", "", "", -1, "", [](O o) { return real(o.nlgs.residual_target); },
     [](O) -> N { return std::nullopt; }, nullptr, std::nullopt,
     [](RunOptions& to, O from) { to.nlgs.residual_target = from.nlgs.residual_target; }, nullptr,
     "also stop a step when the natural-map residual / |q| is below this (0 = off)"},
    {"freq_write", "--write-every", "WRITE OUT DOF STEP", "WriteOut", 0, "nsteps",
     [](O o) { return std::to_string(o.write_every); },
     [](O o) -> N { return static_cast<double>(o.write_every); },
     [](RunOptions& o, V v) { return integer_at_least(v, 1, o.write_every); }, 1.0,
     [](RunOptions& to, O from) { to.write_every = from.write_every; },
     [](C c) { return number(static_cast<double>(c.write_every)); },
     "write DOF/Vloc_Rloc .OUT.n every n steps (0 = never)"},
    {"freq_display", "--display-every", "WRITE OUTPUT GMV STEP", "WriteDisplayFiles", 0, "freq",
     [](O o) { return std::to_string(o.display_every); },
     [](O o) -> N { return static_cast<double>(o.display_every); },
     [](RunOptions& o, V v) { return integer_at_least(v, 1, o.display_every); }, 1.0,
     [](RunOptions& to, O from) { to.display_every = from.display_every; },
     [](C c) { return number(static_cast<double>(c.display_every)); },
     "write DISPLAY files every n steps (0 = never)"},
    {"ymin_boundary", "--ymin-boundary", "INIT YMIN BOUNDARY", "RBDY2_SetYminBoundary", 0, "",
     [](O o) { return real(o.y_min); }, [](O o) -> N { return o.y_min; },
     [](RunOptions& o, V v) { return finite(v, o.y_min); }, std::nullopt,
     [](RunOptions& to, O from) { to.y_min = from.y_min; }, [](C c) { return number(c.y_min); },
     "2D: bodies whose centre goes below this become invisible"},
    {"ymax_boundary", "--ymax-boundary", "INIT YMAX BOUNDARY", "RBDY2_SetYmaxBoundary", 0, "",
     [](O o) { return real(o.y_max); }, [](O o) -> N { return o.y_max; },
     [](RunOptions& o, V v) { return finite(v, o.y_max); }, std::nullopt,
     [](RunOptions& to, O from) { to.y_max = from.y_max; }, [](C c) { return number(c.y_max); },
     "2D: bodies whose centre goes above this become invisible"},
    {"xmin_boundary", "--xmin-boundary", "INIT XMIN BOUNDARY", "RBDY2_SetXminBoundary", 0, "",
     [](O o) { return real(o.x_min); }, [](O o) -> N { return o.x_min; },
     [](RunOptions& o, V v) { return finite(v, o.x_min); }, std::nullopt,
     [](RunOptions& to, O from) { to.x_min = from.x_min; }, [](C c) { return number(c.x_min); },
     "2D: bodies whose centre goes left of this become invisible"},
    {"xmax_boundary", "--xmax-boundary", "INIT XMAX BOUNDARY", "RBDY2_SetXmaxBoundary", 0, "",
     [](O o) { return real(o.x_max); }, [](O o) -> N { return o.x_max; },
     [](RunOptions& o, V v) { return finite(v, o.x_max); }, std::nullopt,
     [](RunOptions& to, O from) { to.x_max = from.x_max; }, [](C c) { return number(c.x_max); },
     "2D: bodies whose centre goes right of this become invisible"},
    {"xperiod", "--xperiod", "PERIODIC CONDITION, XPERIODIC CONDITION", "SetPeriodicCondition", 0, "xperiod",
     [](O o) { return real(o.x_period); }, [](O o) -> N { return o.x_period; },
     [](RunOptions& o, V v) { return positive(v, o.x_period); }, std::nullopt,
     [](RunOptions& to, O from) { to.x_period = from.x_period; }, [](C c) { return number(c.x_period); },
     "periodic in x with this period"},
    {"yperiod", "--yperiod", "YPERIODIC CONDITION", "SetPeriodicCondition", 1, "yperiod",
     [](O o) { return real(o.y_period); }, [](O o) -> N { return o.y_period; },
     [](RunOptions& o, V v) { return positive(v, o.y_period); }, std::nullopt,
     [](RunOptions& to, O from) { to.y_period = from.y_period; }, [](C c) { return number(c.y_period); },
     "3D: periodic in y with this period"},
    {"new_rotation_scheme", "--new-rotation-scheme", "NEW ROTATION SCHEME", "RBDY3_NewRotationScheme", -1, "",
     [](O o) { return yes_no(o.new_rotation_scheme); }, [](O o) -> N { return o.new_rotation_scheme; },
     [](RunOptions& o, V v) { return switch_on(v, o.new_rotation_scheme); }, std::nullopt,
     [](RunOptions& to, O from) { to.new_rotation_scheme = from.new_rotation_scheme; },
     [](C c) { return number(c.new_rotation_scheme); },
     "RBDY3: update the principal frame by the Cayley map"},
    {"cundall_iterations", "--cundall-iterations", "CUNDALL ITERATION", "PRPRx_UseCpCundallDetection", 0,
     "nb_iter", [](O o) { return std::to_string(o.cundall_iterations); },
     [](O o) -> N { return o.cundall_iterations; },
     [](RunOptions& o, V v) { return integer_at_least(v, 1, o.cundall_iterations); }, std::nullopt,
     [](RunOptions& to, O from) { to.cundall_iterations = from.cundall_iterations; },
     [](C c) { return number(static_cast<double>(c.cundall_iterations)); },
     "3D: cap of Cundall's common-plane search between polyhedra"},
    {"zero_initial_velocity", "", "FATAL DAMPING, INI V DOF NULL (before the first step)", "", -1, "",
     [](O o) { return yes_no(o.zero_initial_velocity); }, [](O) -> N { return std::nullopt; },
     [](RunOptions& o, V v) { return switch_on(v, o.zero_initial_velocity); }, std::nullopt,
     [](RunOptions& to, O from) { to.zero_initial_velocity = from.zero_initial_velocity; },
     [](C c) { return number(c.zero_initial_velocity); }, "every body starts at rest"},
    {"source_point", "--source-point", "INIT SOURCE POINT, FD INIT SOURCE POINT",
     "RBDY3_SetSourcePointWithIni", -1, "",
     [](O o) {
       return o.source_first > 0
                  ? fmt::format("{},{},{},{},{}{}", o.source_first, real(o.source_radius),
                                real(o.source_point[0]), real(o.source_point[1]), real(o.source_point[2]),
                                o.source_point_absolute ? "" : " relative")
                  : std::string("none");
     },
     [](O) -> N { return std::nullopt; }, nullptr, std::nullopt,
     [](RunOptions& to, O from) {
       to.source_first = from.source_first;
       to.source_radius = from.source_radius;
       to.source_point[0] = from.source_point[0];
       to.source_point[1] = from.source_point[1];
       to.source_point[2] = from.source_point[2];
       to.source_point_absolute = from.source_point_absolute;
     },
     nullptr,
     "3D: FIRST RADIUS X Y Z: bodies after FIRST enter one by one at (X, Y, Z), each when the previous one "
     "is farther than RADIUS from it"},
    {"ptpt3_network", "--ptpt3-network", "", "PTPT3_LoadNetwork", -1, "",
     [](O o) { return yes_no(o.ptpt3_network); }, [](O o) -> N { return o.ptpt3_network; },
     [](RunOptions& o, V v) { return switch_on(v, o.ptpt3_network); }, std::nullopt,
     [](RunOptions& to, O from) { to.ptpt3_network = from.ptpt3_network; }, nullptr,
     "3D: link PT3Dx points as DATBOX/PTPT3_NETWORK.DAT lists instead of by distance"},
    {"ptpt3_current_nonuc0", "--ptpt3-current-nonuc0", "", "PTPT3_UseCurrentNonuc0", 0, "",
     [](O o) { return yes_no(o.ptpt3_current_nonuc0); }, [](O o) -> N { return o.ptpt3_current_nonuc0; },
     [](RunOptions& o, V v) { return switch_on(v, o.ptpt3_current_nonuc0); }, std::nullopt,
     [](RunOptions& to, O from) { to.ptpt3_current_nonuc0 = from.ptpt3_current_nonuc0; }, nullptr,
     "3D: PTPT3 reference lengths from the network file's nonuc0, or for detected links from the positions "
     "at the start"},
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
    case ParameterSource::command_py:
      return "command.py";
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

std::vector<ScriptSetting> script_settings(const grammar::CommandScript& script) {
  std::vector<ScriptSetting> out;
  for (const RunParameter& p : kParameters) {
    if (p.chipy.empty()) continue;
    ScriptSetting setting;
    setting.parameter = &p;
    if (p.name == "nb_steps") {
      const grammar::ScriptLoop* loop = script.step_loop();
      if (!loop) continue;
      if (loop->count) setting.value.number = static_cast<double>(*loop->count);
      setting.expression = loop->header;
      setting.line = loop->line;
      setting.column = 1;
      out.push_back(std::move(setting));
      continue;
    }
    // The 2D and 3D spellings of a call, and its variants; the last call in the file counts.
    std::vector<const grammar::ScriptCall*> calls = script.calls_to(p.chipy);
    const auto also = [&](std::string_view name) {
      for (const grammar::ScriptCall* c : script.calls_to(name)) calls.push_back(c);
    };
    if (p.chipy == "nlgs_SetWithQuickScramble") also("nlgs_3D_SetWithQuickScramble");
    if (p.chipy == "WriteOut") also("WriteOutDof");
    if (p.name == "source_point") also("RBDY3_SetSourcePoint");
    std::stable_sort(
        calls.begin(), calls.end(),
        [](const grammar::ScriptCall* a, const grammar::ScriptCall* b) { return a->line < b->line; });
    const grammar::ScriptCall* call = calls.empty() ? nullptr : calls.back();
    if (call) {
      setting.line = call->line;
      setting.column = call->column;
      setting.expression = call->name + "(...)";
    }
    if (p.name == "source_point") {
      if (!call) continue;
      for (std::size_t k = 0; k < 5; ++k) {
        const grammar::ScriptArgument* a = grammar::script_argument(*call, k, "");
        setting.source_point.push_back(a ? a->value : grammar::ScriptValue{});
      }
      setting.value = setting.source_point[0];
      setting.source_point_relative = call->name == "RBDY3_SetSourcePoint";
      out.push_back(std::move(setting));
      continue;
    }
    if (p.argument < 0) {
      // Set by the call's presence.
      setting.value.number = call ? 1.0 : 0.0;
      if (!call) setting.expression = "not called";
      out.push_back(std::move(setting));
      continue;
    }
    if (!call) continue;
    const grammar::ScriptArgument* a =
        grammar::script_argument(*call, static_cast<std::size_t>(p.argument), p.keyword);
    if (a) {
      setting.value = a->value;
      setting.expression = a->expression;
    } else if (p.call_default) {
      setting.value.number = *p.call_default;
    } else {
      continue;  // the call does not set this one (SetPeriodicCondition(xperiod) in 2D)
    }
    out.push_back(std::move(setting));
  }
  return out;
}

std::vector<ScriptDifference> script_differences(const RunOptions& options,
                                                 const grammar::CommandScript& script) {
  std::vector<ScriptDifference> out;
  for (const ScriptSetting& s : script_settings(script)) {
    const RunParameter& p = *s.parameter;
    const auto differ = [&](std::string script_value) {
      out.push_back({&p, p.text(options), std::move(script_value), s.line, s.column});
    };
    if (p.name == "source_point") {
      std::string values;
      bool resolved = true;
      for (std::size_t k = 0; k < s.source_point.size(); ++k) {
        if (!s.source_point[k].number)
          resolved = false;
        else
          values += fmt::format("{}{}", k ? "," : "", *s.source_point[k].number);
      }
      if (s.source_point_relative) values += " relative";
      if (resolved && values != p.text(options)) differ(values);
      continue;
    }
    if (!s.value.resolved()) continue;
    const auto number = p.number(options);
    if (p.argument < 0 && p.name != "nb_steps") {
      const bool called = *s.value.number != 0.0;
      if (number && called != (*number != 0.0)) differ(called ? "called" : "not called");
      continue;
    }
    bool same = true;
    if (number && s.value.number) {
      same = same_number(*number, *s.value.number);
    } else if (s.value.text) {
      // Strings: the NLGS storage and norm, compared as LMGC90 reads them (trailing blanks dropped).
      const std::string run = p.text(options), given = trimmed(*s.value.text);
      same = run == given || (p.name == "norm" && given == "MaxM" && run == "Quad");
    }
    if (!same) differ(p.name == "nb_steps" ? fmt::format("{}", *s.value.number) : literal_text(s.value));
  }
  return out;
}

void apply_script_parameters(const grammar::CommandScript& script, bool three_d, RunOptions& options,
                             ParameterSources& sources, grammar::DiagnosticSink& sink) {
  for (const ScriptSetting& s : script_settings(script)) {
    const RunParameter& p = *s.parameter;
    const grammar::Location where{
        script.path, grammar::SourceSpan{s.line, s.column, static_cast<std::uint16_t>(s.column + 1)}};
    const std::string flag = p.flag.empty() ? std::string() : " (" + std::string(p.flag) + ")";
    if (p.name == "source_point") {
      const auto& v = s.source_point;
      const bool resolved =
          std::all_of(v.begin(), v.end(), [](const auto& x) { return x.number.has_value(); });
      if (!resolved) {
        sink.report("L4013", where,
                    "command.py computes the source point; lmgc-solve runs " + p.text(options) + flag);
        continue;
      }
      if (*v[0].number < 1.0 || *v[0].number != std::floor(*v[0].number) || !(*v[1].number > 0.0) ||
          !std::isfinite(*v[2].number) || !std::isfinite(*v[3].number) || !std::isfinite(*v[4].number)) {
        sink.report(
            "L4010", where,
            "the source point needs a first body of at least 1, a positive radius and a finite point");
        continue;
      }
      options.source_first = static_cast<long>(*v[0].number);
      options.source_radius = *v[1].number;
      for (std::size_t d = 0; d < 3; ++d) options.source_point[d] = *v[d + 2].number;
      options.source_point_absolute = !s.source_point_relative;
      sources[std::string(p.name)] = ParameterSource::command_py;
      continue;
    }
    if (!p.assign) continue;
    if (!s.value.resolved()) {
      sink.report("L4013", where,
                  "command.py computes " + std::string(p.name) + " (" + s.expression + "); lmgc-solve runs " +
                      p.text(options) + (sources.count(p.name) ? "" : " (its default)") + flag);
      continue;
    }
    if (!p.assign(options, s.value)) {
      // LMGC90's 3D NLGS keeps 'Quad ' for a norm it does not know (mod_nlgs_3D set_nlgs_parameter has
      // no default branch): the same run, without a word, as LMGC90's.
      if (p.name == "norm" && three_d && s.value.text) {
        options.nlgs.norm = NlgsNorm::quad;
        sources[std::string(p.name)] = ParameterSource::command_py;
        continue;
      }
      sink.report("L4010", where,
                  std::string(p.name) + " = " + literal_text(s.value) + " is not a value a run can take");
      continue;
    }
    sources[std::string(p.name)] = ParameterSource::command_py;
  }
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

void apply_command_parameters(const grammar::CommandFile& command, std::string_view path, bool three_d,
                              RunOptions& options, grammar::DiagnosticSink& sink, ParameterSources* sources) {
  // The file's own faults (an APPELLE without its label, ...) are lmgc-check's to report.
  grammar::DiagnosticSink expansion(static_cast<std::size_t>(-1));
  apply_command_parameters(grammar::command_run_parameters(command, expansion), path, three_d, options, sink,
                           sources);
}

void apply_command_parameters(const grammar::CommandRunParameters& p, std::string_view path, bool three_d,
                              RunOptions& options, grammar::DiagnosticSink& sink, ParameterSources* sources) {
  const auto line_of = [&](std::string_view name) {
    const auto it = p.lines.find(name);
    return it == p.lines.end() ? 0u : it->second;
  };
  const auto where = [&](std::uint32_t line) {
    return grammar::Location{std::string(path), grammar::SourceSpan{line, 1, 2}};
  };
  for (const RunParameter& parameter : kParameters) {
    const std::uint32_t line = line_of(parameter.name);
    if (line == 0) continue;
    if (parameter.name == "source_point") {
      if (p.source_first < 1 || !(p.source_radius > 0.0) || !std::isfinite(p.source_radius) ||
          !std::isfinite(p.source_point[0]) || !std::isfinite(p.source_point[1]) ||
          !std::isfinite(p.source_point[2])) {
        sink.report(
            "L4010", where(line),
            "the source point needs a first body of at least 1, a positive radius and a finite point");
        continue;
      }
      options.source_first = p.source_first;
      options.source_radius = p.source_radius;
      for (int d = 0; d < 3; ++d) options.source_point[d] = p.source_point[d];
      options.source_point_absolute = p.source_point_absolute;
    } else {
      if (!parameter.from_command_dat || !parameter.assign) continue;
      const grammar::ScriptValue value = parameter.from_command_dat(p);
      if (!parameter.assign(options, value)) {
        // LMGC90's 3D NLGS keeps 'Quad ' for a norm it does not know, as in a script (above).
        if (parameter.name == "norm" && three_d) {
          options.nlgs.norm = NlgsNorm::quad;
        } else if (parameter.name == "solver_type") {
          // CHIC reads the storage from the line after EX PREP NLGS, whatever it holds; both storages
          // give the same iterates, so another word changes nothing (lmgc-check notes it, L4006).
          continue;
        } else {
          sink.report("L4010", where(line),
                      std::string(parameter.command_dat) + " gives " + std::string(parameter.name) + " = " +
                          literal_text(value) + ", not a value a run can take");
          continue;
        }
      }
    }
    if (sources) (*sources)[std::string(parameter.name)] = ParameterSource::command_dat;
  }
}

const RunParameter* find_run_parameter_by_flag(std::string_view flag) {
  for (const RunParameter& p : kParameters)
    if (p.flag == flag) return &p;
  return nullptr;
}

std::string flag_help(const RunParameter& p) {
  std::string help(p.help);
  std::vector<std::string> where;
  if (!p.chipy.empty()) where.push_back("command.py: " + std::string(p.chipy));
  if (!p.command_dat.empty()) where.push_back("COMMAND.DAT: " + std::string(p.command_dat));
  where.push_back("default " + p.text(RunOptions{}));
  help += " [";
  for (std::size_t k = 0; k < where.size(); ++k) help += (k ? "; " : "") + where[k];
  return help + "]";
}

std::string run_parameters_markdown() {
  std::string out =
      "| parameter | flag | command.py | COMMAND.DAT | default | meaning |\n| --- | --- | --- | --- | --- | "
      "--- |\n";
  const auto cell = [](std::string_view text) {
    return text.empty() ? std::string("—") : "`" + std::string(text) + "`";
  };
  for (const RunParameter& p : kParameters) {
    std::string meaning(p.help);
    for (std::size_t at = meaning.find('|'); at != std::string::npos; at = meaning.find('|', at + 2))
      meaning.replace(at, 1, "\\|");
    out += "| `" + std::string(p.name) + "` | " + cell(p.flag) + " | " + cell(p.chipy) + " | " +
           (p.command_dat.empty() ? std::string("—") : std::string(p.command_dat)) + " | " +
           p.text(RunOptions{}) + " | " + meaning + " |\n";
  }
  return out;
}

}  // namespace lmgc::run
