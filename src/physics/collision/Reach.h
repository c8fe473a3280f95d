#pragma once

#include <btBulletDynamicsCommon.h>

namespace tabletop {

/// Whether anything but `body` comes within `reach` m of its bounding box:
/// another object's bounding box (the broadphase's, margins and padding
/// included), or, for a plane such as the floor, the plane itself (its
/// bounding box is unbounded, so every body would be near it). With a
/// `slideStep` (s; 0: none), an object the body slides on over a step that
/// long (slidesOn) does not count. World::substeps asks it with how far a
/// body can move in a step: a body nothing is that near strikes nothing in
/// the step.
bool nearAnything(btCollisionWorld& world, const btRigidBody& body, double reach, double slideStep);

/// Whether `body` rests on `support` and moves along it in a step of
/// `timestep` s, in which it moves at most `reach` m: a contact point of
/// theirs within kOnSurface of touching, its normal within 45 degrees of
/// the body's up (against its gravity), at which the body does not close
/// on the support faster than its gravity gives in the step; and the
/// body's box, grown by `reach`, stays within the support's across up, so
/// that no edge of the support comes under it (a plane has none). The
/// pair's points are found through the broadphase's `pairs` cache.
bool slidesOn(btOverlappingPairCache& pairs, const btRigidBody& body, const btCollisionObject& support,
              double timestep, double reach);

}  // namespace tabletop
