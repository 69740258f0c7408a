#include "grammar/gpv/writer.hpp"

#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {

// docs/lmgc90-facts/state-and-outputs.md §1.2 (header), §1.5 (blocks).
std::string write_gpv(const GpvFile& file) {
  std::string out = "     \n! Gauss Point Values\n      \n$steps  ";
  append_fortran_i(out, file.step.value, 7);
  append_blanks(out, 14);
  out += "time=";
  append_fortran_d(out, file.time.value);
  out += "\n \n!-----------------------------------------------------------------------\n";
  for (const GpvBody& body : file.bodies) {
    out += "$bdyty\n MAILx";
    append_fortran_i(out, body.number.value, 7);
    out += '\n';
    for (const GpvElement& e : body.elements) {
      out += "$blmty\n ";
      append_fortran_a(out, e.type.value, 5);
      append_fortran_i(out, e.number.value, 7);
      out += '\n';
      for (const GpvModelBlock& m : e.models) {
        out += "$model\n ";
        out += m.model.value;
        out += '\n';
        for (const auto& line : m.lines) {
          for (const Real& v : line) append_fortran_d(out, v.value);
          out += '\n';
        }
      }
    }
    out += "$$$$$$\n";
  }
  // write_gpv ends with the dashed line whatever the number of bodies (mod_MAILx.f90 write_gpv).
  out += "!-----------------------------------------------------------------------\n";
  return out;
}

}  // namespace lmgc::grammar
