// BULK_BEHAV.OUT writer. spec: datbox-inputs.md §2 "Echo BULK_BEHAV.OUT".
#include "grammar/bulk_behav/writer.hpp"

#include "grammar/bulk_behav/catalogue.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// LMGC90's fixed comment block (write_comment of mod_bulk_behav), 18 lines and a blank line.
constexpr std::string_view kHeader =
    "! File BULK_BEHAV                                                       \n"
    "!                                                                       \n"
    "  ! The symbol   '$'       preceeds a keyword used in scanning files.   \n"
    "!                                                                       \n"
    "  ! The symbol   'behav'   stands for the nickname of a bulk behaviour  \n"
    "! law, character(len=5).                                                \n"
    "!                                                                       \n"
    "  ! The symbol   'lawty'   stands for the name of a dedicated reading   \n"
    "! filter of a bulk behaviour law, character(len=30).                    \n"
    "!                                                                       \n"
    "! STANDARD FILTERS of bulk laws                                         \n"
    "!                                                                       \n"
    "! 123456789012345678901234567890:                                       \n"
    "!                               :                                       \n"
    "! bulk behaviour                :                                       \n"
    "!                               :                                       \n"
    "! RIGID                         : Rigid body                            \n"
    "! ELAS                          : Deformable elastic body               \n"
    "                                                                        \n";

// Sub-blocks that write their own blank line after them (the "blank-line quirk").
bool ends_with_blank(const std::string& kind) {
  return kind == "ELAS" || kind == "CPLT" || kind == "THERM" || kind == "VARIA" || kind == "PLAS" ||
         kind == "VISCO" || kind == "BIOT";
}

void append_pairs(std::string& out, const std::vector<std::string>& labels, const std::vector<Real>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    append_blanks(out, 2);
    append_fortran_a(out, i < labels.size() ? labels[i] : std::string("     "), 5);
    append_fortran_d(out, values[i].value);
  }
}

}  // namespace

std::string write_bulk_behav(const BulkBehavFile& file) {
  std::string out(kHeader);
  if (file.has_gravity) {
    out += "$gravy\n";
    append_blanks(out, 17);
    append_pairs(out, {"grv1=", "grv2=", "grv3="}, {file.gravity[0], file.gravity[1], file.gravity[2]});
    out += "\n \n";
  }
  for (const BulkLaw& law : file.laws) {
    out += "$behav  lawty\n ";
    append_fortran_a(out, law.nickname.value, 5);
    append_blanks(out, 2);
    append_fortran_a(out, law.law_type.value, 30);
    const BulkLawKind* kind = find_bulk_law_kind(law.law_type.value);
    if (kind && kind->first_line != BulkFirstLine::umas) {
      const std::vector<std::string> labels = kind->first_line == BulkFirstLine::values3
                                                  ? std::vector<std::string>{"m1  =", "m2  =", "m3  ="}
                                                  : std::vector<std::string>{"p___=", "p___=", "p___="};
      append_pairs(out, labels, law.first_line_values);
    } else if (law.density_field) {
      out += "  Umas=field";
    } else {
      out += "  Umas=";
      append_fortran_d(out, law.density.value);
    }
    out += '\n';
    for (const BulkBlock& block : law.blocks) {
      for (const BulkLine& line : block.lines) {
        switch (line.kind) {
          case BulkLine::Kind::option:
            append_blanks(out, 40);
            append_fortran_a(out, line.label, 5);
            out += ' ';
            append_fortran_a(out, line.word.value, 13);
            break;
          case BulkLine::Kind::marker:
            append_blanks(out, 40);
            out += line.label;
            break;
          case BulkLine::Kind::field:
            append_blanks(out, 40);
            append_fortran_a(out, line.label, 5);
            out += "field";
            break;
          case BulkLine::Kind::values:
            append_blanks(out, 38);
            append_pairs(out, line.labels, line.values);
            break;
        }
        out += '\n';
      }
      if (ends_with_blank(block.kind)) out += " \n";
    }
    out += " \n";
  }
  return out;
}

}  // namespace lmgc::grammar
