// Mutating one numeric field of the default case (reference_cases/disk_bounce_rst) to any value
// (zero, negative, tiny, huge) never crashes the checks, and a nonsensical value (a non-positive
// radius, wall size, density or alert distance, a negative equivalent radius or friction, a
// restitution outside [0, 1]) always gives at least one error.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/common/diagnostic.hpp"
#include "tests/support/run_tool.hpp"
#include "tests/support/shared_data.hpp"
#include "validate/checks.hpp"

namespace lmgc::test {
namespace {

namespace fs = std::filesystem;

// A D14.7 field ("±0.dddddddD±ee", or "±0.ddddddd±eee" beyond two exponent digits) and its value.
struct Field {
  std::string text;
  double value = 0.0;
};

Field field(bool negative, int digits, int exponent) {
  Field f;
  if (digits == 0) {
    f.text = negative ? "-0.0000000D+00" : " 0.0000000D+00";
  } else {
    const std::string mantissa = std::to_string(digits);  // 7 digits: 1000000..9999999
    const std::string e = std::to_string(std::abs(exponent));
    f.text = std::string(negative ? "-" : " ") + "0." + mantissa +
             (std::abs(exponent) > 99
                  ? std::string(exponent < 0 ? "-" : "+") + e
                  : std::string("D") + (exponent < 0 ? "-" : "+") + (e.size() < 2 ? "0" : "") + e);
  }
  std::string c_syntax = f.text;
  const std::size_t d = c_syntax.find('D');
  if (d != std::string::npos)
    c_syntax[d] = 'E';
  else if (digits != 0)
    c_syntax.insert(c_syntax.size() - 4, "E");
  f.value = std::strtod(c_syntax.c_str(), nullptr);
  return f;
}

// One numeric field of the default case: the text that holds it (label and value) and when a
// value is nonsense.
struct Target {
  const char* file;
  const char* before;  // the text before the 14-column value (its label), unique in the file
  const char* value;   // the value as written
  std::function<bool(double)> nonsense;
};

const std::vector<Target>& targets() {
  static const std::vector<Target> list = {
      {"BODIES.DAT", "byrd=", " 0.1000000D+00", [](double v) { return !(v > 0.0); }},  // disk radius
      {"BODIES.DAT", "PLEXx  avrd=", " 0.1000000D+00", [](double v) { return v < 0.0; }},
      {"BODIES.DAT", "ax1 =", " 0.1000000D+01", [](double v) { return !(v > 0.0); }},  // wall half length
      {"BODIES.DAT", "ax2 =", " 0.5000000D-01", [](double v) { return !(v > 0.0); }},  // wall half thickness
      {"BODIES.DAT", "coo2=", " 0.1100000D+01", [](double) { return false; }},         // disk height
      {"BULK_BEHAV.DAT", "PLEXx  RIGID                           Umas=", " 0.1000000D+04",
       [](double v) { return !(v > 0.0); }},  // density of the disk
      {"BULK_BEHAV.DAT", "grv2=", "-0.9810000D+01", [](double) { return false; }},
      {"TACT_BEHAV.DAT", "rstn=", " 0.8000000D+00", [](double v) { return v < 0.0 || v > 1.0; }},
      {"TACT_BEHAV.DAT", "rstt=", " 0.0000000D+00", [](double v) { return v < 0.0 || v > 1.0; }},
      {"TACT_BEHAV.DAT", "fric=", " 0.0000000D+00", [](double v) { return v < 0.0; }},
      {"TACT_BEHAV.DAT", "WALLx      ", " 0.1000000D-01", [](double v) { return !(v > 0.0); }},  // alert
  };
  return list;
}

RC_GTEST_PROP(CheckMutation, OneNumericFieldNeverCrashesAndNonsenseIsAnError, ()) {
  // Full size: every field equally likely from the first test on.
  const std::size_t which = *rc::gen::resize(100, rc::gen::inRange<std::size_t>(0, targets().size()));
  const Target& target = targets()[which];
  const bool negative = *rc::gen::arbitrary<bool>();
  const int digits =
      *rc::gen::oneOf(rc::gen::just(0), rc::gen::resize(100, rc::gen::inRange(1000000, 10000000)));
  const int exponent =
      *rc::gen::resize(100, rc::gen::oneOf(rc::gen::inRange(-3, 4), rc::gen::inRange(-300, 301)));
  const Field value = field(negative, digits, exponent);
  RC_TAG(target.before);

  const fs::path dir = scratch_dir("mutation_property");
  fs::copy(fs::path(LMGC_SOURCE_DIR) / "reference_cases" / "disk_bounce_rst" / "DATBOX", dir / "DATBOX",
           fs::copy_options::recursive);
  // 10 steps instead of 3000: the checks read only the time step, and running COMMAND.DAT's
  // program for its parameters is then cheap (sanitizer builds).
  const fs::path command = dir / "DATBOX" / "COMMAND.DAT";
  std::string program = read_file(command);
  const std::size_t loop = program.find("REPETE 2999 FOIS");
  RC_ASSERT(loop != std::string::npos);
  program.replace(loop, 16, "REPETE    9 FOIS");
  std::ofstream(command, std::ios::binary) << program;
  const fs::path path = dir / "DATBOX" / target.file;
  std::string text = read_file(path);
  const std::string from = std::string(target.before) + target.value;
  const std::size_t at = text.find(from);
  RC_ASSERT(at != std::string::npos);
  text.replace(at, from.size(), std::string(target.before) + value.text);
  std::ofstream(path, std::ios::binary) << text;

  grammar::DiagnosticSink sink;
  const auto files = case_folder::load_case(dir, sink);
  RC_ASSERT(files.has_value());
  validate::check_case(*files, sink);
  if (target.nonsense(value.value)) RC_ASSERT(sink.has_errors());
}

// The formatter writes the fields LMGC90's readers expect.
TEST(CheckMutation, FieldsAreFourteenColumnsWithTheirValue) {
  EXPECT_EQ(field(false, 1000000, 0).text, " 0.1000000D+00");
  EXPECT_EQ(field(true, 2500000, -3).text, "-0.2500000D-03");
  EXPECT_EQ(field(false, 1000000, 120).text, " 0.1000000+120");
  EXPECT_EQ(field(true, 0, 5).text, "-0.0000000D+00");
  EXPECT_DOUBLE_EQ(field(true, 2500000, -3).value, -0.00025);
  EXPECT_DOUBLE_EQ(field(false, 1000000, 120).value, 1e119);
  for (int e : {-300, -10, 0, 7, 99, 100, 300}) EXPECT_EQ(field(false, 1234567, e).text.size(), 14u) << e;
}

}  // namespace
}  // namespace lmgc::test
