// MODELS.OUT writer. docs/lmgc90-facts/datbox-inputs.md §4 "Echo MODELS.OUT" (write_models of mod_models).
#include "grammar/models/writer.hpp"

#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// FORMAT(1x,5x,2x,A5,2x,A5,2x,A5,2x,A30) [12]; A50 for the user model name [13];
// ',1x,I5' after the value for an 'extvf' option line [14].
void option_line(std::string& out, std::string_view kind, std::string_view element, std::string_view id,
                 std::string_view value, int value_width, const std::int64_t* size) {
  append_blanks(out, 8);
  append_fortran_a(out, kind, 5);
  append_blanks(out, 2);
  append_fortran_a(out, element, 5);
  append_blanks(out, 2);
  append_fortran_a(out, id, 5);
  append_blanks(out, 2);
  append_fortran_a(out, value, value_width);
  if (size) {
    out += ' ';
    append_fortran_i(out, *size, 5);
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
    const bool user_model = !m.user_model.value.empty();
    if (!user_model && m.options.empty()) {
      option_line(out, m.kind.value, m.element.value, "", "", 30, nullptr);
      continue;
    }
    // The mdlty line carries 'u_mdl' or the first option (never with a size).
    std::size_t next = 0;
    if (user_model)
      option_line(out, m.kind.value, m.element.value, "u_mdl", m.user_model.value, 50, nullptr);
    else {
      option_line(out, m.kind.value, m.element.value, m.options[0].id.value, m.options[0].value.value, 30,
                  nullptr);
      next = 1;
    }
    for (; next < m.options.size(); ++next) {
      const ModelOption& o = m.options[next];
      option_line(out, "", "", o.id.value, o.value.value, 30,
                  o.id.value == "extvf" ? &m.vfield_max_size.value : nullptr);
    }
  }
  return out;
}

}  // namespace lmgc::grammar
