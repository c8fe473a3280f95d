// What the bench's and compare's gnuplot scripts draw: read back from the
// scripts, since the pictures themselves are judged by eye.

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/BenchTables.h"
#include "app/TrajectoryPlot.h"

namespace tabletop {
namespace {

BenchPoint point(double rate, double costMs, double error, bool reference = false) {
  BenchPoint p{"s", 1.0 / rate, 10, Integrator::Trapezoid, SimulationMode::Bullet};
  p.costMs = costMs, p.error = error, p.reference = reference;
  return p;
}

// A scene's own reference run is not drawn; an exact point sits on the
// labelled floor; every point carries its rate; axes read as powers of ten.
TEST(PlotScript, BenchPlotLeavesOutTheReferenceAndLabelsTheFloor) {
  std::vector<BenchPoint> points = {point(60, 0.5, 2e-4), point(240, 1.25, 0.0), point(4000, 77.0, 0.0, true)};
  markParetoFronts(points);
  EXPECT_FALSE(points[2].front) << "the reference is not on the front";
  const std::string g = sweepPlotScript(points, "s");
  EXPECT_EQ(g.find("\n77 "), std::string::npos) << "the reference run is drawn:\n" << g;
  EXPECT_NE(g.find("\n1.25 1e-06 240\n"), std::string::npos) << "the exact point is not on the floor:\n" << g;
  EXPECT_NE(g.find("exact (below 10^{-6} mm)"), std::string::npos);
  EXPECT_NE(g.find("sprintf('%g Hz', $3)"), std::string::npos) << "points carry no rate";
  EXPECT_NE(g.find("set format y '10^{%L}'"), std::string::npos);
  EXPECT_NE(g.find("set key outside"), std::string::npos) << "the legend sits over the curves";
}

Comparison stacked() {
  Comparison c;
  c.scenario = "stack";
  for (const char* name : {"Base", "Rider", "Other"}) {
    EntityComparison e;
    e.name = name;
    e.start = std::string(name) == "Other" ? Vec3{-0.4, 0.8, 0.3} : Vec3{0.1, 0.8, -0.2};
    for (ModeOutcome& m : e.modes) m.trajectory.points = {e.start, e.start + Vec3{0.3, 0, 0}};
    c.entities.push_back(e);
  }
  return c;
}

// One colour per entity, a legend row per entity and per mode, a start
// and an end mark per path, and names that do not sit on each other.
TEST(PlotScript, CompareColoursByEntityAndKeepsNamesApart) {
  const std::string g = trajectoryPlotScript(stacked(), TableSpec{});
  const std::regex keyentry("keyentry");
  EXPECT_EQ(std::distance(std::sregex_iterator(g.begin(), g.end(), keyentry), std::sregex_iterator()), 3 + 3 + 1)
      << g;
  for (const char* colour : {"#0072B2", "#D55E00", "#009E73"}) EXPECT_NE(g.find(colour), std::string::npos) << colour;
  const std::regex start("every ::0::0 with points");
  EXPECT_EQ(std::distance(std::sregex_iterator(g.begin(), g.end(), start), std::sregex_iterator()), 9);
  // The labels' places: Base and Rider start at the same point.
  const std::regex label("set label \\d+ '([A-Za-z]+)' at ([-0-9.e]+),([-0-9.e]+)");
  std::vector<std::pair<double, double>> at;
  for (auto it = std::sregex_iterator(g.begin(), g.end(), label); it != std::sregex_iterator(); ++it) {
    at.emplace_back(std::stod((*it)[2]), std::stod((*it)[3]));
  }
  ASSERT_EQ(at.size(), 3u) << g;
  for (std::size_t i = 0; i < at.size(); ++i) {
    for (std::size_t j = i + 1; j < at.size(); ++j) {
      EXPECT_GT(std::hypot(at[i].first - at[j].first, at[i].second - at[j].second), 0.01) << i << " " << j;
    }
  }
}

}  // namespace
}  // namespace tabletop
