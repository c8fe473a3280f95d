// Every enum value has one name, and reading the name gives the value back.

#include "core/EnumNames.h"

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/Broadphase.h"
#include "core/ContactSolver.h"
#include "core/DirectionDef.h"
#include "core/EntityPositionStatus.h"
#include "core/Event.h"
#include "core/Gyroscopic.h"
#include "core/Integrator.h"
#include "core/ShapeKind.h"
#include "core/SimulationMode.h"

namespace tabletop {
namespace {

// Each of `values` named, the names distinct, and each read back.
template <class Enum, std::size_t N, class Parse>
void roundTrips(const Enum (&values)[N], Parse parse) {
  std::set<std::string> names;
  for (Enum v : values) {
    const std::string name(toString(v));
    EXPECT_FALSE(name.empty()) << static_cast<int>(v);
    EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_EQ(parse(name), v) << name;
  }
  EXPECT_FALSE(parse("no such name").has_value());
}

TEST(EnumNames, EveryValueRoundTrips) {
  roundTrips(kAllBroadphases, broadphaseFromString);
  roundTrips(kAllContactSolvers, contactSolverFromString);
  roundTrips(kAllGyroscopics, gyroscopicFromString);
  roundTrips(kAllIntegrators, integratorFromString);
  roundTrips(kAllModes, simulationModeFromString);
  constexpr ShapeKind shapes[] = {ShapeKind::Cube, ShapeKind::Sphere, ShapeKind::SolidBox, ShapeKind::Cylinder};
  roundTrips(shapes, shapeKindFromString);
  constexpr DirectionDef faces[] = {DirectionDef::Left, DirectionDef::Right, DirectionDef::Front,
                                    DirectionDef::Back};
  roundTrips(faces, directionFromString);
  constexpr EntityPositionStatus statuses[] = {
      EntityPositionStatus::OnTable,           EntityPositionStatus::DropFromLeftEdge,
      EntityPositionStatus::DropFromFrontEdge, EntityPositionStatus::DropFromRightEdge,
      EntityPositionStatus::DropFromBackEdge,  EntityPositionStatus::FinishDropSimulation};
  roundTrips(statuses, statusFromString);
  EXPECT_STREQ(toString(EventType::AtRest), "at_rest");
  EXPECT_STREQ(toString(EventType::ContactBegin), "contact_begin");
}

}  // namespace
}  // namespace tabletop
