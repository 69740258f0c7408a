#include "grammar/drv_dof/parser.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_format.hpp"
#include "grammar/common/fortran_number.hpp"
#include "grammar/common/list_directed.hpp"

namespace lmgc::grammar {
namespace {

// The six D14.7 fields of a dof line (docs/lmgc90-facts/datbox-inputs.md §5).
constexpr int kParameterColumns[6][2] = {{15, 28}, {30, 43}, {45, 58}, {60, 73}, {75, 88}, {90, 103}};

int line_end_column(const Line& line) {
  const auto size = static_cast<int>(std::min<std::size_t>(line.text.size(), kRecordLength));
  return size < 1 ? 1 : size;
}

bool is_end_of_block(std::string_view keyword) {
  return keyword == "$$$$$";
}

bool is_dof_keyword(std::string_view keyword) {
  const std::string_view k = trim_right(keyword);
  return k == "vlocy" || k == "force" || k == "temp" || k == "flux";
}

// Which dof keywords a block accepts: mechanical (rigid, MECAx), thermal (THERM), both (POROx,
// whose exact keyword set is not in the spec).
bool keyword_allowed(std::string_view keyword, std::string_view model) {
  const std::string_view k = trim_right(keyword);
  const bool mechanical = k == "vlocy" || k == "force";
  if (model == "THERM") return !mechanical;
  if (model == "POROx") return true;
  return mechanical;
}

// Number of dofs of a node type `NOkxx` (k in 1..6), 0 when the type is not of that form.
int node_dof_count(std::string_view type) {
  if (type.size() != 5 || type[0] != 'N' || type[1] != 'O' || type[3] != 'x' || type[4] != 'x') return 0;
  if (type[2] < '1' || type[2] > '6') return 0;
  return type[2] - '0';
}

class DrvDofParser {
 public:
  DrvDofParser(const SourceText& source, DiagnosticSink& sink) : reader_(source, sink) {}

  DrvDofFile run() {
    DrvDofFile file;
    if (!reader_.check_records(CardReader::Empty::allowed)) return file;
    // Bounded: every iteration consumes at least one line.
    while (!reader_.at_end()) {
      const Line& line = reader_.peek();
      if (keyword_of(line.text) == "bdyty") {
        reader_.next();
        parse_block(file);
        continue;
      }
      reader_.report("L1019", line, 1, line_end_column(line),
                     "line outside any '$bdyty' block is skipped by LMGC90");
      reader_.next();
    }
    return file;
  }

 private:
  // Skips to the end of a block LMGC90 cannot read: past its `$$$$$$`, or up to the next `$bdyty`.
  void skip_block() {
    while (!reader_.at_end()) {
      const std::string_view keyword = keyword_of(reader_.peek().text);
      if (keyword == "bdyty") return;
      reader_.next();
      if (is_end_of_block(keyword)) return;
    }
  }

  void parse_block(DrvDofFile& file) {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends after '$bdyty' where a body line is expected");
      return;
    }
    const Line& body_line = reader_.next();
    DrvDofBody body;
    body.body_type = reader_.word(body_line, 2, 6);
    const std::string& type = body.body_type.value;
    if (type != "RBDY2" && type != "RBDY3" && type != "MAILx") {
      reader_.report("L1001", body_line, 2, 6, "unknown body type '" + type + "' in DRV_DOF.DAT",
                     "expected RBDY2, RBDY3 or MAILx in columns 2-6");
      skip_block();
      return;
    }
    const bool rigid = type != "MAILx";
    // spec §5: rigid rank I7 in 9-15, MAILx rank I7 in 7-13.
    body.rank = rigid ? reader_.integer(body_line, 9, 15) : reader_.integer(body_line, 7, 13);
    if (body.rank.value < 1)
      reader_.report("L1003", body_line, rigid ? 9 : 7, rigid ? 15 : 13,
                     "body rank " + std::to_string(body.rank.value) + " is not a positive number");
    if (!rigid && !parse_model(body)) {
      skip_block();
      file.bodies.push_back(std::move(body));
      return;
    }
    parse_groups(body, rigid);
    file.bodies.push_back(std::move(body));
  }

  // `$model` then ` MECAx` / ` THERM` / ` POROx` (spec §5).
  bool parse_model(DrvDofBody& body) {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends where '$model' is expected");
      return false;
    }
    const Line& model_keyword = reader_.peek();
    if (keyword_of(model_keyword.text) != "model") {
      reader_.report("L1012", model_keyword, 1, 6, "'$model' line is missing after the MAILx body line");
      return false;
    }
    reader_.next();
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends where the model line (MECAx, THERM, POROx) is expected");
      return false;
    }
    const Line& model_line = reader_.next();
    body.model = reader_.word(model_line, 2, 6);
    const std::string& model = body.model.value;
    if (model != "MECAx" && model != "THERM" && model != "POROx") {
      reader_.report("L1017", model_line, 2, 6, "model '" + model + "' is not MECAx, THERM or POROx");
      return false;
    }
    return true;
  }

  void parse_groups(DrvDofBody& body, bool rigid) {
    while (true) {
      if (reader_.at_end()) {
        reader_.report_at_end("L1005", "block of " + body.body_type.value + " " +
                                           std::to_string(body.rank.value) + " is not closed by '$$$$$$'");
        break;
      }
      const Line& line = reader_.peek();
      const std::string_view keyword = keyword_of(line.text);
      if (is_end_of_block(keyword)) {
        reader_.next();
        break;
      }
      if (keyword == "bdyty") {
        reader_.report("L1005", line, 1, 6,
                       "block of " + body.body_type.value + " " + std::to_string(body.rank.value) +
                           " is not closed by '$$$$$$' before the next '$bdyty'");
        break;
      }
      if (keyword == "nodty") {
        reader_.next();
        const std::size_t before = body.nodes.size();
        parse_node_group(body, rigid);
        if (rigid && before == 1 && body.nodes.size() == 2) {
          const SourceSpan& where = body.nodes.back().node_type.span;
          reader_.sink().report("L1014", Location{reader_.source().path(), where},
                                body.body_type.value + " has one node; LMGC90 reads only the first '$nodty'");
        }
        continue;
      }
      if (body.nodes.empty() && columns(line.text, 2, 3) == "NO") {
        // A node line without its `$nodty`: report, then read the group so parsing goes on.
        reader_.report("L1012", line, 1, 6, "'$nodty' line is missing before the node line");
        parse_node_group(body, rigid);
        continue;
      }
      reader_.report("L1001", line, 2, 6, "unknown keyword '" + std::string(keyword) + "' in a DRV_DOF block",
                     "expected '$nodty', a dof line (vlocy, force, temp, flux) or '$$$$$$'");
      reader_.next();
    }
  }

  void parse_node_group(DrvDofBody& body, bool rigid) {
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends where a node line is expected after '$nodty'");
      return;
    }
    const Line& node_line = reader_.next();
    DrvDofNode node;
    node.node_type = reader_.word(node_line, 2, 6);
    int dof_count = node_dof_count(node.node_type.value);
    if (dof_count == 0) {
      reader_.report("L1001", node_line, 2, 6, "unknown node type '" + node.node_type.value + "'",
                     "node types are NO1xx ... NO6xx in columns 2-6");
    } else if (rigid) {
      // LMGC90 checks only that the name is a node type, keeps it nowhere, and bounds the dofs by the
      // body's own node (read_driven_dof of mod_RBDY2 / mod_RBDY3): NO3xx for RBDY2, NO6xx for RBDY3.
      const std::string expected = body.body_type.value == "RBDY2" ? "NO3xx" : "NO6xx";
      if (node.node_type.value != expected)
        reader_.report("L1023", node_line, 2, 6,
                       "LMGC90 ignores this node type: the dofs of an " + body.body_type.value +
                           " body are those of its " + expected + " node (1.." +
                           std::to_string(node_dof_count(expected)) + ")");
      dof_count = node_dof_count(expected);
    }
    if (body.model.value == "THERM") dof_count = 1;  // one temperature per node
    if (body.model.value == "POROx") dof_count = 0;  // dof set not in the spec: no bound check
    // spec §5: rigid node number I5 in 9-13 (must be 1); MAILx node number I7 in 7-13.
    if (rigid) {
      node.number = reader_.integer(node_line, 9, 13);
      if (node.number.value != 1)
        reader_.report("L1003", node_line, 9, 13,
                       "node number of a rigid body must be 1, not " + std::to_string(node.number.value));
    } else {
      node.number = reader_.integer(node_line, 7, 13);
      if (node.number.value < 1)
        reader_.report("L1003", node_line, 7, 13,
                       "node number " + std::to_string(node.number.value) + " is not a positive number");
    }
    parse_dofty(body.model.value);
    parse_dofs(node, body.model.value, dof_count);
    body.nodes.push_back(std::move(node));
  }

  // A line that ends a node's dof list without being an error there: the end of the block, the
  // next node group, a keyword line or a node line.
  static bool ends_dof_list(const Line& line) {
    if (!line.text.empty() && line.text[0] == '$') return true;
    const std::string_view keyword = keyword_of(line.text);
    return is_end_of_block(keyword) || keyword == "bdyty" || keyword == "nodty" || keyword == "model" ||
           keyword == "dofty" || columns(line.text, 2, 3) == "NO";
  }

  // A dof number written wholly outside its columns 9-13 (in 7-8 or from 14): LMGC90 reads the
  // blank field as 0. Reports L1011 at the written number; true when reported.
  bool report_number_outside(const Line& line) {
    if (!trim(columns(line.text, 9, 13)).empty()) return false;
    const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
    int first = 0, last = 0;
    const std::string_view left = columns(line.text, 7, 8);
    for (int i = 0; i < static_cast<int>(left.size()); ++i) {
      if (!is_digit(left[static_cast<std::size_t>(i)])) continue;
      if (first == 0) first = 7 + i;
      last = 7 + i;
    }
    if (first == 0) {
      const std::string_view right = columns(line.text, 14, 14);
      if (right.empty() || !is_digit(right[0])) return false;
      first = last = 14;
    }
    const std::string written(trim(columns(line.text, first, last)));
    reader_.report("L1011", line, first, last,
                   "dof number '" + written + "' is written in " +
                       (first == last ? "column " + std::to_string(first)
                                      : "columns " + std::to_string(first) + "-" + std::to_string(last)) +
                       ", outside columns 9-13; LMGC90 reads the blank columns 9-13 as dof 0 "
                       "and stops ('dof number 0 does not belong')",
                   "write the dof number in columns 9-13, right-justified");
    return true;
  }

  // `$dofty` (rest of the line is a comment) or the guide's `$dofyty` + template line.
  void parse_dofty(std::string_view model) {
    (void)model;
    if (reader_.at_end()) {
      reader_.report_at_end("L1006", "file ends where '$dofty' is expected");
      return;
    }
    const Line& line = reader_.peek();
    const std::string_view keyword = keyword_of(line.text);
    if (keyword == "dofty") {
      reader_.next();
      return;
    }
    if (keyword == "dofyt") {
      reader_.report(
          "L1018", line, 1, 7, "'$dofyty' (user's guide) read as '$dofty'",
          "LMGC90 reads '$dofty' with the template on the same line; with '$dofyty' it reads no dof");
      reader_.next();
      if (!reader_.at_end()) {
        const std::string_view next = keyword_of(reader_.peek().text);
        if (!is_dof_keyword(next) && !is_end_of_block(next) && next != "nodty" && next != "bdyty")
          reader_.next();
      }
      return;
    }
    reader_.report("L1012", line, 1, 6, "'$dofty' line is missing after the node line");
  }

  void parse_dofs(DrvDofNode& node, std::string_view model, int dof_count) {
    while (!reader_.at_end()) {
      const Line& line = reader_.peek();
      const std::string_view keyword = keyword_of(line.text);
      if (!is_dof_keyword(keyword)) {
        if (ends_dof_list(line)) return;
        // LMGC90 ends the dof list here (BACKSPACE), then reads this line again as a node line
        // and stops ("nodty ... unknown"): one error. The dof lines after it are read on as
        // dofs of this node, so that they are not reported again.
        reader_.report("L1001", line, 2, 6,
                       "unknown dof keyword '" + std::string(keyword) +
                           "'; LMGC90 ends the dof list at this line and stops on it ('nodty " +
                           std::string(keyword) + " unknown')",
                       model == "THERM" ? "THERM dof keywords are temp and flux, in columns 2-6"
                                        : "dof keywords are vlocy and force, in columns 2-6");
        reader_.next();
        continue;
      }
      reader_.next();
      if (!keyword_allowed(keyword, model)) {
        reader_.report("L1017", line, 2, 6,
                       "dof kind '" + std::string(trim_right(keyword)) + "' does not belong to a " +
                           (model.empty() ? std::string("rigid") : std::string(model)) + " body");
        continue;
      }
      DrivenDof dof;
      dof.kind = reader_.word(line, 2, 6);
      dof.dof = reader_.integer(line, 9, 13);
      const bool bounded = dof_count > 0;
      // A number written outside columns 9-13 is reported as such, not as "dof 0".
      const bool outside = report_number_outside(line);
      if (!outside && (dof.dof.value < 1 || (bounded && dof.dof.value > dof_count)))
        reader_.report("L1003", line, 9, 13,
                       "dof number " + std::to_string(dof.dof.value) + " is outside 1.." +
                           (bounded ? std::to_string(dof_count) : std::string("n")) + " for node type " +
                           node.node_type.value);
      if (columns(line.text, 15, 23) == "evolution") {
        dof.uses_evolution = true;
        const std::string_view name = trim(columns(line.text, 25, 64));
        dof.evolution_file = Word{std::string(name), reader_.span(line, 25, 64)};
        if (name.empty())
          reader_.report("L1015", line, 25, 64, "evolution file name is missing in columns 25-64");
      } else {
        for (int i = 0; i < 6; ++i)
          dof.parameters[static_cast<std::size_t>(i)] =
              reader_.real(line, kParameterColumns[i][0], kParameterColumns[i][1]);
      }
      node.dofs.push_back(std::move(dof));
    }
  }

  CardReader reader_;
};

}  // namespace

DrvDofFile parse_drv_dof(const SourceText& source, DiagnosticSink& sink) {
  return DrvDofParser(source, sink).run();
}

EvolutionFile parse_evolution(const SourceText& source, DiagnosticSink& sink) {
  CardReader reader(source, sink);
  EvolutionFile file;
  if (!reader.check_records()) return file;
  const Line* last_line = nullptr;
  for (const Line& line : source.lines()) {
    const std::vector<Token> tokens = list_tokens(line.text);
    if (tokens.empty()) continue;  // list-directed input skips blank records
    last_line = &line;
    Real values[2];
    bool ok = true;
    for (std::size_t i = 0; i < 2 && ok; ++i) {
      if (i >= tokens.size()) {
        const int column = static_cast<int>(std::min(line.text.size(), kRecordLength)) + 1;
        reader.report("L1015", line, column, column,
                      "the value of the pair is missing (one pair per line: t v)");
        ok = false;
        break;
      }
      const Token& token = tokens[i];
      const auto result = read_list_directed_real(token.text);
      if (!result || result->error != NumberError::none || std::abs(result->value) > kLargestMagnitude) {
        const bool range = result && result->error != NumberError::malformed;
        reader.report(range ? "L1003" : "L1002", line, token.first, token.last,
                      "'" + std::string(token.text) + "' is not a " + (range ? "representable " : "") +
                          "real number (evolution files hold only 't v' pairs, no comments)");
        ok = false;
        break;
      }
      values[i] = Real{result->value, reader.span(line, token.first, token.last)};
    }
    if (!ok) continue;
    if (tokens.size() > 2)
      reader.report("L1019", line, tokens[2].first, tokens.back().last,
                    "text after the pair is ignored by LMGC90's list-directed read");
    if (!file.points.empty() && !(values[0].value > file.points.back().time.value)) {
      reader.report("L2016", line, tokens[0].first, tokens[0].last,
                    "time " + std::string(tokens[0].text) + " is not greater than the previous time",
                    "times of an evolution file must increase strictly");
      continue;
    }
    file.points.push_back(EvolutionPoint{values[0], values[1]});
  }
  // (Lines that hold no value at all, blank or cut by a '/', count as none.)
  if (file.points.size() < 2) {
    const std::string message =
        "an evolution file needs at least two 't v' pairs, found " + std::to_string(file.points.size());
    if (last_line != nullptr)
      reader.report("L1014", *last_line, 1,
                    static_cast<int>(std::max<std::size_t>(1, last_line->text.size())), message);
    else
      reader.report_at_end("L1014", message);
  }
  return file;
}

}  // namespace lmgc::grammar
