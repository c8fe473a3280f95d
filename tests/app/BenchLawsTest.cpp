// The accuracy page shows what the program measures: the table in
// docs/accuracy.md is the output of `bench --laws` at the rates it names,
// byte for byte (docs/make-accuracy.sh writes it). The laws themselves are
// held to their tolerances by tests/physics/laws/SlideTest.cpp.

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/CommandLine.h"

namespace tabletop {
namespace {

using namespace tabletop::testing;

std::string pageTable() {
  std::ifstream in(std::string(TABLETOP_SOURCE_DIR) + "/docs/accuracy.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string page = text.str();
  const std::string begin = "<!-- laws: begin -->\n```\n", end = "```\n<!-- laws: end -->";
  const std::size_t from = page.find(begin), to = page.find(end);
  if (from == std::string::npos || to == std::string::npos || to < from) return "";
  return page.substr(from + begin.size(), to - from - begin.size());
}

TEST(BenchLaws, TheAccuracyPageShowsWhatTheProgramMeasures) {
  const Outcome o = run(kBin + "tabletop bench --laws --rates 30,60,240,1000");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("laws: the worst error"), std::string::npos) << o.out;
  EXPECT_EQ(pageTable(), o.out) << "docs/accuracy.md is stale: run docs/make-accuracy.sh";
}

// The runs shared among worker processes come back in order, each as it
// was measured in one process.
TEST(BenchLaws, WorkerProcessesGiveWhatOneProcessGives) {
  const Outcome one = run(kBin + "tabletop bench --laws --rates 30,60 --json --jobs 1");
  const Outcome three = run(kBin + "tabletop bench --laws --rates 30,60 --json --jobs 3");
  ASSERT_EQ(one.status, 0) << one.err;
  ASSERT_EQ(three.status, 0) << three.err;
  EXPECT_NE(one.out.find("\"law\": \"bounce\""), std::string::npos) << one.out;
  EXPECT_EQ(three.out, one.out);
}

}  // namespace
}  // namespace tabletop
