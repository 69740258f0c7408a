// parse(write(ast)) == ast for generated PTPT3 networks, in both record forms.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>

#include "grammar/ptpt3_network/parser.hpp"
#include "grammar/ptpt3_network/writer.hpp"

namespace lmgc::grammar {
namespace {

rc::Gen<double> finite_real() {
  return rc::gen::suchThat(rc::gen::arbitrary<double>(), [](double x) { return std::isfinite(x); });
}

RC_GTEST_PROP(Ptpt3NetworkRoundTrip, ParseOfWriteIsIdentity, ()) {
  Ptpt3NetworkFile file;
  file.with_parameters = *rc::gen::arbitrary<bool>();
  const int count = *rc::gen::inRange(0, 30);
  for (int k = 0; k < count; ++k) {
    Ptpt3Link link;
    link.candidate = Integer{*rc::gen::inRange<std::int64_t>(1, 1000000)};
    link.antagonist = Integer{*rc::gen::inRange<std::int64_t>(1, 1000000)};
    link.x_periods = Integer{*rc::gen::inRange<std::int64_t>(-2, 3)};
    link.y_periods = Integer{*rc::gen::inRange<std::int64_t>(-2, 3)};
    link.loop = Integer{*rc::gen::inRange<std::int64_t>(0, 2)};
    link.reference_length = Real{*finite_real()};
    if (file.with_parameters) {
      link.surface = Real{*finite_real()};
      link.mass = Real{*finite_real()};
    }
    file.links.push_back(link);
  }
  const std::string text = write_ptpt3_network(file);
  DiagnosticSink sink;
  const Ptpt3NetworkFile parsed = parse_ptpt3_network(SourceText("PTPT3_NETWORK.DAT", text), sink);
  RC_ASSERT(sink.items().empty());
  // An empty file cannot tell its form (it reads as plain); any other tells it by its first record.
  if (file.links.empty()) file.with_parameters = false;
  RC_ASSERT(parsed.links == file.links);
  RC_ASSERT(parsed.with_parameters == file.with_parameters);
  RC_ASSERT(write_ptpt3_network(parsed) == text);
}

}  // namespace
}  // namespace lmgc::grammar
