// Mass properties against closed forms and against Bullet's own formulas.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>

#include "core/Angle.h"
#include "physics/shapes/Cube.h"
#include "physics/shapes/Cylinder.h"
#include "physics/shapes/SolidBox.h"
#include "physics/shapes/Sphere.h"

namespace tabletop {
namespace {

// Relative tolerance for closed forms evaluated two ways: a few ulps of the
// build's scalar (Bullet stores vectors as btScalar: float or double).
constexpr double kRel = 16 * std::numeric_limits<btScalar>::epsilon();

void expectInertia(const btVector3& actual, double ix, double iy, double iz) {
  EXPECT_NEAR(actual.x(), ix, kRel * ix);
  EXPECT_NEAR(actual.y(), iy, kRel * iy);
  EXPECT_NEAR(actual.z(), iz, kRel * iz);
}

btVector3 bulletInertia(btCollisionShape& shape, double mass) {
  btVector3 i;
  shape.calculateLocalInertia(mass, i);
  return i;
}

// A cube's moment about any axis through its centre is m s^2 / 6.
TEST(Cube, InertiaIsMassTimesSideSquaredOverSix) {
  Cube cube("A", 0.1);
  expectInertia(cube.localInertia(0.6), 0.001, 0.001, 0.001);  // 0.6 * 0.01 / 6
  EXPECT_NEAR(cube.volume(), 1e-3, kRel * 1e-3);
  const btVector3 b = bulletInertia(cube.collisionShape(), 0.6);
  expectInertia(b, 0.001, 0.001, 0.001);
}

// A box w x h x d: I_x = m (h^2 + d^2) / 12, and so on.
TEST(SolidBox, InertiaMatchesClosedFormAndBullet) {
  SolidBox box("B", 0.3, 0.1, 0.2);
  const double m = 1.2;
  expectInertia(box.localInertia(m), m * (0.01 + 0.04) / 12, m * (0.09 + 0.04) / 12,
                m * (0.09 + 0.01) / 12);
  const btVector3 b = bulletInertia(box.collisionShape(), m);
  expectInertia(box.localInertia(m), b.x(), b.y(), b.z());
  EXPECT_NEAR(box.volume(), 0.006, kRel * 0.006);
}

// A solid ball: 2/5 m r^2.
TEST(Sphere, InertiaIsTwoFifthsMassRadiusSquared) {
  Sphere ball("S", 0.04);
  const double i = 0.4 * 0.25 * 0.0016;
  expectInertia(ball.localInertia(0.25), i, i, i);
  expectInertia(bulletInertia(ball.collisionShape(), 0.25), i, i, i);
  EXPECT_NEAR(ball.volume(), 4.0 / 3.0 * kPi * 6.4e-5, kRel * 3e-4);
}

// A solid cylinder: m r^2 / 2 about its axis, m (3 r^2 + h^2) / 12 across.
TEST(Cylinder, EqualRadiiMatchSolidCylinder) {
  Cylinder c("C", 0.05, 0.05, 0.3);
  const double m = 2.0;
  const double axial = m * 0.0025 / 2;
  const double transverse = m * (3 * 0.0025 + 0.09) / 12;
  expectInertia(c.localInertia(m), transverse, axial, transverse);
  expectInertia(bulletInertia(c.collisionShape(), m), transverse, axial, transverse);
  EXPECT_NEAR(c.centroidHeight(), 0.15, kRel * 0.15);
  EXPECT_NEAR(c.volume(), kPi * 0.0025 * 0.3, kRel * 0.0024);
}

// As the top radius shrinks the frustum becomes a cone: centroid at h/4,
// I_axis = 3/10 m R^2, I_across = 3/20 m R^2 + 3/80 m h^2 about the centroid.
TEST(Cylinder, FrustumTendsToCone) {
  const double R = 0.1, h = 0.4, m = 3.0;
  Cylinder cone("K", R, 1e-7, h);
  // The 1e-7 m top radius moves each quantity by about 1e-6 relative.
  const double tol = 1e-5;
  EXPECT_NEAR(cone.centroidHeight(), h / 4, tol * h);
  const btVector3 i = cone.localInertia(m);
  EXPECT_NEAR(i.y(), 0.3 * m * R * R, tol * 0.3 * m * R * R);
  const double across = 0.15 * m * R * R + 3.0 / 80.0 * m * h * h;
  EXPECT_NEAR(i.x(), across, tol * across);
  EXPECT_NEAR(cone.volume(), kPi * R * R * h / 3, tol * kPi * R * R * h / 3);
}

// A frustum's volume: pi h (R^2 + R r + r^2) / 3.
TEST(Cylinder, FrustumVolume) {
  Cylinder f("F", 0.2, 0.1, 0.3);
  EXPECT_NEAR(f.volume(), kPi * 0.3 * (0.04 + 0.02 + 0.01) / 3, kRel * 0.022);
  EXPECT_NEAR(f.below() + f.above(), 0.3, kRel * 0.3);
  EXPECT_LT(f.below(), 0.15);  // the wide base pulls the centroid down
}

// Bullet's 4 cm default margin would exceed a 2 cm cube's 1 cm half side.
TEST(Shape, MarginScalesWithTheBody) {
  Cube small("s", 0.02);
  EXPECT_NEAR(small.collisionShape().getMargin(), 0.05 * 0.01, kRel * 5e-4);
  Cube large("L", 5.0);
  EXPECT_NEAR(large.collisionShape().getMargin(), 0.04, kRel * 0.04);
  // The box keeps its outer size whatever the margin.
  const btVector3 outer = static_cast<btBoxShape&>(small.collisionShape()).getHalfExtentsWithMargin();
  EXPECT_NEAR(outer.x(), 0.01, kRel * 0.01);
}

// The faces a box's separating-axis test clips lie at its half extents,
// to rounding, for every size: Bullet's own hull step left 28% of sizes
// from 1 mm to 1 m small, a 46 mm cube's by 4.5 um (SolidBox.h).
TEST(SolidBox, PolyhedronCornersAndFacesLieAtTheHalfExtents) {
  for (int k = 1; k <= 400; ++k) {
    const double width = 0.0025 * k;  // 2.5 mm to 1 m
    const SolidBox box("b", width, 0.6 * width, 1.3 * width);
    const auto& shape = static_cast<const btBoxShape&>(box.collisionShape());
    const btConvexPolyhedron& polyhedron = *shape.getConvexPolyhedron();
    const btVector3 half = box.halfExtents();
    ASSERT_EQ(polyhedron.m_vertices.size(), 8) << width;
    ASSERT_EQ(polyhedron.m_faces.size(), 6) << width;
    for (int v = 0; v < polyhedron.m_vertices.size(); ++v) {
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(std::abs(polyhedron.m_vertices[v][a]), half[a], 1e-15) << width << " m, corner " << v;
      }
    }
    for (int f = 0; f < polyhedron.m_faces.size(); ++f) {
      const btScalar* plane = polyhedron.m_faces[f].m_plane;
      const btVector3 normal(plane[0], plane[1], plane[2]);
      const int axis = normal.absolute().maxAxis();
      EXPECT_NEAR(normal.length(), 1.0, 1e-15) << width << " m, face " << f;
      EXPECT_NEAR(std::abs(normal[axis]), 1.0, 1e-15) << width << " m, face " << f;
      EXPECT_NEAR(-plane[3], half[axis], 1e-15) << width << " m, face " << f;
    }
  }
}

// The polyhedron is the one Bullet's own initialize() makes of it (the same
// edge directions in the same order, the same centre, to the bit), but for
// the box inside it that the separating-axis test skips axes by: that is
// the box itself, a millionth smaller, and still inside every face, where
// Bullet's search finds a box no larger.
TEST(SolidBox, PolyhedronIsBulletsWithTheWholeBoxInside) {
  for (int k = 1; k <= 400; k += 7) {
    const double width = 0.0025 * k;
    const SolidBox box("b", width, 0.6 * width, 1.3 * width);
    const btConvexPolyhedron& ours = *static_cast<const btBoxShape&>(box.collisionShape()).getConvexPolyhedron();
    btConvexPolyhedron bullets = ours;
    bullets.m_uniqueEdges.clear();
    bullets.initialize();
    ASSERT_EQ(ours.m_uniqueEdges.size(), bullets.m_uniqueEdges.size()) << width;
    for (int e = 0; e < ours.m_uniqueEdges.size(); ++e) {
      EXPECT_EQ(ours.m_uniqueEdges[e], bullets.m_uniqueEdges[e]) << width << " m, edge " << e;
    }
    EXPECT_EQ(ours.m_localCenter, bullets.m_localCenter) << width;
    EXPECT_TRUE(ours.testContainment()) << width;
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(ours.m_extents[a], bullets.m_extents[a] * (1.0 - 1e-6)) << width << " m, axis " << a;
      EXPECT_NEAR(ours.m_extents[a], box.halfExtents()[a], 2e-6 * box.halfExtents()[a]) << width;
    }
    EXPECT_LE(ours.m_radius, bullets.m_radius) << width;
  }
}

// A push on a box face meets the surface where the ray from the centre
// leaves the box.
TEST(SolidBox, SurfaceDistanceAlongAHorizontalRay) {
  SolidBox box("B", 0.4, 0.1, 0.2);
  EXPECT_NEAR(box.surfaceDistance(btVector3(1, 0, 0)), 0.2, kRel * 0.2);
  EXPECT_NEAR(box.surfaceDistance(btVector3(0, 0, -1)), 0.1, kRel * 0.1);
  const double c = std::cos(kPi / 4);
  EXPECT_NEAR(box.surfaceDistance(btVector3(c, 0, c)), 0.1 / c, kRel * 0.15);
}

// How far a body reaches along a world direction: a 0.1 m cube at height
// 1 m reaches 1.05 m up; turned 45 degrees about Z, its edge reaches
// 1 + 0.05 sqrt(2) m; a sphere of 0.03 m at the same centre reaches
// 0.97 m down (-0.97 along -Y). Within a few ulps.
TEST(Shape, ReachIsTheSupportPointAlongADirection) {
  const btVector3 up(0, 1, 0);
  Cube cube("c", 0.1);
  cube.createBody(1.0, Material{}, btTransform(btQuaternion::getIdentity(), btVector3(0.3, 1.0, -0.2)));
  EXPECT_NEAR(cube.reach(up), 1.05, kRel);
  cube.body()->setWorldTransform(btTransform(btQuaternion(btVector3(0, 0, 1), 0.25 * SIMD_PI), btVector3(0.3, 1.0, -0.2)));
  EXPECT_NEAR(cube.reach(up), 1.0 + 0.05 * std::sqrt(2.0), kRel);
  Sphere ball("s", 0.03);
  ball.createBody(1.0, Material{}, btTransform(btQuaternion::getIdentity(), btVector3(0.3, 1.0, -0.2)));
  EXPECT_NEAR(ball.reach(-up), -0.97, kRel);
}

}  // namespace
}  // namespace tabletop
