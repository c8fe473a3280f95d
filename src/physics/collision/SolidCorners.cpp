#include "physics/collision/SolidCorners.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "physics/collision/ContactResult.h"
#include "physics/shapes/RoundEnds.h"

namespace tabletop {
namespace {

// Heights or spans that differ by less than this are a tie, m: a tie goes
// to the corner that comes first in the solid's own order.
constexpr btScalar kLevel = 1e-6;

// A kept point this near a chosen corner (m, on the solid) is that corner.
constexpr btScalar kSameCorner = 1e-6;

// How far above the lowest corner the others count as on the face a solid
// rests on, m: a twentieth of its smallest size.
btScalar faceBand(const btConvexShape& solid) {
  btVector3 low, high;
  solid.getAabb(btTransform::getIdentity(), low, high);
  const btVector3 size = high - low;
  return 0.05 * std::min({size.x(), size.y(), size.z()});
}

// The unit circle at the rims' kRimPoints angles, made once: cosines and
// sines for every rim of every pair, every step, were a pile's largest
// cost in libm.
const std::array<std::pair<btScalar, btScalar>, kRimPoints>& unitRim() {
  static const auto circle = [] {
    std::array<std::pair<btScalar, btScalar>, kRimPoints> c{};
    for (int i = 0; i < kRimPoints; ++i) {
      const double a = 2.0 * SIMD_PI * i / kRimPoints;
      c[static_cast<std::size_t>(i)] = {std::cos(a), std::sin(a)};
    }
    return c;
  }();
  return circle;
}

}  // namespace

std::vector<btVector3> solidCorners(const btConvexShape& solid, const btVector3& down) {
  std::vector<btVector3> out;
  solidCorners(solid, down, out);
  return out;
}

void solidCorners(const btConvexShape& solid, const btVector3& down, std::vector<btVector3>& out) {
  out.clear();
  if (const std::optional<RoundEnds> ends = roundEnds(solid)) {
    rimCorners(*ends, down, {true, true}, out);
    return;
  }
  const auto& polyhedron = static_cast<const btPolyhedralConvexShape&>(solid);
  const btScalar outset = solid.getShapeType() == BOX_SHAPE_PROXYTYPE ? btScalar(0) : solid.getMargin();
  out.reserve(static_cast<std::size_t>(polyhedron.getNumVertices()));
  for (int i = 0; i < polyhedron.getNumVertices(); ++i) {
    btVector3 v;
    polyhedron.getVertex(i, v);
    out.push_back(v + down * outset);
  }
}

void rimCorners(const RoundEnds& ends, const btVector3& down, const std::array<bool, 2>& lowestFirst,
                std::vector<btVector3>& out) {
  // The way down across the rims, as a unit (cos, sin) in the x-z plane.
  const btScalar across = std::hypot(down.x(), down.z());
  const bool defined = across > SIMD_EPSILON;
  out.reserve(out.size() + 2 * kRimPoints);
  for (int e = 0; e < 2; ++e) {
    const btScalar r = ends.radius[e], y = ends.y[e];
    if (r <= 0) {
      out.emplace_back(0, y, 0);
      continue;
    }
    const bool turned = defined && lowestFirst[static_cast<std::size_t>(e)];
    const btScalar c0 = turned ? down.x() / across : 1, s0 = turned ? down.z() / across : 0;
    for (const auto& [c, s] : unitRim()) out.emplace_back(r * (c0 * c - s0 * s), y, r * (s0 * c + c0 * s));
  }
}

void nearCorners(const btConvexShape& solid, const btTransform& pose, const btVector3& normal, btScalar offset,
                 btScalar threshold, const Approach& approach, std::vector<btVector3>& corners,
                 std::vector<NearCorner>& near) {
  const btRigidBody* moving = btRigidBody::upcast(approach.solid);
  const btRigidBody* support = btRigidBody::upcast(approach.support);
  const auto velocity = [](const btRigidBody* body, const btVector3& at) {
    return body ? body->getVelocityInLocalPoint(at - body->getCenterOfMassPosition()) : btVector3(0, 0, 0);
  };
  const btVector3 down = pose.getBasis().transpose() * -normal;
  const std::optional<RoundEnds> ends = roundEnds(solid);
  // A rim lying out of level touches the plane at its lowest point alone:
  // its other points, turning down as it rolls, would close on the plane
  // along straight lines and hold it back. One within the face's band of
  // level, or that may turn into it within the step, keeps its points at
  // fixed angles on the body, as a resting or landing face needs.
  std::array<bool, 2> lying{false, false};
  if (ends) {
    const auto spin = [](const btRigidBody* body) { return body ? body->getAngularVelocity() : btVector3(0, 0, 0); };
    const btVector3 axis = pose.getBasis().getColumn(1);
    const btScalar tilt = axis.cross(normal).length();
    const btScalar tilting = (spin(moving) - spin(support)).cross(axis).length() * approach.timeStep;
    const btScalar band = faceBand(solid);
    for (std::size_t e = 0; e < 2; ++e) lying[e] = 2 * ends->radius[e] * (tilt - tilting) > band;
    corners.clear();
    rimCorners(*ends, down, lying, corners);
  } else {
    solidCorners(solid, down, corners);
  }
  // The points of a lying rim after its first (its lowest) stand aside.
  const int topFirst = ends && ends->radius[0] > 0 ? kRimPoints : 1;
  const auto standsAside = [&](int c) {
    const bool top = c >= topFirst;
    return ends && lying[top ? 1 : 0] && c != (top ? topFirst : 0);
  };
  near.clear();
  near.reserve(corners.size());
  for (int c = 0; c < static_cast<int>(corners.size()); ++c) {
    if (standsAside(c)) continue;
    const btVector3 vertex = pose * corners[static_cast<std::size_t>(c)];
    const btScalar distance = normal.dot(vertex) - offset;
    if (distance > threshold) continue;
    const btScalar closing = normal.dot(velocity(moving, vertex) - velocity(support, vertex));
    near.push_back({c, distance, vertex, distance + std::min(closing, btScalar(0)) * approach.timeStep,
                    distance < normal.dot(pose.getOrigin()) - offset,
                    corners[static_cast<std::size_t>(c)].y() > 0 ? 1 : 0});
  }
}

void addCornerPoints(btManifoldResult& result, const std::vector<NearCorner>& chosen, const btVector3& normal,
                     bool supportFirst) {
  // A point kept from an earlier step at a corner not chosen now goes
  // first: with the manifold full, Bullet keeps the four points spanning
  // the largest area, and it dropped a corner just chosen for an old one.
  if (btPersistentManifold* manifold = result.getPersistentManifold()) {
    const btCollisionObject* solid = supportFirst ? result.getBody1Internal() : result.getBody0Internal();
    const bool solidIsA = manifold->getBody0() == solid;
    const btTransform& pose = solid->getWorldTransform();
    for (int i = manifold->getNumContacts() - 1; i >= 0; --i) {
      const btManifoldPoint& kept = manifold->getContactPoint(i);
      const btVector3 at = pose * (solidIsA ? kept.m_localPointA : kept.m_localPointB);
      const bool chosenAgain = std::any_of(chosen.begin(), chosen.end(), [&](const NearCorner& c) {
        return (c.point - at).length2() <= kSameCorner * kSameCorner;
      });
      if (!chosenAgain) manifold->removeContactPoint(i);
    }
  }
  auto* distinct = dynamic_cast<ContactResult*>(&result);
  if (distinct) distinct->setEachPointDistinct(true);
  for (const auto& [corner, distance, vertex, arrival, below, end] : chosen) {
    if (supportFirst) {
      result.addContactPoint(-normal, vertex, distance);
    } else {
      result.addContactPoint(normal, vertex - normal * distance, distance);
    }
  }
  if (distinct) distinct->setEachPointDistinct(false);
}

const std::vector<NearCorner>& CornerChoice::choose(const btConvexShape& solid, std::vector<NearCorner>& near) {
  const btScalar band = faceBand(solid);
  const auto level = [](const NearCorner& c) { return std::min(c.distance, c.arrival); };
  btScalar lowest = BT_LARGE_FLOAT, lowestArrival = BT_LARGE_FLOAT;
  for (const NearCorner& c : near) lowest = std::min(lowest, c.distance), lowestArrival = std::min(lowestArrival, c.arrival);
  // The lowest corner of each end (the solid's own -y and +y halves: a
  // cylinder's rims, a box's end faces) that lies below the centre: a body
  // lying on its side rests on both, however far one end tilts out of the
  // band.
  int endLowest[2] = {-1, -1};
  for (int i = 0; i < static_cast<int>(near.size()); ++i) {
    int& at = endLowest[near[i].end];
    if (near[i].below && (at < 0 || level(near[i]) < level(near[at]) - kLevel)) at = i;
  }
  for (int& at : endLowest) at = at < 0 ? -1 : near[at].corner;
  const auto endsLowest = [&](const NearCorner& c) { return c.corner == endLowest[0] || c.corner == endLowest[1]; };
  near.erase(std::remove_if(near.begin(), near.end(),
                            [&](const NearCorner& c) { return level(c) > lowest + band && !endsLowest(c); }),
             near.end());
  const std::size_t wanted = std::min<std::size_t>(MANIFOLD_CACHE_SIZE, near.size());

  std::vector<NearCorner>& chosen = chosen_;
  chosen.clear();
  chosen.reserve(wanted);
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

  // Afresh: the lowest first; then, each the farthest from those chosen,
  // the ends' lowest; then the rest.
  chosen.assign(1, *std::find_if(near.begin(), near.end(),
                                 [&](const NearCorner& c) { return c.distance <= lowest + kLevel; }));
  const auto spread = [&](const auto& allowed) {
    while (chosen.size() < wanted) {
      std::size_t best = 0;
      btScalar farthest = -1;
      for (std::size_t i = 0; i < near.size(); ++i) {
        if (!allowed(near[i])) continue;
        btScalar closest = BT_LARGE_FLOAT;
        for (const NearCorner& c : chosen) closest = std::min(closest, (near[i].point - c.point).length());
        if (closest > farthest + kLevel) farthest = closest, best = i;
      }
      if (farthest <= kLevel) return;
      chosen.push_back(near[best]);
    }
  };
  spread(endsLowest);
  spread([](const NearCorner&) { return true; });
  kept_.clear();
  for (const NearCorner& c : chosen) kept_.push_back(c.corner);
  return chosen;
}

}  // namespace tabletop
