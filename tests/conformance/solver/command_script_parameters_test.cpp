// The run parameters lmgc-solve takes from each rigid example's command.py (read, not run) are the
// literals LMGC90's reference run used, as reference_lmgc90/RUN.md records them, and none of them
// is left unknown (L4013) or refused (L4010).
#include <gtest/gtest.h>

#include <cstdlib>

#include "case_folder/case_files.hpp"
#include "run/run_parameters.hpp"
#include "solver/driver/case_input.hpp"
#include "tests/support/lmgc90_reference_runs.hpp"

namespace lmgc::test {
namespace {

TEST(CommandScriptParameters, EveryRigidExampleRunsWithItsScriptsLiterals) {
  LMGC_REQUIRE_SHARED();
  int compared = 0;
  for (const auto& example : example_cases()) {
    const std::string name = case_name(example);
    if (name.rfind("RIGID_", 0) != 0 || !std::filesystem::exists(example / "command.py")) continue;
    const auto expected = script_parameters(example);
    if (expected.empty()) continue;
    grammar::DiagnosticSink sink(static_cast<std::size_t>(-1));
    const auto files = case_folder::load_case(example, sink);
    ASSERT_TRUE(files && files->command_script) << name;
    run::RunOptions options;
    run::ParameterSources sources;
    run::apply_script_parameters(*files->command_script, solver::is_rigid_3d_case(*files), options, sources,
                                 sink);
    for (const auto& d : sink.items())
      EXPECT_TRUE(d.code != "L4013" && d.code != "L4010") << name << ": " << d.code << " " << d.message;
    const auto number = [&](const char* key) { return std::strtod(expected.at(key).c_str(), nullptr); };
    if (expected.count("dt")) {
      EXPECT_DOUBLE_EQ(options.dt, number("dt")) << name;
    }
    if (expected.count("theta")) {
      EXPECT_DOUBLE_EQ(options.theta, number("theta")) << name;
    }
    if (expected.count("tol")) {
      EXPECT_DOUBLE_EQ(options.nlgs.tolerance, number("tol")) << name;
    }
    if (expected.count("relax")) {
      EXPECT_DOUBLE_EQ(options.nlgs.relax, number("relax")) << name;
    }
    if (expected.count("gs_it1")) {
      EXPECT_EQ(options.nlgs.gs_it1, static_cast<int>(number("gs_it1"))) << name;
    }
    if (expected.count("gs_it2")) {
      EXPECT_EQ(options.nlgs.gs_it2, static_cast<int>(number("gs_it2"))) << name;
    }
    if (expected.count("nb_steps")) {
      EXPECT_EQ(options.steps, static_cast<long>(number("nb_steps"))) << name;
    }
    EXPECT_EQ(sources["dt"], run::ParameterSource::command_py) << name;
    ++compared;
  }
  EXPECT_GT(compared, 10);
}

}  // namespace
}  // namespace lmgc::test
