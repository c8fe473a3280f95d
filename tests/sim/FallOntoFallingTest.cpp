// Report 3.4 and 3.8: a body past an edge falls straight down and lands on
// the first top it meets whose footprint holds its centre, even when the
// body under it is still falling. Rows of cubes (sizes, gaps, steps drawn
// from a fixed seed) pushed from the rear over an edge, one after another:
// each later cube starts to fall while the one before is still in the air.
// The outcome is worked out here from the rules alone and compared with
// the engine's: over the table's edge (rules; compat hands such a body to
// full physics) and over a tall base's edge onto the table (rules and
// compat, whose riders fall by the rules), towards +X and -X.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenario/ScenarioLoader.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;           // m/s^2, the scenes' gravity
constexpr double kSpeed = 0.5;        // m/s, RuleEngine::kDriveSpeed
constexpr double kTableTop = 0.75;    // m
constexpr double kTableEdge = 0.6;    // m, half the default table's width
constexpr double kBaseWidth = 0.8;    // m, the base box: [width, height, depth]
constexpr double kBaseHeight = 0.5;   // m
constexpr double kExact = 1e-9;       // m: kinematics in double

struct Row {
  std::vector<double> sizes;  // m, front (nearest the edge) first
  std::vector<double> gaps;   // m, gaps[j] between cube j - 1 and cube j (gaps[0] unused)
  double front = 0.0;         // m, the front cube's face from the edge
  double step = 0.0;          // m, the push on the rear cube
  int side = 1;               // +1: over the edge at +X, -1: at -X
  bool onBase = false;        // on the base (falls onto the table) or on the table (onto the ground)
};

struct Outcome {
  double out = 0.0;   // m, centre beyond the edge (negative: short of it, on its surface)
  double y = 0.0;     // m, centre height
  std::string on;     // support
  double start = -1;  // s, when its fall began (-1: it stays up)
  double lands = -1;  // s, when it landed
};

double edge(const Row& r) { return r.onBase ? 0.5 * kBaseWidth : kTableEdge; }
double surface(const Row& r) { return r.onBase ? kTableTop + kBaseHeight : kTableTop; }
double below(const Row& r) { return r.onBase ? kTableTop : 0.0; }

// The rules worked by hand. Cube j's centre starts c_j in from the edge.
// The rear cube closes the gaps behind j (G_j) before j is struck, and j
// then moves the rest of the step, S - G_j, at kSpeed (straight-line
// transfer, report 3.7). If that carries its centre to the edge it stops
// being pushed, moves on by its half size and falls from the surface at
// out = h_j; it lands on the highest top among the cubes already down
// whose footprint holds its centre (|h_j - h_k| <= h_k), else below.
std::vector<Outcome> byTheRules(const Row& r) {
  const std::size_t n = r.sizes.size();
  std::vector<double> inward(n), behind(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    inward[j] = j == 0 ? r.front + r.sizes[0] / 2
                       : inward[j - 1] + r.sizes[j - 1] / 2 + r.gaps[j] + r.sizes[j] / 2;
  }
  for (std::size_t j = n - 1; j-- > 0;) behind[j] = behind[j + 1] + r.gaps[j + 1];
  std::vector<Outcome> out(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double h = r.sizes[j] / 2, travel = std::max(0.0, r.step - behind[j]);
    if (travel <= inward[j]) {
      out[j] = {travel - inward[j], surface(r) + h, r.onBase ? "Base" : "table"};
      continue;
    }
    out[j].out = h;
    out[j].start = (behind[j] + inward[j] + h) / kSpeed;
    double floor = below(r);
    out[j].on = r.onBase ? "table" : "ground";
    for (std::size_t k = 0; k < j; ++k) {
      const double hk = r.sizes[k] / 2;
      if (out[k].start < 0 || std::abs(h - hk) > hk) continue;
      if (out[k].y + hk > floor) {
        floor = out[k].y + hk;
        out[j].on = "C" + std::to_string(k);
      }
    }
    out[j].y = floor + h;
    out[j].lands = out[j].start + std::sqrt(2.0 * (surface(r) - floor) / kG);
  }
  return out;
}

Scenario scene(const Row& r) {
  std::string entities;
  char text[512];
  if (r.onBase) {
    std::snprintf(text, sizeof text,
                  R"({"name": "Base", "shape": "box", "size": [%.17g, %.17g, 0.3], "position": [0, 0], "mass": 10})",
                  kBaseWidth, kBaseHeight);
    entities = text;
  }
  double inward = r.front;
  for (std::size_t j = 0; j < r.sizes.size(); ++j) {
    if (j > 0) inward += r.sizes[j - 1] + r.gaps[j];
    const double x = r.side * (edge(r) - inward - r.sizes[j] / 2);
    std::snprintf(text, sizeof text,
                  R"({"name": "C%zu", "shape": "cube", "size": %.17g, "position": [%.17g, 0], "on": "%s", "mass": 1})",
                  j, r.sizes[j], x, r.onBase ? "Base" : "table");
    entities += (entities.empty() ? "" : ", ") + std::string(text);
  }
  std::snprintf(text, sizeof text, R"({"push": {"entity": "C%zu", "direction": "%s", "step": %.17g}})",
                r.sizes.size() - 1, r.side > 0 ? "Left" : "Right", r.step);
  const std::string json = R"({"version": 1, "name": "fall_onto_falling", "settings": {"duration": 20},
    "entities": [)" + entities + R"(], "script": [)" + text + "]}";
  return ScenarioLoader::loadText(json, "fall_onto_falling.json");
}

std::string describe(const Row& r) {
  std::string s = std::string(r.onBase ? "off the base" : "off the table") + (r.side > 0 ? " at +X" : " at -X");
  char text[128];
  std::snprintf(text, sizeof text, ", front face %.4f m in, step %.4f m; sizes/gaps", r.front, r.step);
  s += text;
  for (std::size_t j = 0; j < r.sizes.size(); ++j) {
    std::snprintf(text, sizeof text, " %.4f/%.4f", r.sizes[j], j ? r.gaps[j] : 0.0);
    s += text;
  }
  return s;
}

// Rows whose outcome is far from every tie of the rules: no centre within
// 1 mm of the edge at its drive's end, no footprint within 1 mm of
// holding a centre; at least two cubes go over.
std::vector<Row> rows(bool onBase) {
  std::mt19937 random(onBase ? 38 : 34);
  std::uniform_real_distribution<double> size(0.03, 0.11), gap(0.0, 0.05), front(0.01, 0.1), extra(0.002, 0.3);
  std::vector<Row> all;
  while (all.size() < 24) {
    Row r;
    r.onBase = onBase;
    r.side = all.size() % 2 == 0 ? 1 : -1;
    const std::size_t n = 2 + all.size() % 3;
    for (std::size_t j = 0; j < n; ++j) {
      r.sizes.push_back(std::round(size(random) * 1e3) / 1e3);
      r.gaps.push_back(j == 0 ? 0.0 : std::round(gap(random) * 1e3) / 1e3);
    }
    r.front = std::round(front(random) * 1e3) / 1e3;
    // Enough for the second cube's centre to pass the edge, and more.
    const double second = r.front + r.sizes[0] + r.gaps[1] + r.sizes[1] / 2;
    double behind = 0.0;
    for (std::size_t j = 2; j < n; ++j) behind += r.gaps[j];
    r.step = std::round((second + behind + extra(random)) * 1e3) / 1e3 + 0.0005;
    const std::vector<Outcome> o = byTheRules(r);
    bool clear = true;
    for (std::size_t j = 0; j < n; ++j) {
      clear = clear && std::abs(o[j].out) > 1e-3;
      for (std::size_t k = 0; k < j; ++k) {
        clear = clear && std::abs(std::abs(r.sizes[j] - r.sizes[k]) - r.sizes[k]) > 2e-3;
      }
    }
    if (clear) all.push_back(r);
  }
  return all;
}

// How often the rows exercised the law: cubes that started to fall while
// the one before was still falling, and cubes that went over but did not
// end on the one before (its footprint did not hold their centre).
struct Exercised {
  int overlapping = 0;
  int elsewhere = 0;
};

// Runs each row in `mode` and compares every cube's end with the rules.
Exercised checkRows(const std::vector<Row>& all, SimulationMode mode) {
  Exercised count;
  for (const Row& r : all) {
    const std::vector<Outcome> expected = byTheRules(r);
    const RunResult run = test::runScene(scene(r), mode);
    const std::string what = describe(r);
    EXPECT_TRUE(run.complete) << what;
    EXPECT_LT(run.simTime, 19.0) << what << ": never came to rest";
    const std::size_t first = r.onBase ? 1 : 0;
    for (std::size_t j = 0; j < expected.size(); ++j) {
      const EntityState& e = run.entities[first + j];
      const Outcome& o = expected[j];
      const double out = r.side * e.position.x - edge(r);
      EXPECT_NEAR(out, o.out, kExact) << what << ": C" << j << " along the row";
      EXPECT_NEAR(e.position.y, o.y, kExact) << what << ": C" << j << " height";
      EXPECT_EQ(e.support.name(), o.on) << what << ": C" << j << " support";
      if (j == 0 || o.start < 0 || expected[j - 1].start < 0) continue;
      count.overlapping += o.start < expected[j - 1].lands ? 1 : 0;
      count.elsewhere += o.on != "C" + std::to_string(j - 1) ? 1 : 0;
    }
  }
  return count;
}

void expectExercised(const Exercised& count) {
  EXPECT_GT(count.overlapping, 20);
  EXPECT_GT(count.elsewhere, 0);
}

TEST(FallOntoFalling, OffTheTableLandsOnTheFirstTopMetByTheRules) {
  expectExercised(checkRows(rows(false), SimulationMode::Rules));
}

TEST(FallOntoFalling, OffABaseLandsOnTheFirstTopMetByTheRules) {
  expectExercised(checkRows(rows(true), SimulationMode::Rules));
}

TEST(FallOntoFalling, OffABaseLandsOnTheFirstTopMetInCompat) {
  expectExercised(checkRows(rows(true), SimulationMode::Compat));
}

// The issue's scene: four cubes of 0.1 m in a row with gaps, pushed at
// the right edge; the first two go over 0.2 s apart and the second ends
// on the first's top.
TEST(FallOntoFalling, TheSecondOfTwoEndsOnTheFirstsTop) {
  Row r{{0.1, 0.1, 0.1, 0.1}, {0.0, 0.02, 0.02, 0.02}, 0.05, 0.5, 1, false};
  const std::vector<Outcome> o = byTheRules(r);
  ASSERT_NEAR(o[1].start - o[0].start, 0.2, 1e-12);
  ASSERT_LT(o[1].start, o[0].lands);
  const RunResult run = test::runScene(scene(r), SimulationMode::Rules);
  EXPECT_EQ(run.entities[1].support.name(), "C0");
  EXPECT_NEAR(run.entities[1].position.y, run.entities[0].position.y + 0.05 + 0.05, kExact);
  EXPECT_NEAR(run.entities[0].position.y, 0.05, kExact);
}

// Compat hands a body past the table's edge to full physics, where it
// falls onto one that fell before it. Its drop ends there too: every cube
// ends FinishDropSimulation and the run at rest, long before its duration.
// A wider first cube: with four equal ones, whether the third ended on the
// first turned on a tenth of a millimetre in how it tipped over the edge
// (it did when other cubes' events cut its steps, not when they no longer
// did: StepGroups).
TEST(FallOntoFalling, InCompatADropOntoADroppedBodyEnds) {
  Row r{{0.16, 0.1, 0.1, 0.1}, {0.0, 0.02, 0.02, 0.02}, 0.05, 0.6, 1, false};
  const RunResult run = test::runScene(scene(r), SimulationMode::Compat);
  EXPECT_LT(run.simTime, 5.0);
  bool onACube = false;
  for (const EntityState& e : run.entities) {
    EXPECT_EQ(e.status, EntityPositionStatus::FinishDropSimulation) << e.name;
    onACube = onACube || e.support.kind() == Support::Kind::Entity;
  }
  EXPECT_TRUE(onACube);
}

}  // namespace
}  // namespace tabletop
