#include "grammar/ptpt3_network/parser.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "grammar/common/card_reader.hpp"
#include "grammar/common/fortran_number.hpp"
#include "grammar/common/list_directed.hpp"

namespace lmgc::grammar {
namespace {

constexpr std::array<const char*, 6> kPlainItems = {"icdtac", "iantac", "xper", "yper", "iloop", "nonuc0"};
constexpr std::array<const char*, 8> kParameterItems = {"icdtac", "iantac", "xper",   "yper",
                                                        "iloop",  "surf",   "nonuc0", "mass"};

}  // namespace

Ptpt3NetworkFile parse_ptpt3_network(const SourceText& source, DiagnosticSink& sink) {
  CardReader reader(source, sink);
  Ptpt3NetworkFile file;
  // An empty network is LMGC90's "no link" (its read loop ends at once).
  if (!reader.check_records(CardReader::Empty::allowed)) return file;
  bool form_known = false;
  for (const Line& line : source.lines()) {
    const std::vector<Token> tokens = list_tokens(line.text);
    if (tokens.empty()) continue;  // list-directed input skips blank records
    if (!form_known) {
      file.with_parameters = tokens.size() >= kParameterItems.size();
      form_known = true;
    }
    const std::size_t wanted = file.with_parameters ? kParameterItems.size() : kPlainItems.size();
    const auto name = [&](std::size_t i) {
      return std::string(file.with_parameters ? kParameterItems[i] : kPlainItems[i]);
    };
    if (tokens.size() < wanted) {
      const int column = static_cast<int>(std::min(line.text.size(), kRecordLength)) + 1;
      reader.report("L1015", line, column, column,
                    name(tokens.size()) + " is missing: this file's records have " + std::to_string(wanted) +
                        " items (" +
                        (file.with_parameters ? "icdtac iantac xper yper iloop surf nonuc0 mass"
                                              : "icdtac iantac xper yper iloop nonuc0") +
                        ", the form set by its first record)");
      continue;
    }
    Ptpt3Link link;
    bool ok = true;
    std::array<Integer*, 5> integers = {&link.candidate, &link.antagonist, &link.x_periods, &link.y_periods,
                                        &link.loop};
    for (std::size_t i = 0; i < integers.size() && ok; ++i) {
      const Token& token = tokens[i];
      const auto result = read_list_directed_integer(token.text);
      if (!result || result->error != NumberError::none) {
        const bool range = result && result->error == NumberError::out_of_range;
        reader.report(range ? "L1003" : "L1004", line, token.first, token.last,
                      name(i) + " '" + std::string(token.text) + "' is not " +
                          (range ? "a representable integer" : "an integer"));
        ok = false;
        break;
      }
      *integers[i] = Integer{result->value, reader.span(line, token.first, token.last)};
    }
    std::array<Real, 3> reals{};
    for (std::size_t i = integers.size(); i < wanted && ok; ++i) {
      const Token& token = tokens[i];
      const auto result = read_list_directed_real(token.text);
      if (!result || result->error != NumberError::none) {
        const bool range = result && result->error == NumberError::out_of_range;
        reader.report(range ? "L1003" : "L1002", line, token.first, token.last,
                      name(i) + " '" + std::string(token.text) + "' is not a " +
                          (range ? "representable " : "") + "real number");
        ok = false;
        break;
      }
      reals[i - integers.size()] = Real{result->value, reader.span(line, token.first, token.last)};
    }
    if (!ok) continue;
    if (tokens.size() > wanted)
      reader.report("L1019", line, tokens[wanted].first, tokens.back().last,
                    "text after the link's " + std::to_string(wanted) +
                        " items is ignored by LMGC90's list-directed read");
    if (file.with_parameters) {
      link.surface = reals[0];
      link.reference_length = reals[1];
      link.mass = reals[2];
    } else {
      link.reference_length = reals[0];
    }
    file.links.push_back(link);
  }
  return file;
}

}  // namespace lmgc::grammar
