// Vloc_Rloc reader. spec: state-and-outputs.md §1.4; datbox-inputs.md §7.
#include "grammar/vloc_rloc/parser.hpp"

#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"

namespace lmgc::grammar {
namespace {

bool blank(std::string_view s) { return s.find_first_not_of(" \t") == std::string_view::npos; }

}  // namespace

VlocRlocFile parse_vloc_rloc(const SourceText& source, DiagnosticSink& sink) {
  VlocRlocFile file;
  CardReader reader(source, sink);
  if (!reader.check_records()) return file;
  const auto& lines = source.lines();
  std::size_t i = 0;
  bool header = false;
  // The '$steps' header (datbox-inputs.md §6): step at 9-15, time at 35-48.
  for (; i < lines.size(); ++i) {
    if (keyword_of(lines[i].text) == "steps") {
      file.step = reader.integer(lines[i], 9, 15);
      file.time = reader.real(lines[i], 35, 48);
      header = true;
      ++i;
      break;
    }
    if (keyword_of(lines[i].text) == "icdan") break;
  }
  if (!header) {
    reader.report_at_end("L1012", "no '$steps' header: LMGC90 needs the step number and time of the file");
    return file;
  }
  while (i < lines.size()) {
    const Line& line = lines[i];
    if (keyword_of(line.text) != "icdan") {
      if (!is_skipped_line(line.text))
        reader.report("L1019", line, 1, static_cast<int>(line.text.size()), "line outside any '$icdan' block; LMGC90 skips it");
      ++i;
      continue;
    }
    VlocRlocInteraction c;
    c.type = reader.word(line, 9, 13);
    c.number = reader.integer(line, 16, 25, false);
    const InteractionKind* kind = find_interaction_kind(c.type.value);
    if (!kind) {
      reader.report("L1001", line, 9, 13, "unknown interaction module '" + c.type.value + "'");
      ++i;
      continue;
    }
    ++i;
    if (i + 1 >= lines.size()) {
      reader.report_at_end("L1006", "file ends inside the '$icdan' block of " + c.type.value);
      break;
    }
    c.title = std::string(lines[i++].text);
    // The data line, field by field along the module's format.
    const Line& data = lines[i++];
    int column = 1;
    std::string_view format = kind->data_format;
    while (!format.empty()) {
      const std::size_t end = format.find(' ');
      const std::string_view item = format.substr(0, end);
      format = end == std::string_view::npos ? std::string_view() : format.substr(end + 1);
      const int width = std::stoi(std::string(item.substr(item[0] == 'A' || item[0] == 'I' ? 1 : 0)));
      if (item.back() == 'X') {
        column += width;
      } else if (item[0] == 'A') {
        c.words.push_back(reader.word(data, column, column + width - 1));
        column += width;
      } else {
        c.integers.push_back(reader.integer(data, column, column + width - 1, false));
        column += width;
      }
    }
    // Vector lines: columns 1-29 blank, labelled values from column 30.
    while (i < lines.size() && lines[i].text.size() > 30 && blank(columns(lines[i].text, 1, 29)) &&
           !blank(columns(lines[i].text, 30, 34))) {
      const Line& v = lines[i++];
      VlocRlocVector vec;
      for (int k = 0; k < 3; ++k) {
        const int label = 30 + 21 * k;
        if (blank(columns(v.text, label, label + 4)) && columns(v.text, label + 5, label + 18).empty()) break;
        vec.labels.emplace_back(columns(v.text, label, label + 4));
        vec.values.push_back(reader.real(v, label + 5, label + 18));
      }
      c.vectors.push_back(std::move(vec));
    }
    // Internal variables: an optional '#' comment line, then lines of (1X,D14.7) values.
    if (i < lines.size() && !lines[i].text.empty() && lines[i].text[0] == '#') c.internal_comment = std::string(lines[i++].text);
    while (i < lines.size() && !blank(lines[i].text) && keyword_of(lines[i].text) != "icdan" && lines[i].text[0] == ' ') {
      const Line& v = lines[i++];
      std::vector<Real> values;
      for (int first = 2; first + 13 <= static_cast<int>(v.text.size()); first += 15)
        values.push_back(reader.real(v, first, first + 13));
      c.internal_lines.push_back(std::move(values));
    }
    // The block ends with a one-blank line.
    if (i < lines.size() && blank(lines[i].text)) ++i;
    file.interactions.push_back(std::move(c));
  }
  return file;
}

}  // namespace lmgc::grammar
