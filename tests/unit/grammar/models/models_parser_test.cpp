// MODELS.DAT: models, options, and broken files with their exact diagnostic.
#include <gtest/gtest.h>

#include "grammar/models/parser.hpp"
#include "grammar/models/writer.hpp"

namespace lmgc::grammar {
namespace {

const std::string kModel =
    "$model  mdlty  finel  eleop  value\n"
    " M2DNL\n"
    "        MECAx  Q4xxx  isext  MatL_\n"
    "                      kine_  large\n"
    "                      extvf  temperature                        3\n";

void expect_diagnostic(const std::string& text, const std::string& code, std::uint32_t line,
                       std::uint32_t column) {
  DiagnosticSink sink;
  parse_models(SourceText("MODELS.DAT", text), sink);
  ASSERT_FALSE(sink.items().empty());
  EXPECT_EQ(sink.items()[0].code, code) << sink.items()[0].message;
  EXPECT_EQ(sink.items()[0].where.span.line, line);
  EXPECT_EQ(sink.items()[0].where.span.column, column);
}

TEST(ModelsParser, ReadsModelElementAndOptions) {
  DiagnosticSink sink;
  const ModelsFile f = parse_models(SourceText("MODELS.DAT", kModel), sink);
  EXPECT_FALSE(sink.has_errors());
  ASSERT_EQ(f.models.size(), 1u);
  EXPECT_EQ(f.models[0].kind.value, "MECAx");
  EXPECT_EQ(f.models[0].element.value, "Q4xxx");
  ASSERT_EQ(f.models[0].options.size(), 3u);
  EXPECT_EQ(f.models[0].options[1].value.value, "large");
  EXPECT_EQ(f.models[0].vfield_max_size.value, 3);
}

TEST(ModelsParser, OptionValueKeepsItsLeadingBlanks) {
  std::string t = kModel;
  t.replace(t.find("  large"), 7, "   large");
  DiagnosticSink sink;
  EXPECT_EQ(parse_models(SourceText("MODELS.DAT", t), sink).models[0].options[1].value.value, " large");
}

TEST(ModelsParser, UserModelNameIsReadListDirected) {
  DiagnosticSink sink;
  const ModelsFile f =
      parse_models(SourceText("MODELS.DAT",
                              "$model\n M2DNL\n        MECAx  Q4xxx  u_mdl    my_law  other\n"
                              "                      isext  no___\n"),
                   sink);
  EXPECT_TRUE(sink.items().empty());
  ASSERT_EQ(f.models.size(), 1u);
  EXPECT_EQ(f.models[0].user_model.value, "my_law");
  ASSERT_EQ(f.models[0].options.size(), 1u);
  EXPECT_EQ(write_models(f),
            "$model  mdlty  finel  eleop  value  \n M2DNL                      \n"
            "        MECAx  Q4xxx  u_mdl  my_law" +
                std::string(44, ' ') +
                "\n"
                "                      isext  no___                         \n");
}

TEST(ModelsParser, VectorFieldSizeIsTheLargestOfTheModelAndIsWrittenOnEveryExtvfLine) {
  DiagnosticSink sink;
  const ModelsFile f =
      parse_models(SourceText("MODELS.DAT",
                              "$model\n M2DNL\n        MECAx  Q4xxx  isext  MatL_\n"
                              "                      extvf  temperature                        3\n"
                              "                      extvf  stress                             7\n"),
                   sink);
  EXPECT_TRUE(sink.items().empty());
  EXPECT_EQ(f.models[0].vfield_max_size.value, 7);
  const std::string out = write_models(f);
  // A30 value, 1x, I5 size.
  EXPECT_NE(out.find("extvf  temperature" + std::string(19 + 1 + 4, ' ') + "7\n"), std::string::npos);
  EXPECT_NE(out.find("extvf  stress" + std::string(24 + 1 + 4, ' ') + "7\n"), std::string::npos);
}

TEST(ModelsParser, ModelWithoutOptionsIgnoresLaterOptionLinesAsLmgc90Does) {
  DiagnosticSink sink;
  const ModelsFile f = parse_models(
      SourceText("MODELS.DAT", "$model\n M2DNL\n        THERM  T3xxx\n                      kine_  large\n"),
      sink);
  ASSERT_EQ(sink.items().size(), 1u);
  EXPECT_EQ(sink.items()[0].code, "L1019");
  EXPECT_EQ(sink.items()[0].where.span.line, 4u);
  EXPECT_EQ(sink.items()[0].where.span.column, 23u);
  EXPECT_TRUE(f.models[0].options.empty());
  EXPECT_EQ(write_models(f),
            "$model  mdlty  finel  eleop  value  \n M2DNL                      \n"
            "        THERM  T3xxx" +
                std::string(39, ' ') + "\n");
}

TEST(ModelsParser, ExtFIsReadAsExtsf) {
  std::string t = kModel;
  t.replace(t.find("kine_"), 5, "ext_f");
  DiagnosticSink sink;
  EXPECT_EQ(parse_models(SourceText("MODELS.DAT", t), sink).models[0].options[1].id.value, "extsf");
}

TEST(ModelsWriter, WritesLmgc90Layout) {
  DiagnosticSink sink;
  const std::string out = write_models(parse_models(SourceText("MODELS.DAT", kModel), sink));
  EXPECT_EQ(out.substr(0, out.find("kine_")),
            "$model  mdlty  finel  eleop  value  \n M2DNL                      \n"
            "        MECAx  Q4xxx  isext  MatL_                         \n                      ");
}

TEST(ModelsBroken, EmptyFile) {
  expect_diagnostic("", "L1009", 0, 0);
}
TEST(ModelsBroken, MissingMdltyLine) {
  expect_diagnostic("$model\n M2DNL\n$model\n M3DNL\n        MECAx  H8xxx\n", "L1012", 2, 2);
}
TEST(ModelsBroken, FileEndsAfterModelKeyword) {
  expect_diagnostic("$model  mdlty\n", "L1006", 1, 14);
}
TEST(ModelsBroken, MissingNickname) {
  expect_diagnostic("$model\n        MECAx  Q4xxx  isext  MatL_\n", "L1013", 2, 2);
}
TEST(ModelsBroken, StrayLine) {
  expect_diagnostic("stray\n" + kModel, "L1019", 1, 1);
}
TEST(ModelsBroken, MalformedFieldSize) {
  std::string t = kModel;
  t.replace(t.rfind('3'), 1, "x");
  expect_diagnostic(t, "L1004", 5, 61);
}
TEST(ModelsBroken, SecondMdltyLineAfterOptions) {
  expect_diagnostic(kModel + "        THERM  T3xxx\n", "L1013", 6, 9);
}
TEST(ModelsBroken, MissingUserModelName) {
  expect_diagnostic("$model\n M2DNL\n        MECAx  Q4xxx  u_mdl\n", "L1015", 3, 30);
}
// LMGC90 writes the name unquoted (A50) and would read its own echo as the name 'a'.
TEST(ModelsBroken, QuotedUserModelNameWithABlank) {
  expect_diagnostic("$model\n TET__\n        MECAx  TE4xx  u_mdl  'a name, with blanks'\n", "L1017", 3, 30);
}
TEST(ModelsBroken, UnknownModelType) {
  std::string t = kModel;
  t.replace(t.find("MECAx"), 5, "MECAy");
  expect_diagnostic(t, "L1001", 3, 9);
}
TEST(ModelsBroken, UnknownElement) {
  std::string t = kModel;
  t.replace(t.find("Q4xxx"), 5, "Q5xxx");
  expect_diagnostic(t, "L1001", 3, 16);
}
TEST(ModelsParser, KnowsEveryModelTypeAndExternalElements) {
  for (const char* line :
       {"        THERM  Q8Rxx", "        POROx  Q84xx", "        MULTI  H208x", "        MECAx  SHB6x",
        "        MECAx  J2xx2", "        MECAx  EXT01", "        THERM  S2xth"}) {
    DiagnosticSink sink;
    parse_models(SourceText("MODELS.DAT", std::string("$model\n M2DNL\n") + line + "\n"), sink);
    EXPECT_TRUE(sink.items().empty()) << line;
  }
}
TEST(ModelsBroken, NonAsciiByte) {
  std::string t = kModel;
  t.replace(t.find("large"), 5, "l\xC3\xA0rge");
  expect_diagnostic(t, "L1008", 4, 31);
}

}  // namespace
}  // namespace lmgc::grammar
