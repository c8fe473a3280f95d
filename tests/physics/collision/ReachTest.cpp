// Which bodies a step is cut into parts for (World::substeps): only those
// something is near (nearAnything), not counting what a body slides on
// (slidesOn). Each case is set a millimetre or more either side of the
// reach the rule computes, (|v| + |w| R) dt + g dt^2 / 2 plus the 2 cm
// ahead of touching at which contact points are made.

#include "physics/collision/Reach.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "physics/shapes/Cube.h"
#include "physics/shapes/Seating.h"
#include "physics/shapes/Sphere.h"
#include "physics/World.h"
#include "support/PhysicsFixture.h"

namespace tabletop {
namespace {

using test::kG;
using test::PhysicsFixture;

void place(btRigidBody& body, const btVector3& at) {
  btTransform pose = body.getWorldTransform();
  pose.setOrigin(at);
  body.setWorldTransform(pose);
}

// A body that nothing comes near within what it can move in a step,
// (|v| + |w| R) dt + g dt^2 / 2, plus the 2 cm ahead of touching at which
// contact points are made, strikes nothing in it and is stepped whole
// however fast; once something is that near, the step is cut into parts
// by how far its points move (WorldTest).
// Over the floor, the table and another body.
TEST_F(PhysicsFixture, AStepIsWholeForAFastBodyNothingIsNear) {
  const double dt = 1.0 / 60.0, h = 0.05, g = kG;
  World& w = makeTable(dt);
  const double top = w.table().topHeight();
  btRigidBody& ball = *w.addEntity(std::make_unique<Sphere>("ball", h), 1.0, Material{},
                                   btVector3(-3, 2, 0), 0).body();
  w.addEntity(std::make_unique<Cube>("cube", 2 * h), 1.0, Material{}, btVector3(1, 2, 0), 0);
  const double speed = 6.1;  // m/s: five parts when near (the test above)
  const double reach = speed * dt + 0.5 * g * dt * dt + gContactBreakingThreshold;
  ball.setLinearVelocity(btVector3(0, -speed, 0));
  EXPECT_EQ(w.substeps(), 1) << "falling, 2 m up";
  // Its bounding box's bottom a millimetre either side of the reach.
  btVector3 low, high;
  ball.getCollisionShape()->getAabb(btTransform::getIdentity(), low, high);
  place(ball, btVector3(-3, -low.y() + reach + 1e-3, 0));
  EXPECT_EQ(w.substeps(), 1) << "just out of reach of the floor";
  place(ball, btVector3(-3, -low.y() + reach - 1e-3, 0));
  EXPECT_EQ(w.substeps(), 5) << "just within reach of the floor";
  // Sideways, high over the table's middle; then beside a cube in the air,
  // well out of reach of it and well within.
  ball.setLinearVelocity(btVector3(speed, 0, 0));
  place(ball, btVector3(-0.5, top + 0.3, 0));
  EXPECT_EQ(w.substeps(), 1) << "high over the table";
  place(ball, btVector3(1 - 2 * h - 2 * reach, 2, 0));
  EXPECT_EQ(w.substeps(), 1) << "out of reach of the cube";
  place(ball, btVector3(1 - 2 * h - reach / 2, 2, 0));
  EXPECT_EQ(w.substeps(), 5) << "within reach of the cube";
}

// A body on what carries it, its points there found by a step, slides
// along it: stepped whole however fast, on the floor or the table. It is
// cut into parts again when it closes on its support faster than gravity
// gives in a step (a landing), when its turn moves its surface more than a
// twentieth of its smallest half extent in a step (its corners could come
// down into it), or when it comes within its reach of the support's edge.
TEST_F(PhysicsFixture, ABodySlidingOnWhatCarriesItIsSteppedWhole) {
  const double dt = 1.0 / 60.0, h = 0.05;
  World& w = makeTable(dt);
  const double top = w.table().topHeight();
  btRigidBody& onFloor = *w.addEntity(std::make_unique<Cube>("floor", 2 * h), 1.0, Material{},
                                      btVector3(3, seated(h), 0), 0).body();
  btRigidBody& onTable = *w.addEntity(std::make_unique<Cube>("table", 2 * h), 1.0, Material{},
                                      btVector3(0, seated(top + h), 0), 0).body();
  const auto parts = [&](double travel) { return static_cast<int>(std::ceil(travel / (h / 2))); };
  onFloor.setLinearVelocity(btVector3(6.1, 0, 0));
  EXPECT_EQ(w.substeps(), 5) << "no points found yet: the floor is near";
  w.step();
  for (btRigidBody* body : {&onFloor, &onTable}) {
    body->setLinearVelocity(btVector3(0, 0, 0));
    body->setAngularVelocity(btVector3(0, 0, 0));
  }
  for (btRigidBody* body : {&onFloor, &onTable}) {
    SCOPED_TRACE(body == &onFloor ? "on the floor" : "on the table");
    body->setLinearVelocity(btVector3(6.1, 0, 0));
    EXPECT_EQ(w.substeps(), 1) << "sliding";
    body->setLinearVelocity(btVector3(6.1, -2 * kG * dt, 0));
    EXPECT_EQ(w.substeps(), parts(body->getLinearVelocity().length() * dt)) << "closing on its support";
    body->setLinearVelocity(btVector3(6.1, 0, 0));
    body->setAngularVelocity(btVector3(0, 30, 0));  // its corners move 4.3 cm a step
    EXPECT_EQ(w.substeps(), parts((6.1 + 30 * std::sqrt(3.0) * h) * dt)) << "turning";
    body->setAngularVelocity(btVector3(0, 1.0, 0));  // 1.4 mm, against 2.5 mm
    EXPECT_EQ(w.substeps(), 1) << "turning slowly";
    body->setAngularVelocity(btVector3(0, 2.0, 0));  // 2.9 mm
    EXPECT_EQ(w.substeps(), parts((6.1 + 2.0 * std::sqrt(3.0) * h) * dt)) << "turning faster";
    body->setLinearVelocity(btVector3(0, 0, 0));
    body->setAngularVelocity(btVector3(0, 0, 0));
  }
  // Sliding to within its reach of the table's edge, where it may tip.
  const double reach = 6.1 * dt + 0.5 * kG * dt * dt + gContactBreakingThreshold;
  onTable.setLinearVelocity(btVector3(6.1, 0, 0));
  place(onTable, btVector3(w.table().xRight() - h - reach / 2, seated(top + h), 0));
  EXPECT_EQ(w.substeps(), 5) << "near the table's edge";
}

}  // namespace
}  // namespace tabletop
