// MODELS.DAT reader. spec: datbox-inputs.md §4.
#include "grammar/models/parser.hpp"

#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

bool blank(std::string_view text) { return text.find_first_not_of(" \t") == std::string_view::npos; }

}  // namespace

ModelsFile parse_models(const SourceText& source, DiagnosticSink& sink) {
  ModelsFile file;
  CardReader reader(source, sink);
  if (!reader.check_records()) return file;
  while (!reader.at_end()) {
    const Line& line = reader.next();
    if (keyword_of(line.text) != "model") {
      reader.report("L1019", line, 1, static_cast<int>(std::max<std::size_t>(line.text.size(), 1)),
                    "line outside any '$model' block; LMGC90 skips it");
      continue;
    }
    if (reader.at_end()) {
      reader.report_at_end("L1006", "file ends after '$model'; a model nickname line is expected");
      break;
    }
    const Line& name = reader.next();
    Model model;
    model.nickname = reader.word(name, 2, 6);
    if (blank(model.nickname.value)) {
      reader.report("L1013", name, 2, 6, "expected a model nickname in columns 2-6");
      continue;
    }
    // The mdlty line (columns 2-6 blank, 9-13 set), then option lines (columns 2-13 blank).
    bool first = true;
    while (!reader.at_end()) {
      const Line& opt = reader.peek();
      if (!blank(columns(opt.text, 2, 6))) break;
      if (first && blank(columns(opt.text, 9, 13))) break;
      if (!first && !blank(columns(opt.text, 9, 13))) break;
      reader.next();
      if (first) {
        model.kind = reader.word(opt, 9, 13);
        model.element = reader.word(opt, 16, 20);
        first = false;
      }
      ModelOption o;
      o.id = reader.word(opt, 23, 27);
      if (blank(o.id.value)) continue;  // a model without options
      if (o.id.value == "ext_f") o.id.value = "extsf";
      if (o.id.value == "u_mdl") {
        o.value = reader.word(opt, 30, 79);
        o.value.value = std::string(trim(o.value.value));
      } else {
        o.value = reader.word(opt, 30, 59);
        o.value.value = std::string(trim(o.value.value));
      }
      if (o.id.value == "extvf") o.vfield_size = reader.integer(opt, 61, 65);
      model.options.push_back(std::move(o));
    }
    if (first) reader.report("L1012", name, 2, 6, "model '" + model.nickname.value + "' has no 'mdlty' line");
    file.models.push_back(std::move(model));
  }
  return file;
}

}  // namespace lmgc::grammar
