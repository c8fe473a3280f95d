#pragma once

#include <btBulletCollisionCommon.h>

namespace tabletop {

/// Whether anything but `body` comes within `reach` m of its bounding box:
/// another object's bounding box (the broadphase's, margins and padding
/// included), or, for a plane such as the floor, the plane itself (its
/// bounding box is unbounded, so every body would be near it).
/// World::substeps asks it with how far a body can move in a step: a body
/// nothing is that near strikes nothing in the step.
bool nearAnything(btCollisionWorld& world, const btCollisionObject& body, double reach);

}  // namespace tabletop
