#include "grammar/postpro/writer.hpp"

#include "grammar/common/fortran_format.hpp"
#include "grammar/postpro/catalogue.hpp"

namespace lmgc::grammar {
namespace {

// docs/lmgc90-facts/datbox-inputs.md §8: only columns 1-30 are read; the ':' of column 31 is decoration.
// A longer list-directed line (four integers) keeps a blank before its ':' so the last value
// stays a separate item (the read stops after its last value and never reaches the ':').
void line(std::string& out, std::string_view text) {
  append_fortran_a(out, text, text.size() >= 30 ? static_cast<int>(text.size()) + 1 : 30);
  out += ":\n";
}

}  // namespace

std::string write_postpro(const PostproFile& file) {
  std::string out = "#23456789012345678901234567890:\n";
  for (const PostproCommand& c : file.commands) {
    line(out, c.name.value);
    line(out, "STEP " + std::to_string(c.period.value));
    for (const PostproArgument& a : c.arguments) line(out, postpro_argument_text(a));
  }
  line(out, "END");
  return out;
}

}  // namespace lmgc::grammar
