// Vloc_Rloc reader. docs/lmgc90-facts/state-and-outputs.md §1.2, §1.4; datbox-inputs.md §0, §7.
#include "grammar/vloc_rloc/parser.hpp"

#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"

namespace lmgc::grammar {
namespace {

bool blank(std::string_view s) {
  return s.find_first_not_of(" \t") == std::string_view::npos;
}

bool is_icdan(const Line& line) {
  return keyword_of(line.text) == "icdan";
}

// A labelled vector line: columns 1-29 blank, a label in columns 30-34 (FORMAT 103/104).
bool is_vector_line(const Line& line) {
  return line.text.size() > 34 && blank(columns(line.text, 1, 29)) && !blank(columns(line.text, 30, 34));
}

// An internal-variables line: (1X,D14.7) fields, so a blank in column 1 and values after it.
bool is_internal_line(const Line& line) {
  return !line.text.empty() && line.text[0] == ' ' && !blank(line.text) && !is_icdan(line) &&
         !is_vector_line(line);
}

// One (1X,D14.7) value of an internal-variables line. LMGC90 writes them all on one line, which can
// pass column 180 for laws with many internal variables (EXPO_CZM: up to 17), so the field is read
// from the whole line, not from the 180-column record.
Real internal_value(CardReader& reader, const Line& line, int first, int last) {
  const std::size_t begin = static_cast<std::size_t>(first - 1);
  const std::string_view field = line.text.substr(begin, static_cast<std::size_t>(last - first + 1));
  const RealResult r = read_fortran_real(field, 7);
  const SourceSpan span = reader.span(line, first, last);
  if (r.error == NumberError::malformed) {
    reader.report("L1002", line, first, last,
                  "internal variable '" + std::string(trim(field)) + "' in columns " + std::to_string(first) +
                      "-" + std::to_string(last) + " is not a real number",
                  "internal variables are written (1X,D14.7): 15 columns each");
    return Real{0.0, span};
  }
  if (r.error == NumberError::out_of_range) {
    reader.report("L1003", line, first, last,
                  "internal variable '" + std::string(trim(field)) +
                      "' is out of the range of a double precision real");
    return Real{0.0, span};
  }
  return Real{r.value, span};
}

class VlocRlocParser {
 public:
  VlocRlocParser(const SourceText& source, DiagnosticSink& sink)
      : lines_(source.lines()), reader_(source, sink) {}

  VlocRlocFile run() {
    VlocRlocFile file;
    if (!reader_.check_records()) return file;
    if (!read_header(file)) return file;
    while (i_ < lines_.size()) {
      const Line& line = lines_[i_];
      if (!is_icdan(line)) {
        // LMGC90 fishes for '$icdan' lines and skips everything else (datbox-inputs.md §7).
        if (!is_skipped_line(line.text))
          reader_.report("L1019", line, 1, static_cast<int>(line.text.size()),
                         "line outside any '$icdan' block; LMGC90 skips it");
        ++i_;
        continue;
      }
      read_block(file);
    }
    return file;
  }

 private:
  // The '$steps' header (state-and-outputs.md §1.2): step at columns 9-15, time at 35-48.
  bool read_header(VlocRlocFile& file) {
    for (; i_ < lines_.size(); ++i_) {
      const Line& line = lines_[i_];
      if (keyword_of(line.text) == "steps") {
        file.step = reader_.integer(line, 9, 15);
        file.time = reader_.real(line, 35, 48);
        ++i_;
        return true;
      }
      if (is_icdan(line)) {
        reader_.report(
            "L1012", line, 2, 6,
            "no '$steps' header before the first '$icdan' block: LMGC90 needs the step number and time");
        return false;
      }
      if (!is_skipped_line(line.text))
        reader_.report("L1019", line, 1, static_cast<int>(line.text.size()),
                       "line before the '$steps' header; LMGC90 skips it");
    }
    reader_.report_at_end("L1012", "no '$steps' header: LMGC90 needs the step number and time of the file");
    return false;
  }

  // The next significant line of the block (LMGC90 reads through read_G_clin, which skips comment
  // and blank lines), or nullptr after reporting where it is missing.
  const Line* block_line(const char* what, const std::string& type) {
    while (i_ < lines_.size() && is_skipped_line(lines_[i_].text)) ++i_;
    if (i_ >= lines_.size()) {
      reader_.report_at_end("L1006",
                            "file ends before the " + std::string(what) + " of a '" + type + "' block");
      return nullptr;
    }
    const Line& line = lines_[i_];
    if (is_icdan(line)) {
      reader_.report("L1012", line, 1, static_cast<int>(line.text.size()),
                     "the " + std::string(what) + " of the '" + type + "' block before is missing");
      return nullptr;
    }
    ++i_;
    return &line;
  }

  void skip_to_next_block() {
    while (i_ < lines_.size() && !is_icdan(lines_[i_])) ++i_;
  }

  void read_block(VlocRlocFile& file) {
    const Line& head = lines_[i_++];
    VlocRlocInteraction c;
    c.type = reader_.word(head, 9, 13);
    // I7 (I10 in 2D xxl mode) from column 16.
    c.number = reader_.integer(head, 16, 25, false);
    const InteractionKind* kind = find_interaction_kind(c.type.value);
    if (!kind) {
      reader_.report("L1001", head, 9, 13, "unknown interaction module '" + c.type.value + "'",
                     "LMGC90 skips blocks of modules it does not know");
      skip_to_next_block();
      return;
    }
    const Line* title = block_line("title line", c.type.value);
    if (!title) return;
    c.title = std::string(title->text);
    // The xxl layout is recognised by its title (LMGC90 itself knows it from its run state).
    if (const InteractionKind* xxl = find_interaction_kind(c.type.value, true);
        xxl != kind && trim_right(c.title) == trim_right(xxl->title)) {
      kind = xxl;
      c.xxl = true;
    }
    const Line* data = block_line("data line", c.type.value);
    if (!data) return;
    read_data_line(*kind, *data, c);
    read_vectors(c);
    read_internals(c);
    // The block ends with a line holding one blank.
    if (i_ < lines_.size() && blank(lines_[i_].text)) ++i_;
    file.interactions.push_back(std::move(c));
  }

  // The data line, field by field along the module's format.
  void read_data_line(const InteractionKind& kind, const Line& data, VlocRlocInteraction& c) {
    int column = 1;
    for (const DataItem& item : data_items(kind.data_format)) {
      const int last = column + item.width - 1;
      if (item.kind == 'A') c.words.push_back(reader_.word(data, column, last));
      if (item.kind == 'I') c.integers.push_back(reader_.integer(data, column, last, false));
      column = last + 1;
    }
  }

  // Vector lines: up to three (2X,A5,D14.7) fields after 27 blank columns. The first three (rl, vl,
  // gap) are read unconditionally by LMGC90; the others are recognised by their label.
  void read_vectors(VlocRlocInteraction& c) {
    while (i_ < lines_.size() && is_vector_line(lines_[i_])) {
      const Line& v = lines_[i_++];
      VlocRlocVector vec;
      for (int k = 0; k < 3; ++k) {
        const int label = 30 + 21 * k;
        if (blank(columns(v.text, label, label + 4)) && blank(columns(v.text, label + 5, label + 18))) break;
        vec.labels.emplace_back(columns(v.text, label, label + 4));
        vec.values.push_back(reader_.real(v, label + 5, label + 18));
      }
      c.vectors.push_back(std::move(vec));
    }
    static constexpr const char* kMandatory[] = {"reaction (rl) line", "relative velocity (vl) line",
                                                 "gap line"};
    if (c.vectors.size() >= 3) return;
    const std::string what = kMandatory[c.vectors.size()];
    if (i_ < lines_.size())
      reader_.report("L1012", lines_[i_], 30, 34,
                     "the " + what + " of '" + c.type.value + "' block " + std::to_string(c.number.value) +
                         " is missing; LMGC90 reads it unconditionally");
    else
      reader_.report_at_end("L1006", "file ends before the " + what + " of '" + c.type.value + "' block " +
                                         std::to_string(c.number.value));
  }

  // Internal variables: an optional '#' comment line, then lines of (1X,D14.7) values.
  void read_internals(VlocRlocInteraction& c) {
    if (i_ < lines_.size() && !lines_[i_].text.empty() && lines_[i_].text[0] == '#')
      c.internal_comment = std::string(lines_[i_++].text);
    while (i_ < lines_.size() && is_internal_line(lines_[i_])) {
      const Line& v = lines_[i_++];
      std::vector<Real> values;
      const int size = static_cast<int>(v.text.size());
      // Trailing blanks hold no value.
      const int used = static_cast<int>(v.text.find_last_not_of(" \t")) + 1;
      // (1X,D14.7) fields: column `first` is the skipped blank, the value is in the next 14.
      for (int first = 1; first < used && values.size() < 10000; first += 15)
        values.push_back(internal_value(reader_, v, first + 1, std::min(first + 14, size)));
      c.internal_lines.push_back(std::move(values));
    }
  }

  const std::vector<Line>& lines_;
  CardReader reader_;
  std::size_t i_ = 0;
};

}  // namespace

VlocRlocFile parse_vloc_rloc(const SourceText& source, DiagnosticSink& sink) {
  return VlocRlocParser(source, sink).run();
}

}  // namespace lmgc::grammar
