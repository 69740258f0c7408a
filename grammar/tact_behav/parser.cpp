#include "grammar/tact_behav/parser.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"
#include "grammar/tact_behav/law_catalogue.hpp"
#include "grammar/tact_behav/see_table.hpp"

namespace lmgc::grammar {
namespace {

// Columns of the value fields of a law line (docs/lmgc90-facts/contact-laws.md §1.1): read_single takes
// (7X,D14.7) from columns 39-59, read_double 2(7X,D14.7) from 39-80.
constexpr int kValueColumns[2][2] = {{46, 59}, {67, 80}};

bool is_card_keyword(std::string_view keyword) {
  return keyword == "behav" || keyword == "seety";
}

int line_end_column(const Line& line) {
  const auto size = static_cast<int>(std::min<std::size_t>(line.text.size(), kRecordLength));
  return size < 1 ? 1 : size;
}

std::string padded5(const std::string& text) {
  std::string result = text.substr(0, 5);
  result.resize(5, ' ');
  return result;
}

class TactBehavParser {
 public:
  TactBehavParser(const SourceText& source, DiagnosticSink& sink)
      : reader_(source, sink), accounted_(source.lines().size(), false) {}

  TactBehavFile run() {
    TactBehavFile file;
    if (!reader_.check_records()) return file;
    read_laws(file);
    // LMGC90 rewinds and fishes for `seety` independently of the law pass (docs/lmgc90-facts/datbox-inputs.md
    // §0).
    reader_.rewind_to(0);
    reader_.skip_insignificant();
    read_sees(file);
    check_duplicate_sees(file);
    report_unread_lines();
    return file;
  }

 private:
  const Line& take() {
    accounted_[reader_.position()] = true;
    return reader_.next();
  }

  // docs/lmgc90-facts/contact-laws.md §1.1. A card starts at a line whose columns 2-6 are `behav`; the
  // next significant line is the law line, whatever it holds.
  void read_laws(TactBehavFile& file) {
    while (!reader_.at_end()) {  // bounded: every iteration consumes a line
      if (keyword_of(reader_.peek().text) != "behav") {
        reader_.next();
        continue;
      }
      take();
      if (reader_.at_end()) {
        reader_.report_at_end(
            "L1006", "file ends after '$behav' where the law line (nickname, law keyword) is expected");
        return;
      }
      read_law(file, take());
    }
  }

  void read_law(TactBehavFile& file, const Line& law_line) {
    TactLaw law;
    law.nickname = reader_.word(law_line, 2, 6);
    law.keyword = reader_.word(law_line, 9, 38);
    const LawKind* kind = find_law_kind(law.keyword.value);
    if (kind == nullptr || !kind->readable) {
      const std::string message =
          law.keyword.value.empty()
              ? std::string("law keyword is missing in columns 9-38 of law '") + law.nickname.value + "'"
              : "unknown contact law '" + law.keyword.value + "' (law '" + law.nickname.value + "')";
      reader_.report("L1001", law_line, 9, 38, message, law_keyword_hint(law.keyword.value));
      // LMGC90 stops here; skip the card's value lines without reporting them again.
      while (!reader_.at_end() && !is_card_keyword(keyword_of(reader_.peek().text))) take();
      return;
    }
    law.parameters.assign(kind->parameters.size(), Real{});
    const Line* current = &law_line;
    int current_line = 0;
    for (const LawField& field : kind->reads) {
      while (current_line < field.line) {
        if (reader_.at_end()) {
          reader_.report_at_end("L1006",
                                "file ends inside law '" + law.nickname.value + "' (" + law.keyword.value +
                                    "): " + std::to_string(kind->read_line_count() - current_line - 1) +
                                    " more line(s) of values expected");
          file.laws.push_back(std::move(law));
          return;
        }
        const Line& next = take();
        const std::string_view keyword = keyword_of(next.text);
        if (is_card_keyword(keyword))
          reader_.report("L1019", next, 2, 6,
                         "'$" + std::string(keyword) + "' line is read as a value line of law '" +
                             law.nickname.value + "' (" + law.keyword.value + "), which needs " +
                             std::to_string(kind->read_line_count()) +
                             " lines; LMGC90 reads its columns 46-59/67-80 as values" +
                             (keyword == "behav" ? std::string(" and loses this card")
                                                 : std::string(" (its see pass still reads the block)")),
                         "give law '" + law.nickname.value + "' all its value lines (contact-laws.md §0)");
        current = &next;
        ++current_line;
      }
      for (int slot = 0; slot < field.count; ++slot) {
        const std::size_t index = static_cast<std::size_t>(field.first) + static_cast<std::size_t>(slot);
        if (index < law.parameters.size())
          law.parameters[index] = reader_.real(*current, kValueColumns[slot][0], kValueColumns[slot][1]);
      }
    }
    file.laws.push_back(std::move(law));
  }

  // docs/lmgc90-facts/datbox-inputs.md §3, contact-laws.md §1.2.
  void read_sees(TactBehavFile& file) {
    while (!reader_.at_end()) {
      if (keyword_of(reader_.peek().text) != "seety") {
        reader_.next();
        continue;
      }
      take();
      if (reader_.at_end()) {
        reader_.report_at_end("L1006", "file ends after '$seety' where the title line is expected");
        return;
      }
      const Line& title = reader_.peek();
      if (columns(title.text, 2, 6) != "cdbdy" && looks_like_see_data(title)) {
        // LMGC90 skips the title line whatever it holds: here it would swallow this data line.
        reader_.report("L1012", title, 2, 6,
                       "title line of '$seety' is missing: LMGC90 skips this data line as the title",
                       "put ' cdbdy  cdtac  cdcol  behav  anbdy  antac  ancol       alert' after '$seety'");
      } else {
        take();
        if (reader_.at_end()) {
          reader_.report_at_end("L1006",
                                "file ends after the '$seety' title line where the data line is expected");
          return;
        }
      }
      // A keyword line where the data line is expected: LMGC90 would read its columns as a pair and
      // a law ('$behav  lawty' as candidate 'behav', law 'lawty'...).
      if (reader_.peek().text.starts_with("$")) {
        reader_.report(
            "L1013", reader_.peek(), 1, 6,
            "keyword line where the data line of '$seety' is expected; LMGC90 would read it as a pair",
            "give the '$seety' block its data line");
        continue;
      }
      file.sees.push_back(read_see_data(take()));
    }
  }

  bool looks_like_see_data(const Line& line) {
    const std::string_view alert = columns(line.text, 55, 68);
    if (trim(alert).empty() || trim(columns(line.text, 23, 27)).empty()) return false;
    return read_fortran_real(alert, 7).error == NumberError::none;
  }

  SeeEntry read_see_data(const Line& line) {
    SeeEntry see;
    see.candidate_body = reader_.word(line, 2, 6);
    see.candidate_contactor = reader_.word(line, 9, 13);
    see.candidate_colour = reader_.word(line, 16, 20);
    see.law_nickname = reader_.word(line, 23, 27);
    see.antagonist_body = reader_.word(line, 30, 34);
    see.antagonist_contactor = reader_.word(line, 37, 41);
    see.antagonist_colour = reader_.word(line, 44, 48);
    see.alert = reader_.real(line, 55, 68);
    if (!reader_.at_end() && columns(reader_.peek().text, 1, 1) == "+")
      see.global_alert = reader_.real(take(), 55, 68);
    return see;
  }

  // docs/lmgc90-facts/contact-laws.md §1.2 (remove_bad_see_links).
  void check_duplicate_sees(const TactBehavFile& file) {
    const std::vector<std::size_t> duplicate_of = see_duplicate_of(file.sees);
    for (std::size_t j = 0; j < file.sees.size(); ++j) {
      if (duplicate_of[j] == kNoDuplicate) continue;
      const SeeEntry& kept = file.sees[duplicate_of[j]];
      const SeeEntry& dropped = file.sees[j];
      const Location where{reader_.source().path(), dropped.law_nickname.span};
      const std::string earlier = "the see entry of line " + std::to_string(kept.law_nickname.span.line);
      if (padded5(kept.law_nickname.value) != padded5(dropped.law_nickname.value))
        reader_.sink().report("L2015", where,
                              "see entry names the same pair as " + earlier + " with another law ('" +
                                  dropped.law_nickname.value + "' vs '" + kept.law_nickname.value +
                                  "'); LMGC90 stops",
                              "keep one entry per pair (candidate and antagonist may be swapped)");
      else
        reader_.sink().report("L1019", where, "see entry repeats " + earlier + "; LMGC90 drops it");
    }
  }

  // Significant lines that neither pass read: LMGC90 skips them silently.
  void report_unread_lines() {
    const auto& lines = reader_.source().lines();
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (accounted_[i] || is_skipped_line(lines[i].text)) continue;
      const Line& line = lines[i];
      const std::string_view text = trim(line.text);
      std::string message = "line is outside every '$behav' card and '$seety' block; LMGC90 skips it";
      std::string hint;
      if (text.starts_with("$behav") || text.starts_with("$seety")) {
        message =
            "'" + std::string(text.substr(0, 6)) + "' is not in columns 1-6; LMGC90 does not see the card";
        hint = "LMGC90 tests columns 2-6 for the keyword";
      } else if (const LawKind* kind = find_law_kind(std::string(trim_right(columns(line.text, 9, 38))));
                 kind != nullptr && kind->readable) {
        message =
            "law line of '" + std::string(trim_right(columns(line.text, 2, 6))) + "' (" +
            std::string(kind->keyword) +
            ") has no '$behav' line before it (or that line was read as a value line); LMGC90 skips the law";
      }
      reader_.report("L1019", line, 1, line_end_column(line), message, hint);
    }
  }

  CardReader reader_;
  std::vector<bool> accounted_;  // per record: read by the law pass or the see pass
};

}  // namespace

TactBehavFile parse_tact_behav(const SourceText& source, DiagnosticSink& sink) {
  return TactBehavParser(source, sink).run();
}

}  // namespace lmgc::grammar
