#include "run/run_options.hpp"

namespace lmgc::run {
namespace {
std::string trimmed(const std::string& s) {
  const auto end = s.find_last_not_of(' ');
  const auto begin = s.find_first_not_of(' ');
  return begin == std::string::npos ? std::string() : s.substr(begin, end - begin + 1);
}
}  // namespace

bool parse_norm(const std::string& text, NlgsNorm& norm) {
  const std::string t = trimmed(text);
  if (t == "Quad")
    norm = NlgsNorm::quad;
  else if (t == "QuaN")
    norm = NlgsNorm::quad_normal;
  else if (t == "Maxm")
    norm = NlgsNorm::maxm;
  else if (t == "QM/16")
    norm = NlgsNorm::qm16;
  else
    return false;
  return true;
}

bool parse_storage(const std::string& text, NlgsStorage& storage) {
  const std::string t = trimmed(text);
  if (t == "Stored_Delassus_Loops")
    storage = NlgsStorage::stored_delassus_loops;
  else if (t == "Exchange_Local_Global")
    storage = NlgsStorage::exchange_local_global;
  else
    return false;
  return true;
}

}  // namespace lmgc::run
