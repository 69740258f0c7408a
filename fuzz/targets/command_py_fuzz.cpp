// Fuzz target: a case's command.py, read without running it, and the comparison of its literals
// with a run's parameters.
#include <string>

#include "grammar/command_py/script.hpp"
#include "run/run_parameters.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const lmgc::grammar::CommandScript script = lmgc::grammar::read_command_script("command.py", text);
  lmgc::run::script_differences(lmgc::run::RunOptions{}, script);
  return 0;
}
