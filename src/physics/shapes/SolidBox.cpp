#include "physics/shapes/SolidBox.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>

#include "core/ShapeGeometry.h"
#include "physics/shapes/CollisionMargin.h"

namespace tabletop {
namespace {

// btBoxShape keeps its outer size: the margin is taken from inside the half
// extents, so the box is exact for box-box and box-plane contacts. Its faces
// and edges are built for polyhedral clipping (see World: box-box contacts).
std::unique_ptr<btCollisionShape> makeBox(const btVector3& half, double margin) {
  auto box = std::make_unique<btBoxShape>(half);
  box->setMargin(margin);
  initializeExactBoxFeatures(*box);
  return box;
}

// What btConvexPolyhedron::initialize() makes of the exact box, in its
// order (the unique edge directions, the area-weighted centre), but for
// the box inside it that Bullet's separating-axis test uses to skip an axis
// early (m_extents, m_radius): Bullet searches for it with up to 2048
// containment tests of 8 corners against every face, per box and world,
// the largest single cost of a short run. For a box it is the box itself,
// taken a millionth smaller so that rounding keeps it inside; an axis is
// skipped only where it cannot win, so the contacts found are the same.
void finishBoxPolyhedron(btConvexPolyhedron& p, const btVector3& half) {
  const auto almostZero = [](const btVector3& v) {
    return btFabs(v.x()) <= 1e-6 && btFabs(v.y()) <= 1e-6 && btFabs(v.z()) <= 1e-6;
  };
  p.m_uniqueEdges.clear();
  for (int f = 0; f < p.m_faces.size(); ++f) {
    const btAlignedObjectArray<int>& at = p.m_faces[f].m_indices;
    for (int j = 0; j < at.size(); ++j) {
      const int a = at[j], b = at[(j + 1) % at.size()];
      btVector3 edge = p.m_vertices[std::min(a, b)] - p.m_vertices[std::max(a, b)];
      edge.normalize();
      bool found = false;
      for (int u = 0; u < p.m_uniqueEdges.size() && !found; ++u) {
        found = almostZero(p.m_uniqueEdges[u] - edge) || almostZero(p.m_uniqueEdges[u] + edge);
      }
      if (!found) p.m_uniqueEdges.push_back(edge);
    }
  }
  btScalar area = 0;
  p.m_localCenter.setValue(0, 0, 0);
  for (int f = 0; f < p.m_faces.size(); ++f) {
    const btAlignedObjectArray<int>& at = p.m_faces[f].m_indices;
    const btVector3& p0 = p.m_vertices[at[0]];
    for (int j = 1; j <= at.size() - 2; ++j) {
      const btVector3& p1 = p.m_vertices[at[j]];
      const btVector3& p2 = p.m_vertices[at[(j + 1) % at.size()]];
      const btScalar triangle = ((p0 - p1).cross(p0 - p2)).length() * btScalar(0.5);
      p.m_localCenter += triangle * ((p0 + p1 + p2) / btScalar(3.0));
      area += triangle;
    }
  }
  p.m_localCenter /= area;
  constexpr btScalar kInside = 1.0 - 1e-6;
  p.m_extents = half * kInside;
  p.m_radius = half[half.minAxis()] * kInside;
  p.mC.setValue(0, 0, 0);
  p.mE = half * 2;
}

// Bullet's hull of a box whose longest side is along `maxAxis` and
// shortest along `minAxis`, as its hull computer names them: it scales
// each axis of the corners to the same integer range and lays them out by
// those two axes, so every such box gets the same vertices and faces in
// the same order (tests/physics/shapes/SolidBoxTest.cpp holds that over
// sizes and shapes).
btConvexPolyhedron boxHull(int maxAxis, int minAxis) {
  btVector3 half(2, 2, 2);
  half[maxAxis] = 3;
  half[minAxis] = 1;
  btBoxShape box(half);  // features over a shape's own leak: this one is thrown away
  box.initializePolyhedralFeatures();
  return *box.getConvexPolyhedron();
}

}  // namespace

void initializeExactBoxFeatures(btBoxShape& box) {
  // Built once for each layout: building the hull cost each box a million
  // instructions, most in btConvexPolyhedron::initialize's containment
  // search, a quarter of stepping a field of a thousand cubes for half a
  // second.
  static const std::array<btConvexPolyhedron, 9> kHulls = [] {
    std::array<btConvexPolyhedron, 9> hulls;
    for (int maxAxis = 0; maxAxis < 3; ++maxAxis) {
      for (int minAxis = 0; minAxis < 3; ++minAxis) {
        if (minAxis != maxAxis) hulls[static_cast<std::size_t>(3 * maxAxis + minAxis)] = boxHull(maxAxis, minAxis);
      }
    }
    return hulls;
  }();
  const btVector3 half = box.getHalfExtentsWithMargin();
  const int maxAxis = half.maxAxis();
  const int minAxis = half.minAxis() != maxAxis ? half.minAxis() : (maxAxis + 1) % 3;
  btConvexPolyhedron exact = kHulls[static_cast<std::size_t>(3 * maxAxis + minAxis)];
  // Each corner is at +-half on every axis, each face's normal on one axis
  // at half from the centre.
  for (int v = 0; v < exact.m_vertices.size(); ++v) {
    for (int a = 0; a < 3; ++a) exact.m_vertices[v][a] = std::copysign(half[a], exact.m_vertices[v][a]);
  }
  for (int f = 0; f < exact.m_faces.size(); ++f) {
    btScalar* plane = exact.m_faces[f].m_plane;
    const int axis = btVector3(plane[0], plane[1], plane[2]).absolute().maxAxis();
    const btScalar sign = plane[axis] > 0 ? 1 : -1;
    for (int a = 0; a < 3; ++a) plane[a] = a == axis ? sign : 0;
    plane[3] = -half[axis];
  }
  finishBoxPolyhedron(exact, half);
  box.setPolyhedralFeatures(exact);
}

SolidBox::SolidBox(std::string name, double width, double height, double depth)
    : Shape(std::move(name),
            makeBox(btVector3(width, height, depth) * 0.5,
                    collisionMargin(0.5 * std::min({width, height, depth})))),
      half_(btVector3(width, height, depth) * 0.5) {}

// The box's geometry, from the sides its half extents were made from.
static ShapeGeometry boxGeometry(const btVector3& half) {
  return ShapeGeometry::box(2.0 * half.x(), 2.0 * half.y(), 2.0 * half.z());
}

double SolidBox::volume() const { return boxGeometry(half_).volume(); }

btVector3 SolidBox::localInertia(double mass) const {
  const Vec3 i = boxGeometry(half_).inertia(mass);
  return btVector3(i.x, i.y, i.z);
}

// A ray from the centre along a horizontal direction leaves the box through
// the first face it meets.
double SolidBox::surfaceDistance(const btVector3& direction) const {
  double t = std::numeric_limits<double>::infinity();
  if (std::abs(direction.x()) > 1e-12) t = std::min(t, double(half_.x() / std::abs(direction.x())));
  if (std::abs(direction.z()) > 1e-12) t = std::min(t, double(half_.z() / std::abs(direction.z())));
  return std::isfinite(t) ? t : 0.0;
}

}  // namespace tabletop
