// BULK_BEHAV.OUT writer: walks the law catalogue, as LMGC90's write_behaviours walks its
// sub-block writers. docs/lmgc90-facts/datbox-inputs.md §2 "Echo BULK_BEHAV.OUT".
#include "grammar/bulk_behav/writer.hpp"

#include <algorithm>

#include "grammar/bulk_behav/catalogue.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// LMGC90's fixed comment block (write_comment of mod_bulk_behav): 18 lines written '(A72)' and a
// line of 72 blanks. Three lines start with "  !": their literal holds two doubled quotes, so it
// is 70 characters long and A72 right-justifies it.
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

constexpr std::string_view kIndent = "                                        ";  // 40 blanks: (38X,2X, ...)

// k(2X,A5,D14.7), or 'field' after each label ((2X,A5,A5)).
void append_values(std::string& out, const BulkValueLayout& layout, const BulkValues& line) {
  if (line.field) {
    for (int k = 0; k < std::max(layout.count, 1) && k < 3; ++k) {
      append_blanks(out, 2);
      append_fortran_a(out, layout.labels[static_cast<std::size_t>(k)], 5);
      out += "field";
    }
    return;
  }
  for (std::size_t k = 0; k < line.values.size() && k < 3; ++k) {
    append_blanks(out, 2);
    append_fortran_a(out, layout.labels[k], 5);
    append_fortran_d(out, line.values[k].value);
  }
}

// Writes a block's value lines in order; `next` walks block.lines.
class BlockWriter {
 public:
  BlockWriter(std::string& out, const BulkBlock& block) : out_(out), block_(block) {}

  void lines(std::span<const BulkValueLayout> layouts) {
    for (const BulkValueLayout& layout : layouts) {
      if (next_line_ >= block_.lines.size()) return;
      out_ += kIndent.substr(0, 38);
      append_values(out_, layout, block_.lines[next_line_++]);
      out_ += '\n';
    }
  }

  // Returns the option word, or nullptr when the block holds no more options.
  const Word* option(const BulkStep& step) {
    if (next_option_ >= block_.options.size()) return nullptr;
    const Word& word = block_.options[next_option_++];
    out_ += kIndent;
    switch (step.style) {
      case BulkOptionStyle::labelled13:  // (38X,2X,A5,1x,A13)
        append_fortran_a(out_, step.label, 5);
        out_ += ' ';
        append_fortran_a(out_, word.value, 13);
        break;
      case BulkOptionStyle::labelled5:  // (38X,2X,A5,1X,A5)
        append_fortran_a(out_, step.label, 5);
        out_ += ' ';
        append_fortran_a(out_, word.value, 5);
        break;
      case BulkOptionStyle::colon3:  // (40X,A3,A1)
        append_fortran_a(out_, word.value, 3);
        out_ += ':';
        break;
    }
    out_ += '\n';
    return &word;
  }

 private:
  std::string& out_;
  const BulkBlock& block_;
  std::size_t next_line_ = 0;
  std::size_t next_option_ = 0;
};

std::string anisotropy_of(const BulkLaw& law) {
  for (const BulkBlock& block : law.blocks)
    if (block.kind == BulkBlockKind::elas && block.options.size() >= 2) return block.options[1].value;
  return "isotropic";
}

const BulkOptionCase* find_case(std::span<const BulkOptionCase> cases, std::string_view value) {
  const auto it =
      std::find_if(cases.begin(), cases.end(), [&](const BulkOptionCase& c) { return c.value == value; });
  return it == cases.end() ? nullptr : &*it;
}

void write_block(std::string& out, const BulkLaw& law, const BulkBlock& block) {
  const BulkBlockInfo& info = bulk_block_info(block.kind);
  BlockWriter writer(out, block);
  for (const BulkStep& step : info.steps) {
    bool ends_block = false;
    switch (step.kind) {
      case BulkStepKind::marker:  // (38X,2X,A5)
        out += kIndent;
        out += step.label;
        out += '\n';
        break;
      case BulkStepKind::option:
        if (const Word* word = writer.option(step)) {
          const BulkOptionCase* chosen = find_case(step.cases, word->value);
          if (chosen) {
            writer.lines(chosen->lines);
            ends_block = chosen->ends_block;
          }
        }
        break;
      case BulkStepKind::values:
        writer.lines(step.lines);
        break;
      case BulkStepKind::anisotropy_values:
        if (const BulkOptionCase* chosen = find_case(step.cases, anisotropy_of(law)))
          writer.lines(chosen->lines);
        break;
      case BulkStepKind::file_name:  // (38X,1(2X,A50))
        out += kIndent;
        append_fortran_a(out, block.file_name.value, 50);
        out += '\n';
        break;
    }
    if (ends_block) break;
  }
  if (info.own_blank_line) out += " \n";
}

}  // namespace

std::string write_bulk_behav(const BulkBehavFile& file) {
  std::string out(kHeader);
  // '$gravy', (17X,3(2X,A5,D14.7)), ' '. LMGC90 always writes it (zero when never read).
  out += "$gravy\n";
  append_blanks(out, 17);
  constexpr std::string_view kGravityLabels[] = {"grv1=", "grv2=", "grv3="};
  for (std::size_t k = 0; k < 3; ++k) {
    append_blanks(out, 2);
    out += kGravityLabels[k];
    append_fortran_d(out, file.gravity[k].value);
  }
  out += "\n \n";
  for (const BulkLaw& law : file.laws) {
    out += "$behav  lawty\n";
    const BulkLawKind* kind = find_bulk_law_kind(law.law_type.value);
    if (kind) {
      // (1X,A5,2X,A30, ...): nickname and law type, then Umas or the first values.
      out += ' ';
      append_fortran_a(out, law.nickname.value, 5);
      append_blanks(out, 2);
      append_fortran_a(out, law.law_type.value, 30);
      if (kind->first_line == BulkFirstLine::values) {
        append_values(out, kind->first_values, BulkValues{false, law.first_line_values});
      } else if (law.density_field) {
        out += "  Umas=field";
      } else {
        out += "  Umas=";
        append_fortran_d(out, law.density.value);
      }
      out += '\n';
      for (const BulkBlock& block : law.blocks) write_block(out, law, block);
    }
    // An unknown law type writes nothing between '$behav  lawty' and the law loop's ' ' line.
    out += " \n";
  }
  return out;
}

}  // namespace lmgc::grammar
