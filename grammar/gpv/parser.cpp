#include "grammar/gpv/parser.hpp"

#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {

GpvFile parse_gpv(const SourceText& source, DiagnosticSink& sink) {
  GpvFile file;
  CardReader reader(source, sink);
  if (!reader.check_records()) return file;
  const auto& lines = source.lines();
  std::size_t i = 0;
  bool header = false;
  for (; i < lines.size(); ++i)
    if (keyword_of(lines[i].text) == "steps") {
      file.step = reader.integer(lines[i], 9, 15);
      file.time = reader.real(lines[i], 35, 48);
      header = true;
      ++i;
      break;
    }
  if (!header) {
    reader.report_at_end("L1012", "no '$steps' header in the Gauss-point file");
    return file;
  }
  auto next_text = [&](const char* what) -> const Line* {
    while (i < lines.size() && is_skipped_line(lines[i].text)) ++i;
    if (i >= lines.size()) {
      reader.report_at_end("L1006", std::string("file ends where ") + what + " is expected");
      return nullptr;
    }
    return &lines[i++];
  };
  while (i < lines.size()) {
    const Line& line = lines[i];
    const std::string_view kw = keyword_of(line.text);
    if (is_skipped_line(line.text)) {
      ++i;
      continue;
    }
    if (kw != "bdyty") {
      reader.report("L1013", line, 1, static_cast<int>(line.text.size()), "expected '$bdyty'");
      ++i;
      continue;
    }
    ++i;
    const Line* type = next_text("the body line");
    if (!type) break;
    if (keyword_of(type->text) != "MAILx") {
      reader.report("L1001", *type, 2, 6, "Gauss-point values belong to MAILx bodies, not '" +
                                              std::string(keyword_of(type->text)) + "'");
      continue;
    }
    GpvBody body;
    body.number = reader.integer(*type, 7, 13);
    bool closed = false;
    while (i < lines.size()) {
      const std::string_view k = keyword_of(lines[i].text);
      if (k == "$$$$$") {
        ++i;
        closed = true;
        break;
      }
      if (k == "bdyty") break;
      if (k != "blmty") {
        if (!is_skipped_line(lines[i].text))
          reader.report("L1013", lines[i], 1, static_cast<int>(lines[i].text.size()), "expected '$blmty' or '$$$$$$'");
        ++i;
        continue;
      }
      ++i;
      const Line* element_line = next_text("the element line");
      if (!element_line) break;
      GpvElement element;
      element.type = reader.word(*element_line, 2, 6);
      element.number = reader.integer(*element_line, 7, 13);
      while (i < lines.size() && keyword_of(lines[i].text) == "model") {
        ++i;
        const Line* model_line = next_text("the model line");
        if (!model_line) break;
        GpvModelBlock block;
        block.model = reader.word(*model_line, 2, 6);
        // Value lines: consecutive 14-column fields from column 1.
        while (i < lines.size() && !lines[i].text.empty() && lines[i].text[0] != '$' && lines[i].text[0] != '!') {
          const Line& v = lines[i++];
          std::vector<Real> values;
          for (int first = 1; first + 13 <= static_cast<int>(v.text.size()); first += 14)
            values.push_back(reader.real(v, first, first + 13, 7, false));
          block.lines.push_back(std::move(values));
        }
        element.models.push_back(std::move(block));
      }
      body.elements.push_back(std::move(element));
    }
    if (!closed) reader.report_at_end("L1005", "MAILx body " + std::to_string(body.number.value) + " is not closed by '$$$$$$'");
    file.bodies.push_back(std::move(body));
  }
  return file;
}

}  // namespace lmgc::grammar
