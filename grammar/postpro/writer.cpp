#include "grammar/postpro/writer.hpp"

#include "grammar/common/fortran_format.hpp"
#include "grammar/postpro/catalogue.hpp"

namespace lmgc::grammar {
namespace {

void line(std::string& out, std::string_view text) {
  append_fortran_a(out, text, 30);
  out += ":\n";
}

}  // namespace

std::string write_postpro(const PostproFile& file, int) {
  std::string out = "#23456789012345678901234567890:\n";
  for (const PostproCommand& c : file.commands) {
    line(out, c.name.value);
    line(out, "STEP " + std::to_string(c.period.value));
    for (const PostproArgument& a : c.arguments) {
      std::string text;
      if (!a.word.value.empty()) text = a.word.value;
      if (a.word.value == "INTER" && !a.integers.empty()) {
        // 'INTER' then the body id in columns 7-13.
        text = "INTER ";
        append_fortran_i(text, a.integers[0].value, 7);
      } else if (a.integers.size() == 2 && a.word.value.empty()) {
        // (I7,1X,I3) and (I7,1X,I7) pairs: each value left-justified in its field (blanks are
        // ignored by I formats), which list-directed reading accepts too.
        append_fortran_a(text, std::to_string(a.integers[0].value), 7);
        text += ' ';
        text += std::to_string(a.integers[1].value);
      } else {
        for (std::size_t k = 0; k < a.integers.size(); ++k) text += (k ? " " : "") + std::to_string(a.integers[k].value);
        for (const Real& r : a.reals) {
          std::string v;
          append_fortran_es(v, r.value, 14, 7);
          text += std::string(trim(v));
        }
      }
      line(out, text);
    }
  }
  line(out, "END");
  return out;
}

}  // namespace lmgc::grammar
