#include "grammar/vloc_rloc/writer.hpp"

#include "grammar/common/fortran_format.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"

namespace lmgc::grammar {

void append_state_header(std::string& out, std::string_view title_line, std::string_view third_line,
                         std::int64_t step, double time) {
  out += "     \n";
  out += title_line;
  out += '\n';
  out += third_line;
  out += "\n$steps  ";
  append_fortran_i(out, step, 7);
  append_blanks(out, 14);
  out += "time=";
  append_fortran_d(out, time);
  out += "\n \n!-----------------------------------------------------------------------\n";
}

std::string write_vloc_rloc(const VlocRlocFile& file) {
  std::string out;
  out.reserve(256 + file.interactions.size() * 700);
  append_state_header(out, "! Vloc_Rloc", "      ", file.step.value, file.time.value);
  for (const VlocRlocInteraction& c : file.interactions) {
    const InteractionKind* kind = find_interaction_kind(c.type.value, c.xxl);
    // '(A6,2X,A5,2X,I7)', I10 in 2D xxl mode (state-and-outputs.md §1.4).
    out += "$icdan  ";
    append_fortran_a(out, c.type.value, 5);
    append_blanks(out, 2);
    append_fortran_i(out, c.number.value, kind ? kind->icdan_width : 7);
    out += '\n';
    out += c.title;
    out += '\n';
    // The data line along the module's format; missing values are written blank / 0.
    std::size_t w = 0, n = 0;
    for (const DataItem& item : data_items(kind ? kind->data_format : std::string_view())) {
      if (item.kind == 'X')
        append_blanks(out, item.width);
      else if (item.kind == 'A')
        append_fortran_a(out, w < c.words.size() ? std::string_view(c.words[w++].value) : "", item.width);
      else
        append_fortran_i(out, n < c.integers.size() ? c.integers[n++].value : 0, item.width);
    }
    out += '\n';
    for (const VlocRlocVector& v : c.vectors) {
      append_blanks(out, 27);
      for (std::size_t k = 0; k < v.values.size(); ++k) {
        append_blanks(out, 2);
        append_fortran_a(out, k < v.labels.size() ? std::string_view(v.labels[k]) : "", 5);
        append_fortran_d(out, v.values[k].value);
      }
      out += '\n';
    }
    if (!c.internal_comment.empty()) {
      out += c.internal_comment;
      out += '\n';
    }
    for (const auto& line : c.internal_lines) {
      for (const Real& value : line) {
        out += ' ';
        append_fortran_d(out, value.value);
      }
      out += '\n';
    }
    out += " \n";
  }
  return out;
}

}  // namespace lmgc::grammar
