// ResultTable's three writers: the same rows as a text table, CSV and
// JSON, each column only in the formats it names.
#include "io/ResultTable.h"

#include <gtest/gtest.h>

namespace tabletop {
namespace {

ResultTable sample() {
  ResultTable t;
  t.title = "title";
  t.columns = {{"scene", "scene"}, {"error_m", "error [mm]"}, {"", "shown only"}, {"complete", ""}};
  t.rows.push_back({cell("a, \"b\""), cell(0.0012, "1.2000"), cell(nullptr, "x"), cell(true, "")});
  t.rows.push_back({cell("long scene name"), cell(0.25, "250.0000"), cell(nullptr, ""), cell(false, "")});
  t.notes = {"a note"};
  return t;
}

TEST(ResultTable, TextAlignsEachColumnToItsWidestEntry) {
  EXPECT_EQ(toText(sample()),
            "title\n"
            "  scene           error [mm] shown only\n"
            "  a, \"b\"          1.2000     x\n"
            "  long scene name 250.0000\n"
            "  a note\n");
}

TEST(ResultTable, CsvQuotesTextAndKeepsEveryDigit) {
  EXPECT_EQ(toCsv(sample()),
            "scene,error_m,complete\n"
            "\"a, \"\"b\"\"\",0.0011999999999999999,1\n"
            "long scene name,0.25,0\n");
}

TEST(ResultTable, JsonHasTheKeyedColumnsOnly) {
  const nlohmann::json j = toJson(sample());
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0].size(), 3u);
  EXPECT_EQ(j[0]["scene"], "a, \"b\"");
  EXPECT_DOUBLE_EQ(j[0]["error_m"].get<double>(), 0.0012);
  EXPECT_EQ(j[1]["complete"], false);
}

}  // namespace
}  // namespace tabletop
