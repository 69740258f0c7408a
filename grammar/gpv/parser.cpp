// GPV reader. docs/lmgc90-facts/state-and-outputs.md §1.2, §1.5; datbox-inputs.md §0, §7.
#include "grammar/gpv/parser.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

// Element names that LMGC90's GPV readers accept; any other stops the run
// (mod_mecaMAILx.f90 / mod_therMAILx.f90 read_in_gpv).
constexpr std::array<std::string_view, 10> kElements = {"T3xxx", "T6xxx", "Q4xxx", "Q8xxx", "H8xxx",
                                                        "H20xx", "TE4xx", "TE10x", "PRI6x", "PRI15"};

bool is_block_keyword(std::string_view line) {
  if (!line.empty() && line[0] == '$') return true;
  const std::string_view k = keyword_of(line);
  return k == "bdyty" || k == "blmty" || k == "model" || k == "$$$$$";
}

class GpvParser {
 public:
  GpvParser(const SourceText& source, DiagnosticSink& sink) : lines_(source.lines()), reader_(source, sink) {}

  GpvFile run() {
    GpvFile file;
    if (!reader_.check_records()) return file;
    if (!read_header(file)) return file;
    while (i_ < lines_.size()) {
      const Line& line = lines_[i_];
      if (is_skipped_line(line.text)) {
        ++i_;
        continue;
      }
      if (keyword_of(line.text) != "bdyty") {
        reader_.report("L1013", line, 1, static_cast<int>(line.text.size()), "expected '$bdyty'");
        ++i_;
        continue;
      }
      ++i_;
      read_body(file);
    }
    return file;
  }

 private:
  // The '$steps' header (state-and-outputs.md §1.2): step at columns 9-15, time at 35-48.
  bool read_header(GpvFile& file) {
    for (; i_ < lines_.size(); ++i_) {
      const Line& line = lines_[i_];
      if (keyword_of(line.text) == "steps") {
        file.step = reader_.integer(line, 9, 15);
        file.time = reader_.real(line, 35, 48);
        ++i_;
        return true;
      }
      if (keyword_of(line.text) == "bdyty") {
        reader_.report("L1012", line, 2, 6, "no '$steps' header before the first '$bdyty' block");
        return false;
      }
    }
    reader_.report_at_end("L1012", "no '$steps' header in the Gauss-point file");
    return false;
  }

  // The next significant line (LMGC90's read_G_clin skips comments and blank lines).
  const Line* next_line(const char* what) {
    while (i_ < lines_.size() && is_skipped_line(lines_[i_].text)) ++i_;
    if (i_ >= lines_.size()) {
      reader_.report_at_end("L1006", std::string("file ends where ") + what + " is expected");
      return nullptr;
    }
    return &lines_[i_++];
  }

  void read_body(GpvFile& file) {
    const Line* type = next_line("the body line");
    if (!type) return;
    if (keyword_of(type->text) != "MAILx") {
      reader_.report(
          "L1001", *type, 2, 6,
          "Gauss-point values belong to MAILx bodies, not '" + std::string(keyword_of(type->text)) + "'");
      return;
    }
    GpvBody body;
    body.number = reader_.integer(*type, 7, 13);
    bool closed = false;
    while (i_ < lines_.size()) {
      const Line& line = lines_[i_];
      const std::string_view k = keyword_of(line.text);
      if (k == "$$$$$") {
        ++i_;
        closed = true;
        break;
      }
      if (k == "bdyty") break;
      if (k != "blmty") {
        if (!is_skipped_line(line.text))
          reader_.report("L1013", line, 1, static_cast<int>(line.text.size()),
                         "expected '$blmty' or '$$$$$$'");
        ++i_;
        continue;
      }
      ++i_;
      if (!read_element(body)) break;
    }
    if (!closed) {
      if (i_ < lines_.size())
        reader_.report("L1005", lines_[i_], 1, 6,
                       "MAILx body " + std::to_string(body.number.value) +
                           " is not closed by '$$$$$$' before the next '$bdyty'",
                       "end every body with a '$$$$$$' line");
      else
        reader_.report_at_end(
            "L1005", "MAILx body " + std::to_string(body.number.value) + " is not closed by '$$$$$$'");
    }
    file.bodies.push_back(std::move(body));
  }

  bool read_element(GpvBody& body) {
    const Line* element_line = next_line("the element line");
    if (!element_line) return false;
    GpvElement element;
    element.type = reader_.word(*element_line, 2, 6);
    element.number = reader_.integer(*element_line, 7, 13);
    if (std::find(kElements.begin(), kElements.end(), element.type.value) == kElements.end())
      reader_.report(
          "L1001", *element_line, 2, 6,
          "element '" + element.type.value + "' is not one that LMGC90 reads Gauss-point values for",
          "LMGC90 reads T3xxx, T6xxx, Q4xxx, Q8xxx, H8xxx, H20xx, TE4xx, TE10x, PRI6x and PRI15");
    while (i_ < lines_.size() && keyword_of(lines_[i_].text) == "model") {
      ++i_;
      const Line* model_line = next_line("the model line");
      if (!model_line) break;
      GpvModelBlock block;
      block.model = reader_.word(*model_line, 2, 6);
      read_values(block);
      element.models.push_back(std::move(block));
    }
    body.elements.push_back(std::move(element));
    return true;
  }

  // Value lines up to the next keyword: (9D14.7), consecutive 14-column fields from column 1.
  // A blank line is a vector of no value (LMGC90 writes an empty record for an empty vector).
  void read_values(GpvModelBlock& block) {
    while (i_ < lines_.size()) {
      const Line& v = lines_[i_];
      const std::string_view text = v.text;
      if (!text.empty() && (text[0] == '!' || text[0] == '#')) {
        ++i_;
        continue;
      }
      if (is_block_keyword(text)) break;
      ++i_;
      std::vector<Real> values;
      const std::size_t last_used = text.find_last_not_of(" \t");
      const int used = last_used == std::string_view::npos ? 0 : static_cast<int>(last_used) + 1;
      const int size = static_cast<int>(text.size());
      for (int first = 1; first <= used && values.size() < 10000; first += 14)
        values.push_back(reader_.real(v, first, std::min(first + 13, size), 7, false));
      block.lines.push_back(std::move(values));
    }
  }

  const std::vector<Line>& lines_;
  CardReader reader_;
  std::size_t i_ = 0;
};

}  // namespace

GpvFile parse_gpv(const SourceText& source, DiagnosticSink& sink) {
  return GpvParser(source, sink).run();
}

}  // namespace lmgc::grammar
