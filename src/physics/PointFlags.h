#pragma once

namespace tabletop {

/// The bits of btManifoldPoint::m_contactPointFlags that tabletop sets,
/// above Bullet's own (1 to 16), in one place so that no two collide.

/// The point is an impact in this step (DynamicsWorld::markImpacts).
inline constexpr int kImpactFlag = 1 << 20;

/// The point's friction has its first row only, along the line its
/// contact's slip turned round on (DynamicsWorld::holdFrictionAlongLine;
/// IslandSolver drops the second).
inline constexpr int kFirstFrictionRowOnly = 1 << 21;

}  // namespace tabletop
