#include "grammar/dof/writer.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

constexpr std::string_view kDashes =
    "!-----------------------------------------------------------------------\n";

// k label/value pairs `(2X,A5,D14.7)` after the 27-column lead of a node or continuation line
// (state-and-outputs.md §1.3: FORMAT(1X,A5,1X,I6,2X,5X,2X,5X,k(2X,A5,D14.7)) and
// FORMAT(1X,5X,2X,5X,2X,5X,2X,5X,k(2X,A5,D14.7))).
void append_pairs(std::string& out, char letter, const std::vector<Real>& values, std::size_t first,
                  std::size_t count, std::size_t label_offset) {
  for (std::size_t i = first; i < first + count && i < values.size(); ++i) {
    out += "  ";
    out += letter;
    out += '(';
    out += std::to_string(i - label_offset + 1);
    out += ")=";
    append_fortran_d(out, values[i].value);
  }
  out += '\n';
}

// Values of one kind, 3 a line; the first line may be the node line (lead already written).
void append_value_lines(std::string& out, char letter, const std::vector<Real>& values, bool lead_written,
                        std::size_t label_offset = 0, std::size_t begin = 0,
                        std::size_t end = std::string::npos) {
  if (end > values.size()) end = values.size();
  for (std::size_t i = begin; i < end; i += 3) {
    if (!lead_written) append_blanks(out, 27);
    lead_written = false;
    append_pairs(out, letter, values, i, std::min<std::size_t>(3, end - i), label_offset);
  }
}

void write_node(std::string& out, const DofNode& node, bool thermal) {
  out += ' ';
  append_fortran_a(out, node.node_type.value, 5);
  out += ' ';
  append_fortran_i(out, node.number.value, 6);
  append_blanks(out, 14);
  if (thermal) {
    append_value_lines(out, 'T', node.x, true);  // therMAILx: T(1)= only
    if (node.x.empty()) out += '\n';
    return;
  }
  if (node.x.empty()) {
    out += '\n';
  } else {
    append_value_lines(out, 'X', node.x, true);
  }
  append_value_lines(out, 'V', node.v, false);
  // a(1..3), b(1..3), g(1..3): the columns of the principal frame.
  append_value_lines(out, 'a', node.frame, false, 0, 0, 3);
  append_value_lines(out, 'b', node.frame, false, 3, 3, 6);
  append_value_lines(out, 'g', node.frame, false, 6, 6, 9);
}

void write_body(std::string& out, const DofBody& body) {
  out += "$bdyty\n ";
  append_fortran_a(out, body.body_type.value, 5);
  if (body.body_type.value == "MAILx") {
    // (1X,A5,I7): no 2X for MAILx (state-and-outputs.md §1.3).
    append_fortran_i(out, body.number.value, 7);
    out += "\n$model\n ";
    append_fortran_a(out, body.model.value, 5);
  } else {
    append_blanks(out, 2);
    append_fortran_i(out, body.number.value, 7);
  }
  out += "\n$nodty\n";
  for (const DofNode& node : body.nodes) write_node(out, node, body.model.value == "THERM");
  if (body.rigid_part) {
    out += "!rigid part\n";
    write_node(out, *body.rigid_part, false);
  }
  out += "$$$$$$\n      \n";
}

}  // namespace

std::string write_dof(const DofFile& file) {
  // Header (state-and-outputs.md §1.2): '     ', '! DOF', '     ', (A6,2X,I7,14X,A5,D14.7), ' ', dashes.
  std::string out = "     \n! DOF\n     \n$steps  ";
  append_fortran_i(out, file.step.value, 7);
  append_blanks(out, 14);
  out += "time=";
  append_fortran_d(out, file.time.value);
  out += "\n \n";
  out += kDashes;
  for (const DofSection& section : file.sections) {
    for (const DofBody& body : section.bodies) write_body(out, body);
    if (section.closed) out += kDashes;
  }
  return out;
}

}  // namespace lmgc::grammar
