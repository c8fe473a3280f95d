// The status rule (core/EntityPositionStatus.h) in every mode: an entity
// that was never on the table reads OnGround while it rests (on the ground,
// or on what rests there) and OffTable while it falls, never OnTable, nor
// the report's drop statuses; one pushed off a table edge still reads
// DropFrom<side>Edge, then FinishDropSimulation. Each placement is a scene
// on the default table (1.2 m x 0.8 m, top at 0.75 m, edges at x = +-0.6 m,
// z = +-0.4 m), stepped until all rests; every status seen is checked.

#include <algorithm>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"

namespace tabletop {
namespace {

using S = EntityPositionStatus;

// Long enough for every scene here to come to rest in full physics.
constexpr double kLongest = 6.0;  // s

struct Expected {
  const char* entity;
  S status;             // at the end
  const char* support;  // at the end
};

struct Placement {
  const char* name = "";
  const char* entities = "";  // the scenario's entity list, JSON
  std::optional<Arrow> push = {};
  double step = 0.0;  // m
  std::vector<Expected> end = {};
  bool falls = false;  // OffTable must be seen on the way
};

void PrintTo(const Placement& p, std::ostream* os) { *os << p.name; }

Arrow arrow(const char* entity, double angleDegrees) {
  Arrow a;
  a.entity = entity;
  a.angleDegrees = angleDegrees;
  return a;
}

const Placement kPlacements[] = {
    {"right_of_table", R"({"name": "A", "shape": "cube", "size": 0.1, "position": [0.9, 0.0], "on": "ground", "mass": 1})",
     {}, 0.0, {{"A", S::OnGround, "ground"}}},
    {"left_of_table", R"({"name": "A", "shape": "cube", "size": 0.1, "position": [-0.9, 0.0], "on": "ground", "mass": 1})",
     {}, 0.0, {{"A", S::OnGround, "ground"}}},
    {"front_of_table", R"({"name": "A", "shape": "sphere", "size": 0.05, "position": [0.0, 0.7], "on": "ground", "mass": 1})",
     {}, 0.0, {{"A", S::OnGround, "ground"}}},
    {"behind_table", R"({"name": "A", "shape": "box", "size": [0.2, 0.1, 0.1], "position": [0.0, -0.7], "on": "ground", "mass": 1})",
     {}, 0.0, {{"A", S::OnGround, "ground"}}},
    {"can_under_table",
     R"({"name": "Can", "shape": "cylinder", "size": [0.04, 0.04, 0.12], "position": [0.0, 0.0], "on": "ground", "mass": 0.3})",
     {}, 0.0, {{"Can", S::OnGround, "ground"}}},
    {"stack_of_5_beside_table",
     R"({"name": "C0", "shape": "cube", "size": 0.2, "position": [1.2, 0.0], "on": "ground", "mass": 1},
        {"name": "C1", "shape": "cube", "size": 0.2, "position": [1.2, 0.0], "on": "C0", "mass": 1},
        {"name": "C2", "shape": "cube", "size": 0.2, "position": [1.2, 0.0], "on": "C1", "mass": 1},
        {"name": "C3", "shape": "cube", "size": 0.2, "position": [1.2, 0.0], "on": "C2", "mass": 1},
        {"name": "C4", "shape": "cube", "size": 0.2, "position": [1.2, 0.0], "on": "C3", "mass": 1})",
     {}, 0.0,
     {{"C0", S::OnGround, "ground"}, {"C1", S::OnGround, "C0"}, {"C2", S::OnGround, "C1"}, {"C3", S::OnGround, "C2"},
      {"C4", S::OnGround, "C3"}}},
    // Dropped from above a floor stack beside the table: it falls onto the
    // stack's top, higher than the table's.
    {"dropped_onto_floor_stack",
     R"({"name": "C0", "shape": "cube", "size": 0.4, "position": [1.2, 0.0], "on": "ground", "mass": 1},
        {"name": "C1", "shape": "cube", "size": 0.4, "position": [1.2, 0.0], "on": "C0", "mass": 1},
        {"name": "A", "shape": "cube", "size": 0.1, "position": [1.2, 1.2, 0.0], "mass": 1})",
     {}, 0.0, {{"C0", S::OnGround, "ground"}, {"C1", S::OnGround, "C0"}, {"A", S::OnGround, "C1"}}, true},
    // Pushed off the top of a floor stack, away from the table: it falls
    // past the stack's edge to the ground.
    {"pushed_off_floor_stack",
     R"({"name": "Base", "shape": "box", "size": [0.3, 0.3, 0.3], "position": [1.2, 0.0], "on": "ground", "mass": 5},
        {"name": "A", "shape": "cube", "size": 0.1, "position": [1.2, 0.0], "on": "Base", "mass": 1,
         "material": {"friction": 0.3}})",
     arrow("A", 0.0), 0.4, {{"Base", S::OnGround, "ground"}, {"A", S::OnGround, "ground"}}, true},
};

Scenario scene(const Placement& p) {
  const std::string json = std::string(R"({"version": 1, "name": ")") + p.name +
                           R"(", "settings": {"duration": 6.0}, "entities": [)" + p.entities + "], \"script\": []}";
  return ScenarioLoader::loadText(json, std::string(p.name) + ".json");
}

// Steps `sim` until all rests, and calls `look` with every snapshot.
template <typename Look>
void runToRest(Simulation& sim, const Look& look) {
  look(sim.snapshot());
  do {
    sim.step();
    look(sim.snapshot());
  } while (!sim.allAtRest() && sim.time() < kLongest);
}

class OffTableStatus : public ::testing::TestWithParam<std::tuple<Placement, SimulationMode>> {};

TEST_P(OffTableStatus, ReadsOnGroundOrOffTableNeverATableStatus) {
  const auto& [p, mode] = GetParam();
  const Scenario s = scene(p);
  std::unique_ptr<Simulation> sim = buildSimulation(s, s.settings, mode);
  if (p.push) sim->push(*p.push, PushMagnitude{PushMagnitude::Kind::Step, p.step});
  bool sawOffTable = false;
  runToRest(*sim, [&](const std::vector<EntityState>& states) {
    for (const EntityState& e : states) {
      ASSERT_TRUE(neverOnTable(e.status)) << e.name << " reads " << toString(e.status) << " on "
                                          << e.support.name() << " at t = " << sim->time() << " s";
      sawOffTable = sawOffTable || e.status == S::OffTable;
    }
  });
  EXPECT_TRUE(sim->allAtRest()) << "still moving after " << kLongest << " s";
  const std::vector<EntityState> end = sim->snapshot();
  for (const Expected& x : p.end) {
    const auto it = std::find_if(end.begin(), end.end(), [&](const EntityState& e) { return e.name == x.entity; });
    ASSERT_NE(it, end.end()) << x.entity;
    EXPECT_EQ(toString(it->status), toString(x.status)) << x.entity;
    EXPECT_EQ(it->support.name(), x.support) << x.entity;
  }
  EXPECT_EQ(sawOffTable, p.falls) << "OffTable, while a body falls, " << (p.falls ? "never seen" : "seen");
}

std::string caseName(const ::testing::TestParamInfo<std::tuple<Placement, SimulationMode>>& info) {
  return std::string(std::get<0>(info.param).name) + "_" + std::string(toString(std::get<1>(info.param)));
}

INSTANTIATE_TEST_SUITE_P(Placements, OffTableStatus,
                         ::testing::Combine(::testing::ValuesIn(kPlacements),
                                            ::testing::Values(SimulationMode::Bullet, SimulationMode::Compat,
                                                              SimulationMode::Rules)),
                         caseName);

// A cube on the table pushed over an edge keeps the report's statuses:
// OnTable, DropFrom<side>Edge, FinishDropSimulation, in that order.
class TableDropStatus : public ::testing::TestWithParam<std::tuple<DirectionDef, SimulationMode>> {};

TEST_P(TableDropStatus, ReadsDropFromTheEdgeThenFinishDropSimulation) {
  const auto& [side, mode] = GetParam();
  Placement p;
  p.name = "pushed_off_table";
  p.entities = R"({"name": "A", "shape": "cube", "size": 0.1, "position": [0.0, 0.0], "on": "table", "mass": 1})";
  const Scenario s = scene(p);
  std::unique_ptr<Simulation> sim = buildSimulation(s, s.settings, mode);
  // A push on the face opposite the side moves the cube towards it
  // (report 2: DirectionDef names the face the force acts on); 0.3 m
  // past the edge it falls from, 0.4 m or 0.6 m from the centre.
  const double reach = side == DirectionDef::Left || side == DirectionDef::Right ? 0.9 : 0.7;
  const DirectionDef face = side == DirectionDef::Left    ? DirectionDef::Right
                            : side == DirectionDef::Right ? DirectionDef::Left
                            : side == DirectionDef::Front ? DirectionDef::Back
                                                          : DirectionDef::Front;
  Arrow push = arrow("A", 0.0);
  push.face = face;
  sim->push(push, PushMagnitude{PushMagnitude::Kind::Step, reach});
  std::vector<S> seen;
  runToRest(*sim, [&](const std::vector<EntityState>& states) {
    if (seen.empty() || seen.back() != states[0].status) seen.push_back(states[0].status);
  });
  const S drop = *statusFromString("DropFrom" + std::string(toString(side)) + "Edge");
  ASSERT_EQ(seen.size(), 3u);
  EXPECT_EQ(seen[0], S::OnTable);
  EXPECT_EQ(seen[1], drop) << toString(seen[1]);
  EXPECT_EQ(seen[2], S::FinishDropSimulation) << toString(seen[2]);
  EXPECT_EQ(sim->snapshot()[0].support, Support::ground());
}

std::string dropName(const ::testing::TestParamInfo<std::tuple<DirectionDef, SimulationMode>>& info) {
  return std::string(toString(std::get<0>(info.param))) + "_" + std::string(toString(std::get<1>(info.param)));
}

INSTANTIATE_TEST_SUITE_P(Edges, TableDropStatus,
                         ::testing::Combine(::testing::Values(DirectionDef::Left, DirectionDef::Right,
                                                              DirectionDef::Front, DirectionDef::Back),
                                            ::testing::Values(SimulationMode::Bullet, SimulationMode::Compat,
                                                              SimulationMode::Rules)),
                         dropName);

}  // namespace
}  // namespace tabletop
