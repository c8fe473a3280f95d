// The table on disk: rows appended whole, a cut row dropped on resuming,
// another sweep's table refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "support/TempFiles.h"
#include "sweep/SweepTable.h"

namespace tabletop {
namespace {

const std::string kShipped = std::string(TABLETOP_SOURCE_DIR) + "/scenarios";

SweepSpec rulesSweep(const std::string& values) {
  return loadSweepText(R"({"version": 1, "name": "t", "scene": "example2_two_cubes",
    "parameters": [{"name": "step", "pointer": "/script/0/push/step", "values": )" + values + R"(}],
    "modes": ["rules"]})",
                       "t.json", kShipped);
}

std::string text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

TEST(SweepTable, ResumesAfterTheLastWholeRowAndDropsACutOne) {
  testing::TempFolder folder("sweep_table");
  const std::string prefix = folder.path() + "/t";
  const SweepSpec spec = rulesSweep("[0.2, 0.4, 0.6, 0.8]");
  {
    SweepTable table(prefix, spec);
    EXPECT_EQ(table.done(), 0u);
    for (std::size_t i = 0; i < 3; ++i) table.append(runSweepRow(spec, i));
  }
  const std::string csv = text(prefix + ".csv"), json = text(prefix + ".jsonl");
  EXPECT_EQ(lines(csv), 4u);
  EXPECT_EQ(lines(json), 3u);
  // A kill in the middle of the third row's CSV line.
  std::filesystem::resize_file(prefix + ".csv", csv.size() - 10);
  {
    SweepTable table(prefix, spec);
    EXPECT_EQ(table.done(), 2u);
    EXPECT_EQ(text(prefix + ".jsonl"), json.substr(0, json.find('\n', json.find('\n') + 1) + 1));
    // The rows read back are the rows computed, but for the wall times.
    const std::vector<std::string> columns = sweepColumns(spec);
    const std::vector<SweepRow> kept = table.rows();
    ASSERT_EQ(kept.size(), 2u);
    const SweepRow again = runSweepRow(spec, 1);
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (!isTimingColumn(columns[c])) {
        EXPECT_EQ(kept[1][c], again[c]) << columns[c];
      }
    }
    // The next row goes after them, whole.
    table.append(again);
    EXPECT_EQ(lines(text(prefix + ".csv")), 4u);
  }
}

TEST(SweepTable, RefusesAnotherSweepsTableAndASecondWriter) {
  testing::TempFolder folder("sweep_table_other");
  const std::string prefix = folder.path() + "/t";
  const SweepSpec spec = rulesSweep("[0.2, 0.4]");
  {
    SweepTable table(prefix, spec);
    table.append(runSweepRow(spec, 0));
    EXPECT_THROW(SweepTable(prefix, spec), std::runtime_error);  // locked
  }
  try {
    SweepTable other(prefix, rulesSweep("[0.3, 0.4]"));
    FAIL() << "another sweep's rows were kept";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("t.jsonl:1: holds another sweep's run 0"), std::string::npos) << e.what();
  }
  EXPECT_EQ(lines(text(prefix + ".jsonl")), 1u);  // left as it was
}

}  // namespace
}  // namespace tabletop
