#include "draw/SceneDrawing.h"

#include <algorithm>
#include <cmath>

#include "core/Angle.h"
#include "core/Quat.h"

namespace tabletop {
namespace {

// How far the floor reaches around the table, in table sizes, and past
// the farthest entity; at most kMostFloorTiles tiles a side (they grow).
constexpr double kFloorReach = 3.0;
constexpr double kFloorBeyond = 1.5;
constexpr double kMostFloorTiles = 200.0;

// The arrow's head stops this far short of the face, metres.
constexpr double kArrowGap = 0.005;

DrawShape shapeOf(const EntitySpec& spec, const EntityState& state) {
  DrawShape d;
  d.name = spec.name;
  d.position = state.position;
  d.orientation = state.orientation;
  d.colour = spec.colour;
  const ShapeGeometry g = spec.geometry;
  switch (g.kind()) {
    case ShapeKind::Cube:
    case ShapeKind::SolidBox: d.primitive = Primitive::Box, d.size = g.halfExtents(); break;
    case ShapeKind::Sphere: d.primitive = Primitive::Sphere, d.size = {g.radius(), 0, 0}; break;
    case ShapeKind::Cylinder:
      d.primitive = Primitive::Cylinder, d.size = {g.radius(), g.topRadius(), g.height()};
      d.baseOffset = g.centroidHeight();
      break;
  }
  return d;
}

// Distance from the centre to the surface along the horizontal unit `dir`.
double reach(const DrawShape& d, const EntityState& state, const Vec3& dir) {
  switch (d.primitive) {
    case Primitive::Sphere: return d.size.x;
    case Primitive::Cylinder: return std::max(d.size.x, d.size.y);
    case Primitive::Box: {
      // The support distance of a box turned by its yaw.
      const double yaw = convertAngle(state.yawDegrees);
      const double along = dir.x * std::cos(yaw) - dir.z * std::sin(yaw);
      const double across = dir.x * std::sin(yaw) + dir.z * std::cos(yaw);
      return std::abs(along) * d.size.x + std::abs(across) * d.size.z;
    }
  }
  return 0.0;
}

double sizeOf(const DrawShape& d) {
  switch (d.primitive) {
    case Primitive::Box: return 2.0 * std::max({d.size.x, d.size.y, d.size.z});
    case Primitive::Sphere: return 2.0 * d.size.x;
    case Primitive::Cylinder: return std::max({2.0 * d.size.x, 2.0 * d.size.y, d.size.z});
  }
  return 0.0;
}

}  // namespace

DrawArrow arrowFor(const Arrow& arrow, const EntitySpec& spec, const EntityState& state) {
  const DrawShape d = shapeOf(spec, state);
  const Vec3 dir = pushDirection(arrow.worldAngleDegrees(spec.geometry.kind() == ShapeKind::Sphere ? 0.0 : state.yawDegrees));
  DrawArrow a;
  if (arrow.at) {
    const auto& q = state.orientation;
    a.head = state.position + Quat{q[0], q[1], q[2], q[3]}.rotate(*arrow.at) - dir * kArrowGap;
  } else {
    a.head = state.position - dir * (reach(d, state, dir) + kArrowGap);
  }
  a.tail = a.head - dir * (1.2 * sizeOf(d));
  a.radius = std::clamp(0.08 * sizeOf(d), 0.002, 0.02);
  return a;
}

DrawList makeDrawList(const Scenario& scenario, const std::vector<EntityState>& states,
                      const std::optional<Arrow>& arrow, const std::vector<Vec3>& contacts,
                      const DrawOptions& options) {
  const TableSpec& t = scenario.table;
  DrawList list;

  DrawShape top;
  top.name = "table";
  top.primitive = Primitive::Box;
  top.size = {0.5 * t.width, 0.5 * t.thickness, 0.5 * t.depth};
  top.position = {t.centreX, t.height - 0.5 * t.thickness, t.centreZ};
  top.colour = t.colour;
  list.table.push_back(top);
  for (int i = 0; i < 4; ++i) {
    DrawShape leg;
    leg.name = "table leg";
    leg.primitive = Primitive::Cylinder;
    const double h = t.height - t.thickness;
    leg.size = {t.legRadius, t.legRadius, h};
    leg.position = t.legCentre(i);
    leg.baseOffset = 0.5 * h;
    leg.colour = {static_cast<int>(0.8 * t.colour.r), static_cast<int>(0.8 * t.colour.g),
                  static_cast<int>(0.8 * t.colour.b)};
    list.table.push_back(leg);
  }

  for (std::size_t i = 0; i < states.size() && i < scenario.entities.size(); ++i) {
    list.entities.push_back(shapeOf(scenario.entities[i], states[i]));
  }
  if (arrow && options.arrow) {
    for (std::size_t i = 0; i < list.entities.size(); ++i) {
      if (scenario.entities[i].name == arrow->entity) list.arrow = arrowFor(*arrow, scenario.entities[i], states[i]);
    }
  }
  if (options.contacts) list.contacts = contacts;

  list.tableTop = {t.height, t.centreX - 0.5 * t.width, t.centreX + 0.5 * t.width, t.centreZ - 0.5 * t.depth,
                   t.centreZ + 0.5 * t.depth};
  double reachOut = std::max(kFloorReach * std::max({t.width, t.depth, t.height}), options.floorReach);
  for (const EntityState& s : states) {
    reachOut = std::max(reachOut, kFloorBeyond * std::max(std::abs(s.position.x - t.centreX),
                                                          std::abs(s.position.z - t.centreZ)));
  }
  list.floor = {0.0, t.centreX - reachOut, t.centreX + reachOut, t.centreZ - reachOut, t.centreZ + reachOut};
  list.floorTile = std::max(0.5 * std::max(t.width, t.depth) / 1.2, 2.0 * reachOut / kMostFloorTiles);
  // The lamp hangs above the table, a little to the left and to the front,
  // so shadows fall to the right and back as in the report's picture.
  const double size = std::max({t.width, t.depth, t.height});
  list.lamp = {t.centreX - 0.6 * size, t.height + 2.5 * size, t.centreZ + 0.8 * size};
  return list;
}

std::vector<Camera::Bound> sceneBounds(const Scenario& scenario, const std::vector<EntityState>& states) {
  const TableSpec& t = scenario.table;
  std::vector<Camera::Bound> bounds;
  // The table as its eight corners, from the floor to its top.
  for (const double x : {t.centreX - 0.5 * t.width, t.centreX + 0.5 * t.width}) {
    for (const double z : {t.centreZ - 0.5 * t.depth, t.centreZ + 0.5 * t.depth}) {
      for (const double y : {0.0, t.height}) bounds.push_back({{x, y, z}, 0.0});
    }
  }
  for (std::size_t i = 0; i < states.size() && i < scenario.entities.size(); ++i) {
    bounds.push_back({states[i].position, scenario.entities[i].geometry.boundingRadius()});
  }
  return bounds;
}

}  // namespace tabletop
