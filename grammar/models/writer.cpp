#include "grammar/models/writer.hpp"

#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// FORMAT(1x,5x,2x,A5,2x,A5,2x,A5,2x,A30) (+ 1x,I5 for extvf).
void option_line(std::string& out, std::string_view kind, std::string_view element, const ModelOption* o) {
  append_blanks(out, 8);
  append_fortran_a(out, kind, 5);
  append_blanks(out, 2);
  append_fortran_a(out, element, 5);
  append_blanks(out, 2);
  append_fortran_a(out, o ? std::string_view(o->id.value) : std::string_view(), 5);
  append_blanks(out, 2);
  append_fortran_a(out, o ? std::string_view(o->value.value) : std::string_view(), 30);
  if (o && o->id.value == "extvf") {
    out += ' ';
    append_fortran_i(out, o->vfield_size.value, 5);
  }
  out += '\n';
}

}  // namespace

std::string write_models(const ModelsFile& file) {
  std::string out;
  for (const Model& m : file.models) {
    out += "$model  mdlty  finel  eleop  value  \n ";
    append_fortran_a(out, m.nickname.value, 5);
    append_blanks(out, 22);
    out += '\n';
    if (m.options.empty()) option_line(out, m.kind.value, m.element.value, nullptr);
    for (std::size_t i = 0; i < m.options.size(); ++i)
      option_line(out, i == 0 ? std::string_view(m.kind.value) : std::string_view(),
                  i == 0 ? std::string_view(m.element.value) : std::string_view(), &m.options[i]);
  }
  return out;
}

}  // namespace lmgc::grammar
