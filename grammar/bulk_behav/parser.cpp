// BULK_BEHAV.DAT reader. spec: datbox-inputs.md §2, §0.
#include "grammar/bulk_behav/parser.hpp"

#include <string>

#include "grammar/bulk_behav/catalogue.hpp"
#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"

namespace lmgc::grammar {
namespace {

constexpr int kValueColumns[3][2] = {{46, 59}, {67, 80}, {88, 101}};

class BulkBehavParser {
 public:
  BulkBehavParser(const SourceText& source, DiagnosticSink& sink) : reader_(source, sink) {}

  BulkBehavFile parse() {
    BulkBehavFile file;
    if (!reader_.check_records()) return file;
    const Line* first_law = nullptr;
    while (!reader_.at_end()) {
      const Line& line = reader_.next();
      const std::string_view kw = keyword_of(line.text);
      if (kw == "gravy" || kw == "gravi") {
        if (kw == "gravi")
          reader_.report("L1018", line, 1, 8,
                         "'$gravity' is the user's guide spelling; LMGC90 reads '$gravy' (columns 2-6) and would stop here");
        if (file.has_gravity) {
          reader_.report("L1019", line, 2, 6, "second gravity block; LMGC90 uses only the first");
          if (!reader_.at_end()) reader_.next();
          continue;
        }
        const Line* values = next_line("the gravity values");
        if (!values) break;
        for (int k = 0; k < 3; ++k) file.gravity[static_cast<std::size_t>(k)] = reader_.real(*values, 25 + 21 * k, 38 + 21 * k);
        file.has_gravity = true;
      } else if (kw == "behav") {
        if (!first_law) first_law = &line;
        if (auto law = parse_law()) file.laws.push_back(std::move(*law));
      } else {
        reader_.report("L1019", line, 1, static_cast<int>(std::max<std::size_t>(line.text.size(), 1)),
                       "line outside any '$behav' block; LMGC90 skips it");
      }
    }
    if (!file.has_gravity)
      reader_.report_at_end("L1012", "no '$gravy' block: LMGC90 stops with 'error reading gravy'");
    return file;
  }

 private:
  const Line* next_line(const char* what) {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", std::string("file ends where ") + what + " is expected");
      return nullptr;
    }
    return &reader_.next();
  }

  // A values line: up to `labels.size()` values at 46-59, 67-80, 88-101, or 'field' at 46-50.
  bool values(BulkBlock& block, std::initializer_list<const char*> labels, bool field_allowed = true) {
    const Line* line = next_line("a parameter line");
    if (!line) return false;
    BulkLine out;
    if (field_allowed && columns(line->text, 46, 50) == "field") {
      out.kind = BulkLine::Kind::field;
      out.label = *labels.begin();
    } else {
      out.kind = BulkLine::Kind::values;
      int k = 0;
      for (const char* label : labels) {
        out.labels.emplace_back(label);
        out.values.push_back(reader_.real(*line, kValueColumns[k][0], kValueColumns[k][1]));
        ++k;
      }
    }
    block.lines.push_back(std::move(out));
    return true;
  }

  // An option line: word at 47-59; `checked` label at 41-45 (or 41-44) when LMGC90 checks it.
  const Line* option(BulkBlock& block, const char* label, std::string_view checked = {}) {
    const Line* line = next_line("an option line");
    if (!line) return nullptr;
    if (!checked.empty() && columns(line->text, 41, 40 + static_cast<int>(checked.size())) != checked) {
      reader_.report("L1016", *line, 41, 45,
                     "expected '" + std::string(checked) + "' in columns 41-" + std::to_string(40 + checked.size()));
    }
    BulkLine out;
    out.kind = BulkLine::Kind::option;
    out.label = label;
    out.word = reader_.word(*line, 47, 59);
    out.word.value = std::string(trim(out.word.value));
    block.lines.push_back(std::move(out));
    return line;
  }

  bool marker(BulkBlock& block, const char* label, std::string_view checked) {
    const Line* line = next_line("a sub-block line");
    if (!line) return false;
    if (columns(line->text, 41, 40 + static_cast<int>(checked.size())) != checked)
      reader_.report("L1016", *line, 41, 44, "expected '" + std::string(checked) + "' in columns 41-44");
    BulkLine out;
    out.kind = BulkLine::Kind::marker;
    out.label = label;
    block.lines.push_back(std::move(out));
    return true;
  }

  // Elastic-like constants by anisotropy: 1 line of 2, 3 lines of 3, or 7 lines of 3.
  bool anisotropic_values(BulkBlock& block, const std::string& anisotropy, const Line& where, bool visco) {
    if (anisotropy == "isotropic") return visco ? values(block, {"VYng=", "VPss="}) : values(block, {"EYng=", "EPss="});
    if (anisotropy == "orthotropic")
      return values(block, {"EY11=", "EY22=", "EY33="}, false) && values(block, {"EP12=", "EP13=", "EP23="}, false) &&
             values(block, {"G12_=", "G13_=", "G23_="}, false);
    if (anisotropy == "anisotropic") {
      static const char* kRows[7][3] = {{"C11_=", "C12_=", "C13_="}, {"C14_=", "C15_=", "C16_="}, {"C22_=", "C23_=", "C24_="},
                                        {"C25_=", "C26_=", "C33_="}, {"C34_=", "C35_=", "C36_="}, {"C44_=", "C45_=", "C46_="},
                                        {"C55_=", "C56_=", "C66_="}};
      for (auto& row : kRows)
        if (!values(block, {row[0], row[1], row[2]}, false)) return false;
      return true;
    }
    reader_.report("L1017", where, 47, 59,
                   "anisotropy '" + anisotropy + "' is not one of isotropic, orthotropic, anisotropic");
    return false;
  }

  bool block(const std::string& kind, BulkLaw& law) {
    BulkBlock b;
    b.kind = kind;
    bool ok = true;
    std::string anisotropy = "isotropic";
    for (const auto& blk : law.blocks)
      for (const auto& l : blk.lines)
        if (l.kind == BulkLine::Kind::option && l.label == "ani_:") anisotropy = l.word.value;
    if (kind == "ELAS") {
      ok = option(b, "elas:", "elas:") != nullptr;
      const Line* ani = ok ? option(b, "ani_:", "ani_:") : nullptr;
      ok = ani && anisotropic_values(b, b.lines.back().word.value, *ani, false);
    } else if (kind == "CPLT") {
      ok = marker(b, "cplt:", "cplt") &&
           (anisotropy == "orthotropic" ? values(b, {"Dil1=", "Dil2=", "Dil3="}) : values(b, {"Dila="})) &&
           values(b, {"Tref="}, false);
    } else if (kind == "THERM") {
      ok = marker(b, "ther:", "ther") && values(b, {"SPHV="}) && values(b, {"COCO="});
    } else if (kind == "VARIA") {
      ok = marker(b, "varf:", "varf") && values(b, {"Trth=", "Tith="}, false);
    } else if (kind == "PLAS") {
      const Line* crit = option(b, "crit:");
      ok = crit != nullptr;
      if (ok && b.lines.back().word.value != "none") {
        const Line* isoh = option(b, "isoh:");
        ok = isoh != nullptr;
        if (ok) {
          const std::string w = b.lines.back().word.value;
          if (w == "Swift") ok = values(b, {"C0__=", "EPS0=", "n___="}, false);
          else if (w == "linear") ok = values(b, {"SIG0=", "K___="}, false);
          else if (w == "Hollomon") ok = values(b, {"K___=", "n___="}, false);
          else if (w != "none") reader_.report("L1017", *isoh, 47, 59, "isotropic hardening '" + w + "' is not none, Swift, linear or Hollomon");
        }
        const Line* cinh = ok ? option(b, "cinh:") : nullptr;
        ok = cinh != nullptr;
        if (ok && b.lines.back().word.value == "linear") ok = values(b, {"K___="}, false);
        const Line* vpla = ok ? option(b, "vpla:") : nullptr;
        ok = vpla != nullptr;
        if (ok && b.lines.back().word.value == "power_law") ok = values(b, {"Sref=", "Dref=", "n___="}, false);
      }
    } else if (kind == "VISCO") {
      ok = option(b, "visc:") != nullptr;
      const Line* ani = ok ? option(b, "ani_:", "ani_:") : nullptr;
      ok = ani && anisotropic_values(b, b.lines.back().word.value, *ani, true);
    } else if (kind == "RIGID_THERM") {
      const Line* mode = option(b, "T_ani");
      ok = mode != nullptr;
      if (ok) {
        const std::string m(trim(columns(mode->text, 41, 43)));
        b.lines.back().word.value = m;
        if (m == "ani") ok = values(b, {"PrTC=", "ScTC="}, false) && values(b, {"PDnx=", "PDny="}, false);
        else ok = values(b, {"TCnd="}, false);
        ok = ok && values(b, {"Hspe="}, false) && values(b, {"Eeq_=", "NUeq="}, false);
      }
    } else if (kind == "RIGID_ELEC") {
      ok = values(b, {"ECnd="}, false) && values(b, {"Eel_=", "NUel="}, false);
    } else if (kind == "WS") {
      const Line* name = option(b, "WSlw=");
      ok = name != nullptr;
      if (ok) {
        b.lines.back().word.value = std::string(trim(columns(name->text, 47, 51)));
        ok = values(b, {"WS__=", "WSvr=", "TMlt="}, false) && values(b, {"Tvar=", "WSmx=", "WSmn="}, false);
      }
    } else if (kind == "UMAT") {
      const Line* line = next_line("the user material file name");
      ok = line != nullptr;
      if (ok) {
        BulkLine out;
        out.kind = BulkLine::Kind::option;
        out.label = "file:";
        out.word = Word{std::string(trim(line->text)), reader_.span(*line, 1, static_cast<int>(line->text.size()))};
        b.lines.push_back(out);
      }
    } else if (kind == "BIOT") {
      ok = marker(b, "cpl_:", "cpl_") && values(b, {"BIOT="});
    } else if (kind == "DISCRETE") {
      ok = values(b, {"k1  =", "k2  =", "k3  ="}, false) && values(b, {"c1  =", "c2  =", "c3  ="}, false);
    } else if (kind == "JOINT") {
      const BulkLawKind* k = find_bulk_law_kind(law.law_type.value);
      for (int done = 0; ok && k && done < k->extra; done += 3) ok = values(b, {"p___=", "p___=", "p___="}, false);
    }
    law.blocks.push_back(std::move(b));
    return ok;
  }

  std::optional<BulkLaw> parse_law() {
    const Line* line = next_line("a law line (nickname and law type)");
    if (!line) return std::nullopt;
    BulkLaw law;
    law.nickname = reader_.word(*line, 2, 6);
    law.law_type = reader_.word(*line, 9, 38);
    const BulkLawKind* kind = find_bulk_law_kind(law.law_type.value);
    if (!kind) {
      reader_.report("L1001", *line, 9, 38, "unknown bulk behaviour law '" + law.law_type.value + "'",
                     "bulk laws are RIGID, ELAS, ELAS_PLAS, THERMO_ELAS, ... (docs/diagnostics.md L1001)");
      return std::nullopt;
    }
    switch (kind->first_line) {
      case BulkFirstLine::umas:
        if (columns(line->text, 46, 50) == "field") law.density_field = true;
        else law.density = reader_.real(*line, 46, 59);
        break;
      case BulkFirstLine::values3:
      case BulkFirstLine::joint3:
        for (int k = 0; k < 3; ++k) law.first_line_values.push_back(reader_.real(*line, kValueColumns[k][0], kValueColumns[k][1]));
        break;
    }
    for (std::string_view blk : kind->blocks)
      if (!block(std::string(blk), law)) break;
    return law;
  }

  CardReader reader_;
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
