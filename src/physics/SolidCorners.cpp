#include "physics/SolidCorners.h"

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "physics/ContactResult.h"

namespace tabletop {
namespace {

constexpr int kRimPoints = 32;  // a cylinder's rims, as points

// Heights or spans that differ by less than this are a tie, m: a tie goes
// to the corner that comes first in the solid's own order.
constexpr btScalar kLevel = 1e-6;

}  // namespace

std::vector<btVector3> solidCorners(const btConvexShape& solid, const btVector3& down) {
  std::vector<btVector3> out;
  if (solid.getShapeType() == CYLINDER_SHAPE_PROXYTYPE) {
    const btVector3 half = static_cast<const btCylinderShape&>(solid).getHalfExtentsWithMargin();
    for (int i = 0; i < kRimPoints; ++i) {
      const double a = 2.0 * SIMD_PI * i / kRimPoints;
      for (const double y : {-half.y(), half.y()}) out.emplace_back(half.x() * std::cos(a), y, half.z() * std::sin(a));
    }
    return out;
  }
  const auto& polyhedron = static_cast<const btPolyhedralConvexShape&>(solid);
  const btScalar outset = solid.getShapeType() == BOX_SHAPE_PROXYTYPE ? btScalar(0) : solid.getMargin();
  for (int i = 0; i < polyhedron.getNumVertices(); ++i) {
    btVector3 v;
    polyhedron.getVertex(i, v);
    out.push_back(v + down * outset);
  }
  return out;
}

std::vector<NearCorner> nearCorners(const btConvexShape& solid, const btTransform& pose, const btVector3& normal,
                                    btScalar offset, btScalar threshold, const Approach& approach) {
  const btRigidBody* moving = btRigidBody::upcast(approach.solid);
  const btRigidBody* support = btRigidBody::upcast(approach.support);
  const auto velocity = [](const btRigidBody* body, const btVector3& at) {
    return body ? body->getVelocityInLocalPoint(at - body->getCenterOfMassPosition()) : btVector3(0, 0, 0);
  };
  std::vector<NearCorner> near;
  const std::vector<btVector3> corners = solidCorners(solid, pose.getBasis().transpose() * -normal);
  for (int c = 0; c < static_cast<int>(corners.size()); ++c) {
    const btVector3 vertex = pose * corners[static_cast<std::size_t>(c)];
    const btScalar distance = normal.dot(vertex) - offset;
    if (distance > threshold) continue;
    const btScalar closing = normal.dot(velocity(moving, vertex) - velocity(support, vertex));
    near.push_back({c, distance, vertex, distance + std::min(closing, btScalar(0)) * approach.timeStep});
  }
  return near;
}

void addCornerPoints(btManifoldResult& result, const std::vector<NearCorner>& chosen, const btVector3& normal,
                     bool supportFirst) {
  auto* distinct = dynamic_cast<ContactResult*>(&result);
  if (distinct) distinct->setEachPointDistinct(true);
  for (const auto& [corner, distance, vertex, arrival] : chosen) {
    if (supportFirst) {
      result.addContactPoint(-normal, vertex, distance);
    } else {
      result.addContactPoint(normal, vertex - normal * distance, distance);
    }
  }
  if (distinct) distinct->setEachPointDistinct(false);
}

std::vector<NearCorner> CornerChoice::choose(const btConvexShape& solid, std::vector<NearCorner> near) {
  btVector3 low, high;
  solid.getAabb(btTransform::getIdentity(), low, high);
  const btVector3 size = high - low;
  const btScalar band = 0.05 * std::min({size.x(), size.y(), size.z()});
  btScalar lowest = BT_LARGE_FLOAT, lowestArrival = BT_LARGE_FLOAT;
  for (const NearCorner& c : near) lowest = std::min(lowest, c.distance), lowestArrival = std::min(lowestArrival, c.arrival);
  near.erase(std::remove_if(near.begin(), near.end(),
                            [&](const NearCorner& c) { return std::min(c.distance, c.arrival) > lowest + band; }),
             near.end());
  const std::size_t wanted = std::min<std::size_t>(MANIFOLD_CACHE_SIZE, near.size());

  std::vector<NearCorner> chosen;
  btScalar keptLowest = BT_LARGE_FLOAT, keptArrival = BT_LARGE_FLOAT;
  for (const int k : kept_) {
    const auto found = std::find_if(near.begin(), near.end(), [&](const NearCorner& c) { return c.corner == k; });
    if (found == near.end()) break;
    chosen.push_back(*found);
    keptLowest = std::min(keptLowest, found->distance);
    keptArrival = std::min(keptArrival, found->arrival);
  }
  if (chosen.size() == kept_.size() && chosen.size() == wanted && keptLowest <= lowest + kReach &&
      keptArrival <= lowestArrival + kReach) {
    return chosen;
  }

  // Afresh: the lowest first, then each the farthest from those chosen.
  chosen.assign(1, *std::find_if(near.begin(), near.end(),
                                 [&](const NearCorner& c) { return c.distance <= lowest + kLevel; }));
  while (chosen.size() < wanted) {
    std::size_t best = 0;
    btScalar farthest = -1;
    for (std::size_t i = 0; i < near.size(); ++i) {
      btScalar closest = BT_LARGE_FLOAT;
      for (const NearCorner& c : chosen) closest = std::min(closest, (near[i].point - c.point).length());
      if (closest > farthest + kLevel) farthest = closest, best = i;
    }
    if (farthest <= kLevel) break;
    chosen.push_back(near[best]);
  }
  kept_.clear();
  for (const NearCorner& c : chosen) kept_.push_back(c.corner);
  return chosen;
}

}  // namespace tabletop
