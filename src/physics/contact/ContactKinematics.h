#pragma once

#include <btBulletDynamicsCommon.h>

namespace tabletop {

/// How the two bodies of a contact point move relative to each other, and
/// the distances and speeds at which tabletop calls a point touching, loaded
/// or striking. Shared by the event search (step/ImpactSearch.h), the
/// solver's choice (solver/IslandSolver.h) and the integration.

/// How close, in metres, two bodies are when they count as touching.
inline constexpr double kTouching = 1e-6;

/// How close, in metres, two bodies are when their contact can carry a
/// load: a resting point sits within the solver's slop of touching.
inline constexpr double kLoadTouching = 1e-4;

/// A touching point carries a load (gravity presses its bodies together)
/// when its normal is within 45 degrees of the vertical: its vertical
/// component is at least this (cos 45).
inline constexpr double kLoadNormal = 0.7071;

/// Points that close within this time, s, of each other strike together:
/// a face landing on a face, found a few micrometres apart at one corner
/// and touching at another (GJK's distance is good to about 1e-3 of
/// itself), bounces on all four.
inline constexpr double kSameInstant = 1e-5;

/// The closing speed, m/s, below which an impact is inelastic, whatever
/// the restitution: a drop of 2 mm. Slower closings are a resting
/// contact's jitter (a light body under a heavy one, solved in a few
/// sweeps, closes at a centimetre a second), and giving them restitution
/// made stacks chatter. Bullet's own threshold is the same; Box2D's is
/// 1 m/s.
inline constexpr double kBounceSpeed = 0.2;

/// The velocity, m/s, of the point of `object` at `point` (world): zero for
/// anything but a rigid body.
btVector3 velocityAt(const btCollisionObject* object, const btVector3& point);

/// The speed, m/s, at which the bodies at `point` of `manifold` approach
/// each other along its normal (negative when they part).
double closingSpeed(const btPersistentManifold& manifold, const btManifoldPoint& point);

/// The velocity, m/s, at which body A slides over body B at `point` (their
/// relative velocity across the normal), and its speed.
btVector3 slipVelocity(const btPersistentManifold& manifold, const btManifoldPoint& point);
double slipSpeed(const btPersistentManifold& manifold, const btManifoldPoint& point);

/// Whether `point` strikes at the start of a part of a step `stepLength`
/// s long: it closes faster than kBounceSpeed and is touching, or near
/// enough that it would touch within kSameInstant (or 1% of the step).
/// Such a point is taken as touching: Bullet's row would let it close by
/// its gap over the part, taking gap / part off the impact, most at high
/// rates (docs/bullet-corrections.md).
bool strikesNow(const btPersistentManifold& manifold, const btManifoldPoint& point, double stepLength);

/// The first time, s, at which a gap of `gap` m closes from the closing
/// speed `speed` and acceleration `accel` (constant), or infinity.
double timeToClose(double gap, double speed, double accel);

/// The combined restitution of the two bodies' Materials (0 without).
double restitutionOf(const btPersistentManifold& manifold);

}  // namespace tabletop
