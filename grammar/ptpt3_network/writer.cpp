#include "grammar/ptpt3_network/writer.hpp"

#include <cstdio>

namespace lmgc::grammar {
namespace {

void append_integer(std::string& out, std::int64_t value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, " %lld", static_cast<long long>(value));
  out += buffer;
}

// 17 significant digits: the double read back is the one written.
void append_real(std::string& out, double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, " %.16E", value);
  out += buffer;
}

}  // namespace

std::string write_ptpt3_network(const Ptpt3NetworkFile& file) {
  std::string out;
  for (const Ptpt3Link& link : file.links) {
    for (const Integer* v : {&link.candidate, &link.antagonist, &link.x_periods, &link.y_periods, &link.loop})
      append_integer(out, v->value);
    if (file.with_parameters) {
      append_real(out, link.surface ? link.surface->value : 0.0);
      append_real(out, link.reference_length.value);
      append_real(out, link.mass ? link.mass->value : 0.0);
    } else {
      append_real(out, link.reference_length.value);
    }
    out += '\n';
  }
  return out;
}

}  // namespace lmgc::grammar
