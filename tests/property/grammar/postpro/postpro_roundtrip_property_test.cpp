// Round trip of POSTPRO.DAT: parse(write(ast)) == ast for command lists generated from the
// catalogue (every command of the 2D or 3D reader, every argument line format).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "grammar/postpro/catalogue.hpp"
#include "grammar/postpro/parser.hpp"
#include "grammar/postpro/writer.hpp"
#include "tests/support/generators.hpp"

namespace lmgc::grammar {
namespace {

using F = PostproLineFormat;

PostproArgument generated_line(const PostproStep& step, bool counts_small) {
  PostproArgument a;
  a.format = step.format;
  auto count_or = [&](std::int64_t low, std::int64_t high) {
    return step.repeat == PostproRepeat::last_integer || counts_small
               ? *rc::gen::inRange<std::int64_t>(0, 4)
               : *rc::gen::inRange<std::int64_t>(low, high);
  };
  switch (step.format) {
    case F::i5:
      a.integers.push_back(Integer{count_or(-9999, 100000)});
      break;
    case F::i7:
      a.integers.push_back(Integer{count_or(-999999, 10000000)});
      break;
    case F::a5:
      a.word = Word{*test::gen_word(5)};
      break;
    case F::a12:
      a.word = Word{*rc::gen::elementOf(
          std::vector<std::string>{"SMOOTH BOX", "ROUGH BOX", "CLUSTER BOX", "COUETTE", "SELECTION"})};
      break;
    case F::i7_x_i3:
      a.integers.push_back(Integer{*rc::gen::inRange<std::int64_t>(-999999, 10000000)});
      a.integers.push_back(Integer{*rc::gen::inRange<std::int64_t>(-99, 1000)});
      break;
    case F::i7_x_i7:
      a.integers.push_back(Integer{*rc::gen::inRange<std::int64_t>(-999999, 10000000)});
      a.integers.push_back(Integer{count_or(-999999, 10000000)});
      break;
    case F::list_integer:
      a.integers.push_back(Integer{count_or(-1000000000, 1000000000)});
      break;
    case F::list_integer_pair:
    case F::list_integer_quad:
      for (int k = 0; k < (step.format == F::list_integer_pair ? 2 : 4); ++k)
        a.integers.push_back(Integer{*rc::gen::inRange<std::int64_t>(-999999, 10000000)});
      break;
    case F::list_real:
    case F::es14_7:
      a.reals.push_back(Real{*test::gen_d14_real()});
      break;
    case F::dense_sample:
      if (*rc::gen::arbitrary<bool>()) {
        const std::int64_t id = *rc::gen::inRange<std::int64_t>(0, 10000000);
        a.word = Word{"INTER " + std::to_string(id)};
        a.integers.push_back(Integer{id});
      } else {
        a.word = Word{"A" + *test::gen_word(4)};  // anything not starting with 'INTER'
      }
      break;
  }
  return a;
}

void generate(std::span<const PostproStep> steps, PostproCommand& command, int depth) {
  std::size_t i = 0;
  while (i < steps.size()) {
    const PostproStep& step = steps[i];
    PostproArgument a = generated_line(step, false);
    std::int64_t count = 0;
    if (step.repeat == PostproRepeat::last_integer) count = a.integers.back().value;
    if (step.repeat == PostproRepeat::compacity_model) count = postpro_compacity_ids(a.word.value);
    command.arguments.push_back(a);
    const auto body = steps.subspan(i + 1, static_cast<std::size_t>(step.body));
    for (std::int64_t k = 0; k < count && depth < 4; ++k) generate(body, command, depth + 1);
    i += 1 + body.size();
  }
}

std::pair<PostproFile, int> generated() {
  const int dimension = *rc::gen::element(2, 3);
  std::vector<const PostproCommandKind*> kinds;
  for (const auto& k : postpro_catalogue())
    if (k.available_in(dimension)) kinds.push_back(&k);
  PostproFile f;
  for (int i = 0, n = *rc::gen::inRange(0, 8); i < n; ++i) {
    const PostproCommandKind* kind = *rc::gen::elementOf(kinds);
    PostproCommand c;
    c.name = Word{std::string(kind->name)};
    c.period = Integer{*rc::gen::inRange(1, 100000)};
    generate(kind->layout(dimension), c, 0);
    f.commands.push_back(c);
  }
  return {f, dimension};
}

RC_GTEST_PROP(PostproRoundTrip, ParseOfWriteIsIdentity, ()) {
  const auto [f, dimension] = generated();
  DiagnosticSink sink;
  const PostproFile back = parse_postpro(SourceText("POSTPRO.DAT", write_postpro(f)), sink, dimension);
  if (sink.has_errors()) RC_FAIL(write_postpro(f) + "\n" + sink.items()[0].message);
  RC_ASSERT(back == f);
}

RC_GTEST_PROP(PostproRoundTrip, WriteOfParseOfCanonicalTextIsIdentity, ()) {
  const auto [f, dimension] = generated();
  const std::string text = write_postpro(f);
  DiagnosticSink sink;
  RC_ASSERT(write_postpro(parse_postpro(SourceText("POSTPRO.DAT", text), sink, dimension)) == text);
}

}  // namespace
}  // namespace lmgc::grammar
