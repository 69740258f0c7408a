// The sink's bound: no error is lost while a warning or note is kept, and what is left out is
// counted and stated (L9004).
#include <gtest/gtest.h>

#include "grammar/common/diagnostic.hpp"

namespace lmgc::grammar {
namespace {

Diagnostic make(Severity severity, int n) {
  Diagnostic d;
  d.code = "L1002";
  d.severity = severity;
  d.message = std::to_string(n);
  return d;
}

TEST(DiagnosticSink, LaterErrorsDisplaceWarningsAndNotesWhenFull) {
  DiagnosticSink sink(4);
  sink.report(make(Severity::warning, 1));
  sink.report(make(Severity::note, 2));
  sink.report(make(Severity::error, 3));
  sink.report(make(Severity::warning, 4));
  sink.report(make(Severity::error, 5));  // displaces warning 4
  sink.report(make(Severity::error, 6));  // displaces note 2
  sink.report(make(Severity::warning, 7));
  ASSERT_EQ(sink.items().size(), 4u);
  EXPECT_EQ(sink.items()[0].message, "1");
  EXPECT_EQ(sink.items()[1].message, "3");
  EXPECT_EQ(sink.items()[2].message, "5");
  EXPECT_EQ(sink.items()[3].message, "6");
  EXPECT_EQ(sink.error_count(), 3u);
  EXPECT_EQ(sink.dropped_errors(), 0u);
  const auto overflow = sink.overflow_diagnostic();
  ASSERT_EQ(overflow.size(), 1u);
  EXPECT_EQ(overflow[0].code, "L9004");
  EXPECT_EQ(overflow[0].severity, Severity::warning);
  EXPECT_NE(overflow[0].message.find("0 error(s), 2 warning(s) and 1 note(s) not shown"), std::string::npos)
      << overflow[0].message;
}

TEST(DiagnosticSink, ErrorsBeyondAFullSinkOfErrorsAreCountedAndStated) {
  DiagnosticSink sink(3);
  for (int k = 0; k < 10; ++k) sink.report(make(Severity::error, k));
  EXPECT_EQ(sink.items().size(), 3u);
  EXPECT_EQ(sink.error_count(), 10u);
  EXPECT_EQ(sink.dropped_errors(), 7u);
  const auto overflow = sink.overflow_diagnostic();
  ASSERT_EQ(overflow.size(), 1u);
  EXPECT_EQ(overflow[0].severity, Severity::error);
  EXPECT_TRUE(DiagnosticSink(3).overflow_diagnostic().empty());
}

}  // namespace
}  // namespace lmgc::grammar
