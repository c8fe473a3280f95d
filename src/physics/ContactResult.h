#pragma once

#include <btBulletCollisionCommon.h>

namespace tabletop {

/// Where the narrow phase puts the contact points it finds: Bullet's
/// btManifoldResult, but a new point replaces a kept one only within the
/// merge radius, half the smallest extent of either shape (mergeRadius()),
/// not within the manifold's breaking threshold.
///
/// Bullet uses one distance for three things: how far ahead of touching a
/// point is made (a speculative contact), how far its two sides may part or
/// slide before it is dropped, and how near a new point must be to a kept
/// one to replace it. The first two want Bullet's 2 cm: a body falling or
/// sliding fast is caught before it sinks, and a sliding face keeps its
/// points, and their impulses, from step to step. The third must shrink
/// with the body: within 2 cm of each other, every corner of a small cube
/// replaced every other, and it rocked on one point and sank
/// (docs/bullet-corrections.md). Half the smallest extent keeps the
/// corners of any face apart.
///
/// The world sets no contact-added or contact-started callbacks, so this
/// does not call them.
class ContactResult : public btManifoldResult {
 public:
  ContactResult(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1);

  void addContactPoint(const btVector3& normalOnBInWorld, const btVector3& pointInWorld, btScalar depth) override;

  /// Within this distance (m) of a kept point, measured on body A, a new
  /// point replaces it: half the smallest extent of either shape, and never
  /// more than `breakingThreshold`.
  static double mergeRadius(const btCollisionShape& a, const btCollisionShape& b, double breakingThreshold);
};

}  // namespace tabletop
