// MODELS.DAT reader. docs/lmgc90-facts/datbox-inputs.md §4 (read_models of mod_models).
#include "grammar/models/parser.hpp"

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"

namespace lmgc::grammar {
namespace {

bool blank(std::string_view text) {
  return text.find_first_not_of(" \t") == std::string_view::npos;
}

int end_column(const Line& line) {
  return static_cast<int>(std::max<std::size_t>(trim_right(line.text).size(), 1));
}

// First item of a list-directed character read: quoted, or up to a blank, ',' or '/'.
std::string list_directed_word(std::string_view text) {
  std::size_t i = text.find_first_not_of(' ');
  if (i == std::string_view::npos) return {};
  const char quote = text[i];
  std::string out;
  if (quote == '\'' || quote == '"') {
    for (++i; i < text.size() && text[i] != quote; ++i) out += text[i];
    return out;
  }
  for (; i < text.size() && text[i] != ' ' && text[i] != ',' && text[i] != '/'; ++i) out += text[i];
  return out;
}

// Model types of init_models (mod_models.f90): any other stops LMGC90 with 'unknown model'.
constexpr std::string_view kModelKinds[] = {"MECAx", "THERM", "POROx", "MULTI"};

// Finite element names LMGC90 knows, all model types together: mod_a_mecaEF_iso.f90
// (get_NAME_mecaEF_iso), _bar, _shell, _shb, _discrete, _joint; mod_a_therEF_iso.f90,
// mod_a_therEF_bar.f90; mod_a_poroEF_iso.f90; mod_a_multiEF_iso.f90. Any other stops the run
// ('mecaEF ... unknown', ...). Names starting with 'EXT' or 'Rxx' are external elements.
constexpr std::string_view kElements[] = {
    // mechanical, isoparametric
    "T3xxx", "T3Lxx", "T6xxx", "Q4xxx", "Q8xxx", "Q8Rxx", "Q4P0x", "H8xxx", "H20xx", "H20Rx", "TE4xx",
    "TE4Lx", "TE10x", "PRI6x", "PRI15",
    // mechanical: bar, shell, solid-shell, discrete, joints
    "BARxx", "DKTxx", "SHB6x", "SPRNG", "J2xx2", "J3xx2", "J3xx3", "J6xx3", "J4xx3", "J8xx3",
    // thermal bar
    "S2xth",
    // poro and multi-physics
    "T33xx", "Q44xx", "Q84xx", "T63xx", "H208x", "H88xx", "TE104", "TE44x"};

bool known_element(std::string_view name) {
  if (name.substr(0, 3) == "EXT" || name.substr(0, 3) == "Rxx") return true;
  return std::find(std::begin(kElements), std::end(kElements), name) != std::end(kElements);
}

class ModelsParser {
 public:
  ModelsParser(const SourceText& source, DiagnosticSink& sink) : reader_(source, sink) {}

  ModelsFile parse() {
    ModelsFile file;
    if (!reader_.check_records()) return file;
    while (!reader_.at_end()) {
      const Line& line = reader_.next();
      if (keyword_of(line.text) != "model") {
        reader_.report("L1019", line, 1, end_column(line),
                       "line outside any '$model' block; LMGC90 skips it");
        continue;
      }
      if (auto model = parse_model()) file.models.push_back(std::move(*model));
    }
    return file;
  }

 private:
  std::optional<Model> parse_model() {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends after '$model'; a model nickname line is expected");
      return std::nullopt;
    }
    const Line& name = reader_.next();
    Model model;
    model.nickname = reader_.word(name, 2, 6);
    if (blank(model.nickname.value)) {
      reader_.report("L1013", name, 2, 6, "expected a model nickname in columns 2-6");
      return std::nullopt;
    }
    // The mdlty line (columns 2-6 blank, 9-13 set), then option lines (columns 2-13 blank).
    bool seen_mdlty = false;
    bool takes_options = false;  // LMGC90 reads further options only when the mdlty line has one
    while (!reader_.at_end()) {
      const Line& line = reader_.peek();
      if (!blank(columns(line.text, 2, 6))) break;
      const bool mdlty_line = !blank(columns(line.text, 9, 13));
      if (!seen_mdlty && !mdlty_line) break;
      reader_.next();
      if (mdlty_line) {
        if (seen_mdlty) {
          if (takes_options) {
            reader_.report("L1013", line, 9, 13,
                           "second 'mdlty' line in model '" + model.nickname.value +
                               "': LMGC90 stops with 'error reading models'");
            continue;
          }
          reader_.report(
              "L1019", line, 9, 13,
              "second 'mdlty' line in model '" + model.nickname.value + "': LMGC90 keeps only this one");
        }
        seen_mdlty = true;
        read_mdlty_line(line, model, takes_options);
        continue;
      }
      const Word id = reader_.word(line, 23, 27);
      if (blank(id.value)) continue;
      if (!takes_options) {
        reader_.report("L1019", line, 23, 27,
                       "option after an 'mdlty' line without option: LMGC90 ignores it",
                       "put the first option on the mdlty line");
        continue;
      }
      model.options.push_back(read_option(line, id));
      // spec §4: 61-65 (I5) on any option line after the mdlty line; one size per model (the max).
      if (!blank(columns(line.text, 61, 65))) {
        const Integer size = reader_.integer(line, 61, 65);
        if (size.value > model.vfield_max_size.value) model.vfield_max_size = size;
      }
    }
    if (!seen_mdlty)
      reader_.report("L1012", name, 2, 6,
                     "model '" + model.nickname.value + "' has no 'mdlty' line (MECAx, THERM, ...)");
    return model;
  }

  void read_mdlty_line(const Line& line, Model& model, bool& takes_options) {
    model.kind = reader_.word(line, 9, 13);
    model.element = reader_.word(line, 16, 20);
    if (std::find(std::begin(kModelKinds), std::end(kModelKinds), model.kind.value) == std::end(kModelKinds))
      reader_.report("L1001", line, 9, 13, "unknown model type '" + model.kind.value + "'",
                     "model types are MECAx, THERM, POROx and MULTI, in columns 9-13");
    if (!known_element(model.element.value))
      reader_.report("L1001", line, 16, 20, "unknown finite element '" + model.element.value + "'",
                     "elements are e.g. T3xxx, Q4xxx, Q4P0x, Q8xxx, H8xxx, TE4xx, PRI6x, in columns 16-20");
    model.user_model = Word{};
    model.options.clear();
    model.vfield_max_size = Integer{};
    const Word id = reader_.word(line, 23, 27);
    takes_options = !blank(id.value);
    if (!takes_options) return;
    if (id.value == "u_mdl") {
      // A user model: its name is read list-directed from columns 30-79 (character(len=50)).
      model.user_model = Word{list_directed_word(columns(line.text, 30, 79)), reader_.span(line, 30, 79)};
      if (model.user_model.value.empty())
        reader_.report("L1015", line, 30, 79, "the user model name ('u_mdl') is missing");
      // A quoted name with a blank, comma, slash or quote reads whole, but LMGC90 writes it unquoted
      // (A50) and reads its own echo as another name.
      else if (model.user_model.value.find_first_of(" ,/'\"") != std::string::npos)
        reader_.report(
            "L1017", line, 30, 79,
            "user model name '" + model.user_model.value +
                "' holds a blank, comma, slash or quote: LMGC90's echo of it would name another model");
      return;
    }
    model.options.push_back(read_option(line, id));
  }

  ModelOption read_option(const Line& line, Word id) {
    if (id.value == "ext_f") id.value = "extsf";  // LMGC90 renames it after reading
    return ModelOption{std::move(id), reader_.word(line, 30, 59)};
  }

  CardReader reader_;
};

}  // namespace

ModelsFile parse_models(const SourceText& source, DiagnosticSink& sink) {
  return ModelsParser(source, sink).parse();
}

}  // namespace lmgc::grammar
