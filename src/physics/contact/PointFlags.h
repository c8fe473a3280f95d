#pragma once

#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>

namespace tabletop {

/// The bits of btManifoldPoint::m_contactPointFlags that tabletop sets,
/// above Bullet's own (1 to 16), in one place so that no two collide.

/// The point is an impact in this step (DynamicsWorld::markImpacts).
inline constexpr int kImpactFlag = 1 << 20;

/// The point's friction has its first row only, along the line its
/// contact's slip turned round on (DynamicsWorld::holdFrictionAlongLine;
/// IslandSolver drops the second).
inline constexpr int kFirstFrictionRowOnly = 1 << 21;

/// The point bounced in the impact solve at the start of the part being
/// solved (DynamicsWorld::resolveTouchingImpacts); cleared as it ends.
inline constexpr int kBouncedFlag = 1 << 22;

inline bool bounced(const btManifoldPoint& point) { return (point.m_contactPointFlags & kBouncedFlag) != 0; }

}  // namespace tabletop
