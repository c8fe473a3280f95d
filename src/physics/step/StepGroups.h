#pragma once

#include <vector>

#include <btBulletDynamicsCommon.h>

#include "physics/contact/BodySet.h"

namespace tabletop {

/// The moving bodies of a step in groups that cannot touch one another
/// within it: two bodies whose boxes overlap (each body's box as the world
/// gives it to the broadphase: grown by the contact threshold and the
/// motion Bullet predicts for the step) are in one group, and so is
/// everything joined to them that way. A fixed body (the table, the
/// ground) joins nothing. An event inside the step (an impact, a body
/// leaving a face, a slip that may turn) concerns its group alone, so
/// only that group need be cut at it (DynamicsWorld::step).
class StepGroups {
 public:
  /// Groups `bodies` (the world's moving bodies) by the pairs of `pairs`.
  void find(const btAlignedObjectArray<btRigidBody*>& bodies, btOverlappingPairCache& pairs);
  /// The moving bodies of every group that holds a body of `seeds`, into
  /// `out` (cleared first): at most all of `bodies` as given to find().
  void spread(const btAlignedObjectArray<btRigidBody*>& bodies, const BodySet& seeds, BodySet& out);

 /// Whether a pair of the broadphase joins its two bodies in one group
  /// (also whether a body taken again comes to touch one set aside).
  static bool joins(const btBroadphaseProxy& a, const btBroadphaseProxy& b);

 private:
  int root(int i);
  std::vector<int> parent_;        // by world array index; -1: not a moving body
  std::vector<unsigned char> hit_;  // roots of the groups spread to
};

}  // namespace tabletop
