#include "grammar/dof/parser.hpp"

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"

namespace lmgc::grammar {
namespace {

// Value columns of a node line and its continuation lines (state-and-outputs.md §1.3).
constexpr int kValueColumns[3][2] = {{35, 48}, {56, 69}, {77, 90}};

bool is_dashed_line(std::string_view text) {
  return text.size() >= 3 && text.substr(0, 3) == "!--";
}

bool is_rigid_part_line(std::string_view text) {
  return text.substr(0, std::min<std::size_t>(text.size(), 11)) == "!rigid part";
}

int node_value_count(std::string_view type) {
  if (type.size() != 5 || type[0] != 'N' || type[1] != 'O' || type[3] != 'x' || type[4] != 'x') return 0;
  if (type[2] < '1' || type[2] > '6') return 0;
  return type[2] - '0';
}

int line_end_column(const Line& line) {
  return std::max(1, static_cast<int>(std::min<std::size_t>(line.text.size(), kRecordLength)));
}

class DofParser {
 public:
  DofParser(const SourceText& source, DiagnosticSink& sink) : lines_(source.lines()), reader_(source, sink) {}

  DofFile run() {
    DofFile file;
    if (!reader_.check_records()) return file;
    parse_header(file);
    DofSection current;
    bool header_dash_pending = steps_found_;
    bool any_body = false;
    while (index_ < lines_.size()) {  // every iteration consumes at least one line
      const Line& line = lines_[index_];
      if (is_dashed_line(line.text)) {
        ++index_;
        if (header_dash_pending && !any_body) {
          header_dash_pending = false;  // the header's own dashed line (line 6)
          continue;
        }
        current.closed = true;
        file.sections.push_back(std::move(current));
        current = DofSection{};
        continue;
      }
      if (is_skipped_line(line.text)) {
        ++index_;
        continue;
      }
      const std::string_view keyword = keyword_of(line.text);
      if (keyword == "bdyty") {
        ++index_;
        header_dash_pending = false;
        any_body = true;
        if (auto body = parse_body()) current.bodies.push_back(std::move(*body));
        continue;
      }
      if (keyword == "steps" && index_ == steps_index_) {
        ++index_;
        continue;
      }
      if (keyword == "steps") {
        reader_.report("L1013", line, 1, 6, "second '$steps' header");
      } else {
        reader_.report("L1019", line, 1, line_end_column(line),
                       "line outside any '$bdyty' block is skipped by LMGC90");
      }
      ++index_;
    }
    if (!current.bodies.empty()) {
      current.closed = false;
      file.sections.push_back(std::move(current));
    }
    return file;
  }

 private:
  // `$steps` (cols 2-6 `steps`): step I7 at 9-15, time D14.7 at 35-48 (state-and-outputs.md §1.2).
  void parse_header(DofFile& file) {
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      if (is_skipped_line(lines_[i].text) || keyword_of(lines_[i].text) != "steps") continue;
      const Line& line = lines_[i];
      file.step = reader_.integer(line, 9, 15);
      file.time = reader_.real(line, 35, 48, 7, false);
      check_time_spill(line, file.time);
      steps_found_ = true;
      steps_index_ = i;
      return;
    }
    for (const Line& line : lines_) {
      if (is_skipped_line(line.text)) continue;
      reader_.report("L1012", line, 1, 6, "the '$steps' header line is missing",
                     "a DOF file starts with '$steps      0                time= 0.0000000D+00'");
      return;
    }
  }

  // The header time is often shifted one or two columns left (3D examples, datbox-inputs.md §6):
  // LMGC90 then loses only a leading '0' and reads the intended value. Report L1011 only when
  // the whole number around columns 35-48 reads differently from what LMGC90 reads.
  void check_time_spill(const Line& line, const Real& time) {
    const std::string_view text = line.text.substr(0, std::min(line.text.size(), kRecordLength));
    if (text.size() < 35) return;
    auto is_number_char = [](char c) {
      return (c >= '0' && c <= '9') || c == '.' || c == 'D' || c == 'd' || c == 'E' || c == 'e' || c == '+' ||
             c == '-';
    };
    std::size_t begin = 34;  // 0-based column 35
    while (begin < text.size() && begin < 48 && text[begin] == ' ') ++begin;
    if (begin >= text.size() || begin >= 48) return;
    while (begin > 0 && is_number_char(text[begin - 1])) --begin;
    std::size_t end = begin;
    while (end < text.size() && is_number_char(text[end])) ++end;
    if (begin >= 34 && end <= 48) return;  // the number sits inside its field
    const RealResult whole = read_fortran_real(text.substr(begin, end - begin), 7);
    if (whole.error == NumberError::none && whole.value == time.value) return;
    reader_.report("L1011", line, 35, 48,
                   "time '" + std::string(text.substr(begin, end - begin)) + "' spills out of columns 35-48",
                   "align the time on columns 35-48 (LMGC90 reads only those columns)");
  }

  // Index of the next significant line from index_ (comments and blanks skipped), or size.
  std::size_t next_significant(std::size_t from) const {
    while (from < lines_.size() && is_skipped_line(lines_[from].text)) ++from;
    return from;
  }

  // Skips to past the `$$$$$` of an unreadable body, or up to the next `$bdyty`.
  void skip_body() {
    while (index_ < lines_.size()) {
      const std::string_view keyword = keyword_of(lines_[index_].text);
      if (keyword == "bdyty" && !is_skipped_line(lines_[index_].text)) return;
      ++index_;
      if (keyword == "$$$$$") return;
    }
  }

  // The next significant line, consumed; nullptr (after L1006) at the end of the file.
  const Line* take(const std::string& what) {
    const std::size_t at = next_significant(index_);
    if (at >= lines_.size()) {
      reader_.report_at_end("L1006", "file ends where " + what + " is expected");
      index_ = lines_.size();
      return nullptr;
    }
    index_ = at + 1;
    return &lines_[at];
  }

  // A keyword line (cols 2-6 == keyword) at the next significant line; L1012 when absent.
  bool expect_keyword(std::string_view keyword, const std::string& what) {
    const std::size_t at = next_significant(index_);
    if (at >= lines_.size()) {
      reader_.report_at_end("L1006", "file ends where " + what + " is expected");
      index_ = lines_.size();
      return false;
    }
    if (keyword_of(lines_[at].text) != keyword) {
      reader_.report("L1012", lines_[at], 1, 6, what + " is missing");
      return false;
    }
    index_ = at + 1;
    return true;
  }

  // Reads `count` values, 3 a line, the first line being `first` (already taken) or, when
  // `first` is null, the next significant lines. Continuation lines must not be keyword lines.
  // `label(i)` is the label LMGC90 writes before value i ("X(1)=", ...): LMGC90 reads by columns and
  // never reads it, so a damaged one is a warning (L1022), the value still read.
  bool read_values(const Line* first, int count, std::vector<Real>& out, const std::string& what,
                   const std::function<std::string(int)>& label) {
    const Line* line = first;
    for (int done = 0; done < count;) {
      if (line == nullptr) {
        const std::size_t at = next_significant(index_);
        if (at >= lines_.size()) {
          reader_.report_at_end("L1006", "file ends where the " + what + " line is expected");
          index_ = lines_.size();
          return false;
        }
        const std::string_view text = lines_[at].text;
        if (text.front() == '$' || !trim(columns(text, 2, 6)).empty()) {
          reader_.report("L1013", lines_[at], 1, 6,
                         "the " + what + " line is expected here (values at columns 35-48, 56-69, 77-90)");
          return false;
        }
        index_ = at + 1;
        line = &lines_[at];
      }
      for (int k = 0; k < 3 && done < count; ++k, ++done) {
        const int label_first = kValueColumns[k][0] - 5;
        const std::string_view written = trim(columns(line->text, label_first, label_first + 4));
        // Alternatives are separated by '|': LMGC90's older writers labelled the third axis 'c'.
        const std::string expected = label(done);
        const bool known = ("|" + expected + "|").find("|" + std::string(written) + "|") != std::string::npos;
        if (!written.empty() && !known)
          reader_.report("L1022", *line, label_first, label_first + 4,
                         "label '" + std::string(written) + "' where LMGC90 writes '" +
                             expected.substr(0, expected.find('|')) +
                             "'; LMGC90 reads the value of columns " + std::to_string(kValueColumns[k][0]) +
                             "-" + std::to_string(kValueColumns[k][1]) + " without reading the label");
        out.push_back(reader_.real(*line, kValueColumns[k][0], kValueColumns[k][1]));
      }
      line = nullptr;
    }
    return true;
  }

  // A node line and its X, V (and a/b/g for NO6xx rigid) lines.
  bool parse_node(DofNode& node, const Line& node_line, bool rigid, std::string_view model) {
    node.node_type = reader_.word(node_line, 2, 6);
    const int count = node_value_count(node.node_type.value);
    if (count == 0) {
      reader_.report("L1001", node_line, 2, 6, "unknown node type '" + node.node_type.value + "'",
                     "node types are NO1xx ... NO6xx in columns 2-6");
      return false;
    }
    node.number = rigid ? reader_.integer(node_line, 9, 13) : reader_.integer(node_line, 7, 13);
    const auto indexed = [](char letter) {
      return [letter](int i) { return std::string(1, letter) + "(" + std::to_string(i + 1) + ")="; };
    };
    if (model == "THERM") return read_values(&node_line, 1, node.x, "temperature", indexed('T'));
    if (!read_values(&node_line, count, node.x, "X", indexed('X'))) return false;
    if (!read_values(nullptr, count, node.v, "V", indexed('V'))) return false;
    if (rigid && count == 6)
      return read_values(nullptr, 9, node.frame, "a/b/g frame", [](int i) {
        const std::string index = "(" + std::to_string(i % 3 + 1) + ")=";
        return i < 6 ? std::string(1, "ab"[i / 3]) + index : "g" + index + "|c" + index;
      });
    return true;
  }

  std::optional<DofBody> parse_body() {
    const Line* body_line = take("a body line");
    if (body_line == nullptr) return std::nullopt;
    DofBody body;
    body.body_type = reader_.word(*body_line, 2, 6);
    const std::string& type = body.body_type.value;
    if (type != "RBDY2" && type != "RBDY3" && type != "MAILx") {
      reader_.report("L1001", *body_line, 2, 6, "unknown body type '" + type + "' in a DOF file",
                     "expected RBDY2, RBDY3 or MAILx in columns 2-6");
      skip_body();
      return std::nullopt;
    }
    const bool rigid = type != "MAILx";
    if (type == "RBDY2") {
      body.number = reader_.integer(*body_line, 9, 15);
    } else if (type == "RBDY3") {
      // datbox-inputs.md §6: the RBDY3 reader reads the body number list-directed from 9-15.
      if (auto number = reader_.list_integer(*body_line, 9, 15, "RBDY3 body number")) body.number = *number;
    } else {
      body.number = reader_.integer(*body_line, 7, 13);
    }
    if (!rigid) {
      if (!expect_keyword("model", "'$model'")) {
        skip_body();
        return body;
      }
      const Line* model_line = take("the model line (MECAx, THERM, POROx)");
      if (model_line == nullptr) return body;
      body.model = reader_.word(*model_line, 2, 6);
      if (body.model.value != "MECAx" && body.model.value != "THERM" && body.model.value != "POROx") {
        reader_.report("L1017", *model_line, 2, 6,
                       "model '" + body.model.value + "' is not MECAx, THERM or POROx");
        skip_body();
        return body;
      }
    }
    if (!expect_keyword("nodty", "'$nodty'")) {
      skip_body();
      return body;
    }
    // Node lines until `$$$$$`: one for a rigid body, any number for MAILx.
    while (true) {
      // The `!rigid part` comment introduces the node of a rigid body attached to a MAILx body.
      std::size_t at = index_;
      bool rigid_part = false;
      while (at < lines_.size() && is_skipped_line(lines_[at].text)) {
        if (!rigid && is_rigid_part_line(lines_[at].text)) rigid_part = true;
        ++at;
      }
      if (at >= lines_.size()) {
        index_ = at;
        reader_.report_at_end("L1005",
                              type + " " + std::to_string(body.number.value) + " is not closed by '$$$$$$'");
        return body;
      }
      const Line& line = lines_[at];
      const std::string_view keyword = keyword_of(line.text);
      if (keyword == "$$$$$") {
        index_ = at + 1;
        return body;
      }
      if (keyword == "bdyty") {
        index_ = at;
        reader_.report("L1005", line, 1, 6,
                       type + " " + std::to_string(body.number.value) +
                           " is not closed by '$$$$$$' before the next '$bdyty'");
        return body;
      }
      index_ = at + 1;
      DofNode node;
      const bool ok =
          parse_node(node, line, rigid || rigid_part, rigid_part ? std::string_view() : body.model.value);
      if (rigid_part) {
        body.rigid_part = std::move(node);
      } else {
        if (rigid && body.nodes.size() == 1)
          reader_.report("L1014", line, 2, 6,
                         type + " has one node; a second node line is not read by LMGC90");
        body.nodes.push_back(std::move(node));
      }
      if (!ok) {
        skip_body();
        return body;
      }
    }
  }

  const std::vector<Line>& lines_;
  CardReader reader_;
  std::size_t index_ = 0;
  bool steps_found_ = false;
  std::size_t steps_index_ = 0;
};

}  // namespace

DofFile parse_dof(const SourceText& source, DiagnosticSink& sink) {
  return DofParser(source, sink).run();
}

}  // namespace lmgc::grammar
