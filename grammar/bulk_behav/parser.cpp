// BULK_BEHAV.DAT reader: walks the law catalogue (grammar/bulk_behav/catalogue.hpp).
// docs/lmgc90-facts/datbox-inputs.md §2, §0 (line reader), §10 ($gravity).
#include "grammar/bulk_behav/parser.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "grammar/bulk_behav/catalogue.hpp"
#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// Value k (0-based) of a value line sits at columns 46+21k .. 59+21k ('(k(7X,D14.7))' from 39).
constexpr int value_first(int k) {
  return 46 + 21 * k;
}
constexpr int value_last(int k) {
  return 59 + 21 * k;
}

bool is_blank(std::string_view text) {
  return text.find_first_not_of(" \t") == std::string_view::npos;
}

// A line whose first non-blank character is '!': not a comment for LMGC90's reader (column 1
// only), but skipped as any line between blocks; LMGC90's own echo header has three of them.
bool is_indented_comment(std::string_view text) {
  const std::size_t i = text.find_first_not_of(' ');
  return i != std::string_view::npos && text[i] == '!';
}

// First item of a list-directed character read: quoted, or up to a blank, ',' or '/'.
std::string list_directed_word(std::string_view text) {
  std::size_t i = text.find_first_not_of(' ');
  if (i == std::string_view::npos) return {};
  const char quote = text[i];
  std::string out;
  if (quote == '\'' || quote == '"') {
    for (++i; i < text.size(); ++i) {
      if (text[i] == quote) {
        if (i + 1 < text.size() && text[i + 1] == quote) {
          out += quote;
          ++i;
          continue;
        }
        break;
      }
      out += text[i];
    }
    return out;
  }
  for (; i < text.size() && text[i] != ' ' && text[i] != ',' && text[i] != '/'; ++i) out += text[i];
  return out;
}

class BulkBehavParser {
 public:
  BulkBehavParser(const SourceText& source, DiagnosticSink& sink) : reader_(source, sink) {}

  BulkBehavFile parse() {
    BulkBehavFile file;
    if (!reader_.check_records()) return file;
    reader_.skip_insignificant();
    bool skipping_unknown_law = false;  // LMGC90 skips what follows an unknown law type
    while (!reader_.at_end()) {
      const Line& line = reader_.next();
      const std::string_view keyword = keyword_of(line.text);
      if (keyword == "gravy" || keyword == "gravi") {
        skipping_unknown_law = false;
        read_gravity(file, line, keyword == "gravi");
      } else if (keyword == "behav") {
        skipping_unknown_law = false;
        if (auto law = parse_law()) {
          skipping_unknown_law = law->law_type.value == kUnknownBulkLawType;
          file.laws.push_back(std::move(*law));
        }
      } else if (!skipping_unknown_law && !is_indented_comment(line.text)) {
        reader_.report("L1019", line, 1,
                       static_cast<int>(std::max<std::size_t>(trim_right(line.text).size(), 1)),
                       "line outside any '$behav' block; LMGC90 skips it");
      }
    }
    if (!file.has_gravity)
      reader_.report_at_end("L1012", "no '$gravy' block: LMGC90 stops with 'error reading gravy'");
    return file;
  }

 private:
  void read_gravity(BulkBehavFile& file, const Line& line, bool guide_spelling) {
    if (guide_spelling)
      reader_.report("L1018", line, 1,
                     static_cast<int>(std::max<std::size_t>(trim_right(line.text).size(), 1)),
                     "'$gravity' is the user's guide spelling; LMGC90 reads only '$gravy' (columns 2-6) and "
                     "would stop with 'error reading gravy'",
                     "write '$gravy'");
    if (file.has_gravity) {
      reader_.report("L1019", line, 2, 6, "second gravity block; LMGC90 uses only the first");
      if (!reader_.at_end()) reader_.next();
      return;
    }
    const Line* values = next_line("the gravity values (grv1= at 25-38, grv2= at 46-59, grv3= at 67-80)");
    if (!values) return;
    // docs/lmgc90-facts/datbox-inputs.md §2: grv1 25-38, grv2 46-59, grv3 67-80.
    file.gravity[0] = reader_.real(*values, 25, 38);
    file.gravity[1] = reader_.real(*values, 46, 59);
    file.gravity[2] = reader_.real(*values, 67, 80);
    file.has_gravity = true;
  }

  // The next significant line of the current law. A '$behav' / '$gravy' keyword line there
  // means the law is truncated: LMGC90 would read that line as data; we stop the law instead.
  const Line* next_line(const std::string& what) {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends where " + what + " is expected" + law_context());
      return nullptr;
    }
    const Line& line = reader_.peek();
    const std::string_view keyword = keyword_of(line.text);
    if (keyword == "behav" || keyword == "gravy") {
      reader_.report("L1013", line, 1, 6,
                     "'$" + std::string(keyword) + "' line where " + what + " is expected" + law_context() +
                         "; LMGC90 would read this line as data");
      return nullptr;
    }
    last_line_ = &reader_.next();
    return last_line_;
  }

  std::string law_context() const {
    return law_nickname_.empty() ? std::string() : " (law '" + law_nickname_ + "')";
  }

  // A value line of `layout`; `third_blank` tells whether columns 88-101 were blank.
  bool read_values(const BulkValueLayout& layout, std::vector<BulkValues>& out) {
    const Line* line = next_line("a value line (" + std::string(trim(layout.labels[0])) + " at 46-59)");
    if (!line) return false;
    BulkValues values;
    if (layout.field_allowed && columns(line->text, 46, 50) == "field") {
      values.field = true;
    } else {
      for (int k = 0; k < layout.count && k < 3; ++k)
        values.values.push_back(reader_.real(*line, value_first(k), value_last(k)));
      if (layout.by_dimension)
        third_columns_blank_ = third_columns_blank_ && is_blank(columns(line->text, 88, 101));
    }
    out.push_back(std::move(values));
    return true;
  }

  bool read_lines(std::span<const BulkValueLayout> layouts, std::vector<BulkValues>& out) {
    for (const BulkValueLayout& layout : layouts)
      if (!read_values(layout, out)) return false;
    return true;
  }

  // The anisotropy given by the law's ELAS block (CPLT follows it).
  static std::string anisotropy_of(const BulkLaw& law) {
    for (const BulkBlock& block : law.blocks)
      if (block.kind == BulkBlockKind::elas && block.options.size() >= 2) return block.options[1].value;
    return "isotropic";
  }

  // Reads one sub-block by its catalogue steps. Returns false when the law ends early.
  bool read_block(const BulkBlockInfo& info, BulkLaw& law) {
    BulkBlock block;
    block.kind = info.kind;
    bool complete = true;
    for (const BulkStep& step : info.steps) {
      bool ends_block = false;
      switch (step.kind) {
        case BulkStepKind::marker: {
          const Line* line =
              next_line("the '" + std::string(step.checked) + "' line of " + std::string(info.name));
          if (!line) {
            complete = false;
            break;
          }
          const int last = 40 + static_cast<int>(step.checked.size());
          if (columns(line->text, 41, last) != step.checked)
            reader_.report("L1016", *line, 41, last,
                           "expected '" + std::string(step.checked) + "' in columns 41-" +
                               std::to_string(last) + " (" + std::string(info.name) +
                               " sub-block); LMGC90 stops with 'BULK_BEHAV.DAT unreadable'");
          break;
        }
        case BulkStepKind::option: {
          const std::string what =
              step.label.empty() ? "the model of " + std::string(info.name)
                                 : "the '" + std::string(step.label) + "' line of " + std::string(info.name);
          const Line* line = next_line(what);
          if (!line) {
            complete = false;
            break;
          }
          if (!step.checked.empty() && columns(line->text, 41, 45) != step.checked)
            reader_.report(
                "L1016", *line, 41, 45,
                "expected '" + std::string(step.checked) + "' in columns 41-45; LMGC90 stops here");
          Word word = reader_.word(*line, step.first, step.last);
          const auto match = std::find_if(step.cases.begin(), step.cases.end(),
                                          [&](const BulkOptionCase& c) { return c.value == word.value; });
          block.options.push_back(word);
          if (match == step.cases.end()) {
            std::string accepted;
            for (const BulkOptionCase& c : step.cases)
              accepted += (accepted.empty() ? "" : ", ") + std::string(c.value);
            reader_.report("L1017", *line, step.first, step.last,
                           "'" + word.value + "' in columns " + std::to_string(step.first) + "-" +
                               std::to_string(step.last) + " is not one of " + accepted + " (" +
                               std::string(info.name) + " sub-block)");
            break;
          }
          if (!match->supported)
            reader_.report("L1017", *line, step.first, step.last,
                           "'" + word.value +
                               "' is accepted by LMGC90's reader but not implemented: it stops with "
                               "'Not implemented yet'",
                           "only 'standard' elasticity is implemented");
          if (!read_lines(match->lines, block.lines)) {
            complete = false;
            break;
          }
          ends_block = match->ends_block;
          break;
        }
        case BulkStepKind::values:
          if (!read_lines(step.lines, block.lines)) complete = false;
          break;
        case BulkStepKind::anisotropy_values: {
          const std::string anisotropy = anisotropy_of(law);
          const auto match = std::find_if(step.cases.begin(), step.cases.end(),
                                          [&](const BulkOptionCase& c) { return c.value == anisotropy; });
          if (match == step.cases.end()) {
            if (last_line_)
              reader_.report("L1017", *last_line_, 41, 45,
                             std::string(info.name) + " is not defined for '" + anisotropy +
                                 "' elasticity; LMGC90 stops here");
            break;
          }
          if (!read_lines(match->lines, block.lines)) complete = false;
          break;
        }
        case BulkStepKind::file_name: {
          const Line* line = next_line("the user material file name");
          if (!line) {
            complete = false;
            break;
          }
          const std::string_view text = columns(line->text, 1, static_cast<int>(kRecordLength));
          // LMGC90 keeps the name in a character(len=50).
          block.file_name = Word{list_directed_word(text).substr(0, 50),
                                 reader_.span(*line, 1, static_cast<int>(trim_right(text).size()))};
          if (block.file_name.value.empty())
            reader_.report("L1015", *line, 1,
                           static_cast<int>(std::max<std::size_t>(trim_right(text).size(), 1)),
                           "the user material file name is missing");
          // A quoted name with a blank, comma, slash or quote reads whole, but LMGC90 writes it
          // unquoted (A50) and reads its own echo as another name (as for MODELS.DAT's user models).
          else if (block.file_name.value.find_first_of(" ,/'\"") != std::string::npos)
            reader_.report(
                "L1017", *line, 1, static_cast<int>(std::max<std::size_t>(trim_right(text).size(), 1)),
                "user material file name '" + block.file_name.value +
                    "' holds a blank, comma, slash or quote: LMGC90's echo of it would name another "
                    "file");
          break;
        }
      }
      if (!complete || ends_block) break;
    }
    law.blocks.push_back(std::move(block));
    return complete;
  }

  std::optional<BulkLaw> parse_law() {
    law_nickname_.clear();
    last_line_ = nullptr;
    const Line* line = next_line("a law line (nickname at 2-6, law type at 9-38)");
    if (!line) return std::nullopt;
    BulkLaw law;
    law.nickname = reader_.word(*line, 2, 6);
    law.law_type = reader_.word(*line, 9, 38);
    law_nickname_ = law.nickname.value;
    const BulkLawKind* kind = find_bulk_law_kind(law.law_type.value);
    if (!kind) {
      // LMGC90 keeps the law with a blank nickname and type 'unknown' and skips its lines.
      reader_.report("L1001", *line, 9, 38, "unknown bulk behaviour law type '" + law.law_type.value + "'",
                     "bulk law types are RIGID, MATERIAL_POINT, ELAS, ELAS_PLAS, THERMO_ELAS, ... "
                     "(datbox-inputs.md §2)");
      law.nickname = Word{std::string(), law.nickname.span};
      law.law_type = Word{std::string(kUnknownBulkLawType), law.law_type.span};
      return law;
    }
    third_columns_blank_ = true;
    if (kind->first_line == BulkFirstLine::umas) {
      // docs/lmgc90-facts/datbox-inputs.md §2 read_UMASS: 'field' at 46-50, else Umas at 46-59.
      if (columns(line->text, 46, 50) == "field")
        law.density_field = true;
      else
        law.density = reader_.real(*line, 46, 59);
    } else {
      const BulkValueLayout& layout = kind->first_values;
      for (int k = 0; k < layout.count && k < 3; ++k)
        law.first_line_values.push_back(reader_.real(*line, value_first(k), value_last(k)));
      if (layout.by_dimension) third_columns_blank_ = is_blank(columns(line->text, 88, 101));
    }
    for (BulkBlockKind block : kind->blocks)
      if (!read_block(bulk_block_info(block), law)) break;
    // DISCRETE: LMGC90 reads 2 or 3 values per line by the space dimension, which this file does
    // not give; a law with columns 88-101 blank on all its lines is a 2D law.
    if (kind->first_values.by_dimension && third_columns_blank_) {
      if (law.first_line_values.size() == 3) law.first_line_values.pop_back();
      for (BulkBlock& block : law.blocks)
        for (BulkValues& values : block.lines)
          if (values.values.size() == 3) values.values.pop_back();
    }
    return law;
  }

  CardReader reader_;
  std::string law_nickname_;
  bool third_columns_blank_ = true;
  const Line* last_line_ = nullptr;  // the last line a law read (where CPLT's anisotropy fails)
};

}  // namespace

bool bulk_density(const BulkBehavFile& file, const std::string& nickname, double& density) {
  for (const BulkLaw& law : file.laws)
    if (law.nickname.value == nickname) {
      if (law.density_field) return false;
      density = law.density.value;
      return true;
    }
  return false;
}

BulkBehavFile parse_bulk_behav(const SourceText& source, DiagnosticSink& sink) {
  return BulkBehavParser(source, sink).parse();
}

}  // namespace lmgc::grammar
