// The camera against the pinhole model's closed form, and the arrow's
// place on its face.

#include <cmath>

#include <gtest/gtest.h>

#include "draw/Camera.h"
#include "draw/SceneDrawing.h"

namespace tabletop {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The target lands in the image's centre; a point h metres above it, on a
// view looking straight along -Z, lands f h / d pixels higher, with the
// focal length f = (H / 2) / tan(fovy / 2) (to 1e-9 px).
TEST(Camera, ProjectsLikeAPinhole) {
  Camera c;
  c.target = {0.3, 0.5, -0.2};
  c.yawDegrees = 0.0, c.pitchDegrees = 0.0, c.distance = 2.0, c.fovyDegrees = 40.0;
  const auto centre = c.project(c.target, 640, 480);
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->column, 320.0, 1e-9);
  EXPECT_NEAR(centre->row, 240.0, 1e-9);
  EXPECT_NEAR(centre->depth, 2.0, 1e-12);
  const double f = 240.0 / std::tan(20.0 * kPi / 180.0);
  const auto up = c.project(c.target + Vec3{0.1, 0.2, 0.0}, 640, 480);
  ASSERT_TRUE(up);
  EXPECT_NEAR(up->row, 240.0 - f * 0.2 / 2.0, 1e-9);
  EXPECT_NEAR(up->column, 320.0 + f * 0.1 / 2.0, 1e-9);
  EXPECT_FALSE(c.project(c.eye() + Vec3{0, 0, 1.0}, 640, 480)) << "behind the eye";
}

// A fitted camera keeps every ball wholly in the image (its centre and the
// points a radius to either side, across and up) for every preset
// direction, aspect and spread of balls, and fits tight: some ball reaches
// the margin's edge within a pixel.
TEST(Camera, FitKeepsEveryBallInViewAndFitsTight) {
  const TableSpec table;
  const std::vector<std::vector<Camera::Bound>> scenes = {
      {{{0, 0.75, 0}, 0.05}},
      {{{-0.6, 0, -0.4}, 0}, {{0.6, 0.75, 0.4}, 0}, {{2.45, 0.05, -0.47}, 0.05}},
      {{{0, 0.4, 0}, 2.5}, {{-3, 0.1, 1}, 0.1}},
      {{{0.1, 0.2, 0.3}, 0.01}, {{0.1, 3.5, 0.3}, 0.05}},
  };
  for (const std::string& name : Camera::names()) {
    for (const auto& [w, h] : {std::pair{960, 720}, std::pair{1280, 480}, std::pair{480, 960}}) {
      for (const auto& bounds : scenes) {
        Camera c = *Camera::named(name, table);
        c.fit(bounds, double(w) / h, 0.05);
        double closest = 1e9;  // px from a ball's edge to the margin's edge
        for (const Camera::Bound& b : bounds) {
          const Mat4 v = c.view();
          const Vec3 right{v.at(0, 0), v.at(0, 1), v.at(0, 2)}, up{v.at(1, 0), v.at(1, 1), v.at(1, 2)};
          for (const Vec3& p : {b.centre, b.centre + right * b.radius, b.centre - right * b.radius,
                                b.centre + up * b.radius, b.centre - up * b.radius}) {
            const auto px = c.project(p, w, h);
            ASSERT_TRUE(px) << name;
            EXPECT_GE(px->column, 0.0) << name;
            EXPECT_LE(px->column, w) << name;
            EXPECT_GE(px->row, 0.0) << name;
            EXPECT_LE(px->row, h) << name;
            closest = std::min({closest, px->column, w - px->column, px->row, h - px->row});
          }
        }
        if (bounds.size() > 1) {
          EXPECT_LT(closest, 0.05 * std::max(w, h)) << name << " " << w << "x" << h;
        }
      }
    }
  }
}

TEST(Camera, OrbitKeepsTheDistanceAndPitchStaysBelowTheVertical) {
  Camera c;
  c.orbit(30.0, 100.0);
  EXPECT_NEAR(c.pitchDegrees, 89.0, 1e-12);
  EXPECT_NEAR((c.eye() - c.target).length(), c.distance, 1e-12);
  EXPECT_NEAR(c.yawDegrees, 30.0, 1e-12);
}

TEST(Camera, NamedViewsFrameTheTable) {
  TableSpec table;
  for (const std::string& name : Camera::names()) {
    const auto c = Camera::named(name, table);
    ASSERT_TRUE(c) << name;
    for (double x : {-0.5 * table.width, 0.5 * table.width}) {
      for (double z : {-0.5 * table.depth, 0.5 * table.depth}) {
        const auto p = c->project({x, table.height, z}, 640, 480);
        ASSERT_TRUE(p) << name;
        EXPECT_TRUE(p->column > 0 && p->column < 640 && p->row > 0 && p->row < 480)
            << name << ": a table corner is out of the picture";
      }
    }
  }
  EXPECT_FALSE(Camera::named("ceiling", table));
}

// The arrow's head stops 5 mm short of the pushed face: for a cube of side
// s pushed on its Left face, at x - s/2 - 0.005, pointing +X.
TEST(SceneDrawing, ArrowHeadTouchesThePushedFace) {
  EntitySpec cube;
  cube.name = "A";
  cube.geometry = ShapeGeometry::cube(0.1);
  EntityState state;
  state.position = {0.2, 0.8, -0.1};
  Arrow arrow;
  arrow.entity = "A";
  arrow.face = DirectionDef::Left;
  const DrawArrow a = arrowFor(arrow, cube, state);
  EXPECT_NEAR(a.head.x, 0.2 - 0.05 - 0.005, 1e-12);
  EXPECT_NEAR(a.head.z, -0.1, 1e-12);
  EXPECT_NEAR(a.head.y, 0.8, 1e-12);
  EXPECT_LT(a.tail.x, a.head.x);
  // Turned by 90 degrees, the Left face looks along -Z (report 3.8: Z' = Z - Step sin(Angle)).
  state.yawDegrees = 90.0;
  const DrawArrow turned = arrowFor(arrow, cube, state);
  EXPECT_NEAR(turned.head.z, -0.1 + 0.05 + 0.005, 1e-9);
  EXPECT_GT(turned.tail.z, turned.head.z);
}

// A push "at" a point of the body is drawn with its head 5 mm short of that
// point, the point turned with the body: at (-0.05, 0.02, 0.03) on a cube
// turned 90 degrees about +Y, the point is (0.03, 0.02, 0.05) from the
// centre (x' = x cos + z sin, z' = -x sin + z cos); pushed on its Left
// face, the arrow points along -Z.
TEST(SceneDrawing, ArrowHeadIsAtThePointAPushActsAt) {
  EntitySpec cube;
  cube.name = "A";
  cube.geometry = ShapeGeometry::cube(0.1);
  EntityState state;
  state.position = {0.2, 0.8, -0.1};
  state.yawDegrees = 90.0;
  const double h = std::sqrt(0.5);
  state.orientation = {h, 0.0, h, 0.0};
  Arrow arrow;
  arrow.entity = "A";
  arrow.face = DirectionDef::Left;
  arrow.at = Vec3{-0.05, 0.02, 0.03};
  const DrawArrow a = arrowFor(arrow, cube, state);
  EXPECT_NEAR(a.head.x, 0.2 + 0.03, 1e-12);
  EXPECT_NEAR(a.head.y, 0.8 + 0.02, 1e-12);
  EXPECT_NEAR(a.head.z, -0.1 + 0.05 + 0.005, 1e-12);
  EXPECT_GT(a.tail.z, a.head.z);
}

}  // namespace
}  // namespace tabletop

namespace tabletop {
namespace {

// The floor reaches past every entity, and past what a render asks for,
// with at most 200 tiles a side however far that is.
TEST(SceneDrawing, FloorReachesPastEveryEntityInBoundedTiles) {
  Scenario scene;
  EntitySpec e;
  e.name = "far";
  scene.entities.push_back(e);
  for (const double x : {0.5, 30.0, 9000.0}) {
    EntityState s;
    s.name = "far";
    s.position = {x, 0.05, -0.2};
    const DrawList list = makeDrawList(scene, {s}, std::nullopt, {});
    EXPECT_GT(list.floor.xMax, x) << x;
    EXPECT_LE((list.floor.xMax - list.floor.xMin) / list.floorTile, 200.0 + 1e-9) << x;
  }
  DrawOptions options;
  options.floorReach = 50.0;
  const DrawList asked = makeDrawList(scene, {EntityState{}}, std::nullopt, {}, options);
  EXPECT_GE(asked.floor.zMax - scene.table.centreZ, 50.0);
}

}  // namespace
}  // namespace tabletop
