// Round trip of POSTPRO.DAT: parse(write(ast)) == ast for generated command lists.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/postpro/catalogue.hpp"
#include "grammar/postpro/parser.hpp"
#include "grammar/postpro/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

PostproArgument ints(std::initializer_list<std::int64_t> values) {
  PostproArgument a;
  for (auto v : values) a.integers.push_back(Integer{v});
  return a;
}

PostproFile generated() {
  PostproFile f;
  for (int i = 0, n = *rc::gen::inRange(0, 8); i < n; ++i) {
    PostproCommand c;
    c.period = Integer{*rc::gen::inRange(1, 1000)};
    switch (*rc::gen::inRange(0, 5)) {
      case 0: c.name = Word{"SOLVER INFORMATIONS"}; break;
      case 1: c.name = Word{"KINETIC ENERGY"}; break;
      case 2: {
        c.name = Word{*rc::gen::elementOf(std::vector<std::string>{"BODY TRACKING", "TORQUE EVOLUTION"})};
        const int bodies = *rc::gen::inRange(0, 5);
        c.arguments.push_back(ints({bodies}));
        for (int k = 0; k < bodies; ++k) c.arguments.push_back(ints({*rc::gen::inRange(1, 9999999)}));
        break;
      }
      case 3: {
        c.name = Word{"AVERAGE VELOCITY EVOLUTION"};
        PostproArgument a;
        a.word = Word{*test::gen_word()};
        c.arguments.push_back(a);
        break;
      }
      default: {
        c.name = Word{"NEW BOUNDED SETS"};
        const int sets = *rc::gen::inRange(0, 3);
        c.arguments.push_back(ints({sets}));
        for (int k = 0; k < sets; ++k) {
          c.arguments.push_back(ints({*rc::gen::inRange(1, 9999)}));
          c.arguments.push_back(ints({*rc::gen::inRange(1, 9999)}));
        }
      }
    }
    // A colour spelled like a command start would be a different file: avoid "END".
    if (!c.arguments.empty() && c.arguments[0].word.value.rfind("END", 0) == 0) continue;
    if (!c.arguments.empty() && (c.arguments[0].word.value.rfind("STEP", 0) == 0 || c.arguments[0].word.value[0] == '#')) continue;
    f.commands.push_back(c);
  }
  return f;
}

RC_GTEST_PROP(PostproRoundTrip, ParseOfWriteIsIdentity, ()) {
  const PostproFile f = generated();
  DiagnosticSink sink;
  RC_ASSERT(parse_postpro(SourceText("POSTPRO.DAT", write_postpro(f)), sink) == f);
  RC_ASSERT(!sink.has_errors());
}

RC_GTEST_PROP(PostproRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const std::string text = write_postpro(generated());
  DiagnosticSink sink;
  RC_ASSERT(write_postpro(parse_postpro(SourceText("POSTPRO.DAT", text), sink)) == text);
}

}  // namespace
}  // namespace lmgc::grammar
