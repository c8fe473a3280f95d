#include "compat/GjkContactFinder.h"

#include <cmath>

#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "core/Angle.h"
#include "physics/World.h"

namespace tabletop {
namespace {

constexpr int kMaxIterations = 64;

btTransform pose(const rules::RuleBody& b, const Vec3& offset) {
  return btTransform(btQuaternion(btVector3(0, 1, 0), convertAngle(b.yawDegrees)),
                     btVector3(b.position.x + offset.x, b.position.y + offset.y, b.position.z + offset.z));
}

}  // namespace

std::optional<rules::Hit> GjkContactFinder::firstHit(std::size_t moverIndex, const rules::RuleBody& mover,
                                                     std::size_t otherIndex, const rules::RuleBody& other,
                                                     const Vec3& d) const {
  const auto& entities = world_.entities();
  const auto* a = static_cast<const btConvexShape*>(&entities.at(moverIndex)->collisionShape());
  const auto* b = static_cast<const btConvexShape*>(&entities.at(otherIndex)->collisionShape());
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector gjk(a, b, &simplex, &epa);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_transformB = pose(other, {});

  double t = 0.0;
  for (int k = 0; k < kMaxIterations; ++k) {
    input.m_transformA = pose(mover, d * t);
    btPointCollector out;
    simplex.reset();
    gjk.getClosestPoints(input, out, nullptr);
    if (!out.m_hasResult) return std::nullopt;
    // Bullet's normal points from B to A; we want mover to other.
    const Vec3 n{-out.m_normalOnBInWorld.x(), -out.m_normalOnBInWorld.y(), -out.m_normalOnBInWorld.z()};
    const double closing = d.dot(n);
    if (closing <= 0.0) return std::nullopt;  // convexity: they never meet
    if (out.m_distance <= kContactTolerance) {
      const double flat = std::hypot(n.x, n.z);
      const Vec3 normal = flat > 0.0 ? Vec3{n.x / flat, 0.0, n.z / flat} : Vec3{};
      return rules::Hit{t, normal};
    }
    t += out.m_distance / closing;
    if (t > 1.0) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace tabletop
