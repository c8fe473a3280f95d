#pragma once

#include <algorithm>
#include <functional>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "physics/contact/BodySet.h"

namespace tabletop {

/// Bodies rolling on a line of contact whose line turns (stages 4 and 7,
/// docs/step.md): a cone rolling on its side, its line through its apex
/// turning about the apex; a truncated cone about the point where its line
/// meets the table's plane. Such a body turns about its line, and the line
/// turns with it, about the support's normal.
///
/// A part's solve holds each contact as the part's start places it, so
/// the spin it ends with lies along that start's line. Turned about that
/// line for the whole part, the body tilted off its support by the square
/// of its turn (its far end dipped, its apex rose); and at the next part's
/// start its velocity rolled about the old line, which the solve projected
/// onto the new one, losing the spin across it. Instead:
/// - before the solve, the velocity a body rolled with about its old line
///   is carried round to the new one, as the line turned (transport());
/// - its part turns it as a rolling solid of revolution moves: its axis
///   precesses about the support's normal and it spins about its axis,
///   both through where the axis meets the support, at the rates its
///   mean spin makes up (turnAt()).
/// A body that was pushed, or whose points do not lie on one line on one
/// support, or that did not roll about its line, is left alone.
class RollingLines {
 public:
  /// After the part's solve, before its integration: each moving body's
  /// line (the part's start) and whether its solved velocity rolls about
  /// it, for the next part. Bodies of `aside` keep theirs.
  void record(btDispatcher& dispatcher, const BodySet& aside);
  /// After the next part's narrow phase: carries each recorded rolling
  /// velocity round to the body's new line (not for `kicked` bodies).
  /// Returns the bodies whose velocities it set.
  const std::vector<btRigidBody*>& transport(btDispatcher& dispatcher, const BodySet& kicked);
  /// The bodies rolling on a line in this part (transport()'s, and those
  /// rolling on one now with none recorded), whose gyroscopic term the
  /// part leaves out.
  const std::vector<btRigidBody*>& rolling() const { return rolling_; }
  /// Turns `pose` (the body's at the part's start, `start`) as the part's
  /// mean velocity (`linear`, `spin`) rolls it over `dt` s: its axis's
  /// precession after its own spin, both through where its axis meets the
  /// support; false (pose untouched) for a body whose line does not turn
  /// (none recorded this part, or a level axis).
  bool turnAt(const btRigidBody& body, const btTransform& start, const btVector3& linear, const btVector3& spin,
              double dt, btTransform& pose) const;

  /// What carries from part to part, saved at a step's start and put back
  /// for `only` (or everyone) when groups are taken again (GroupSteps.cpp).
  void save() { saved_ = recorded_; }
  void putBack(const BodySet& only);
  void putBackAll() { recorded_ = saved_; }

  /// Whether a body turns about a line that turns, in this part.
  bool turning() const { return !turns_.empty(); }
  struct Line {
    const btCollisionObject* body = nullptr;
    const btCollisionObject* support = nullptr;
    btVector3 a, b;      // its ends, world
    btVector3 normal;    // the support's, towards the body, unit
    btVector3 centre;    // the body's centre of mass then
  };
  /// The lines of contact of the moving bodies, by body: a body whose
  /// touching points (within kLoadTouching) all lie on one other body and
  /// on one line, two or more of them at least 1 mm apart.
  const std::vector<Line>& findLines(btDispatcher& dispatcher);

 private:
  struct Turn {
    const btCollisionObject* body;
    btVector3 centre;  // where the axis meets the support
    btVector3 normal;
    btVector3 axis;    // the solid's, world
  };
  struct Touch {
    const btCollisionObject* body;
    const btCollisionObject* other;
    btVector3 point, normal;
  };
  static bool lineOf(const Touch* from, const Touch* to, Line& line);
  // Whether the body's velocity rolls about the line (its ends still,
  // its spin along it, to kRolls).
  static bool rollsAbout(const btRigidBody& body, const Line& line);
  std::vector<Touch> touches_;    // scratch
  std::vector<Line> lines_;       // scratch, by body
  std::vector<Line> recorded_;  // the lines bodies rolled about, by body
  std::vector<Line> saved_;
  std::vector<Turn> turns_;       // this part's, by body
  std::vector<btRigidBody*> moved_;
  std::vector<btRigidBody*> rolling_;
};

}  // namespace tabletop
