#pragma once

#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "physics/contact/BodySet.h"
#include "physics/contact/ContactKinematics.h"

namespace tabletop {

/// Impacts inside a step. A step's contacts are found at its start, up to
/// Bullet's breaking threshold (2 cm) ahead of touching. A point still
/// apart that closes within the step is an impact at its own time: the
/// step is cut there, and at the start of the next part the point touches
/// and bounces (DynamicsWorld). Only points that touch get restitution:
/// Bullet would give it to a point still 2 cm apart, less the gap over the
/// step, so a dropped ball bounced short from above the floor, or stopped
/// dead when the gap ate the whole rebound.

/// The contacts of one part of a step, as found at its start: which bodies
/// something touches (their supports hold them, so they are taken not to
/// accelerate), when the next impact comes, and the speculative rows made
/// to agree with the trapezoid rule.
class ImpactScan {
 public:
  /// Storage a scan fills, kept by its caller from part to part so that
  /// a scan allocates nothing once it has grown.
  struct Storage {
    BodySet held;                 // bodies a touching point (not a bounced one) holds
    btManifoldArray manifolds;    // a pair's manifolds (earliestSeparatedImpact)
    const BodySet* setAside = nullptr;  // bodies done with the step (StepGroups), if any
  };
  ImpactScan(btDispatcher& dispatcher, Storage& storage);

  /// The rate, m/s^2, at which the bodies at `point` approach from their
  /// forces (gravity), a body something touches taken as not accelerating.
  double closingAcceleration(const btPersistentManifold& manifold, const btManifoldPoint& point) const;

  /// The earliest time within `horizon` at which a point that does not
  /// touch yet closes at more than `impactSpeed`; `horizon` if none.
  /// With `eventful`, the bodies of every such point within `horizon` are
  /// added to it.
  double earliestImpact(double horizon, double impactSpeed, BodySet* eventful = nullptr) const;

  /// The same for two bodies of a pair in `pairs` that have no contact
  /// point yet, from their closest points (Bullet's GJK). Box pairs need
  /// it: Bullet's separating-axis test, which gives them whole faces,
  /// reports nothing while they are apart. The time is to half kTouching
  /// past touch, where that test reports the faces.
  /// A pair with a body set aside for the step (Storage::setAside) is not
  /// looked at.
  double earliestSeparatedImpact(btOverlappingPairCache& pairs, double horizon, double impactSpeed,
                                 BodySet* eventful = nullptr) const;

  /// Readies the points still apart of a body nothing touches (and the
  /// points just bounced) for a solve of a part `length` s long whose
  /// positions follow the trapezoid rule. Bullet's speculative row holds
  /// the closing velocity at the part's end to gap / length, right for
  /// positions that move with it (Euler); with the trapezoid rule they
  /// move with the mean of the start and end velocities, and the row
  /// slowed a body accelerating into an impact at the part's end and
  /// stopped a ball in mid-air near the top of a low bounce. Each point's
  /// gap is set to 2 gap - v0 length (v0 its closing speed at the start),
  /// which holds the mean instead, unless that is less than the gap itself
  /// (the bodies would meet inside the part even at v0: Bullet's row then
  /// stops them). Two bodies that something touches are left as Bullet
  /// has them: a support makes their motion other than their forces say,
  /// and holding the mean let pushed bodies chatter and a standing
  /// cylinder creep. Nor are those of the bodies in `stopping`, which a
  /// point of theirs may stop at once: such a body moves by its end
  /// velocity over the part (DynamicsWorld), which Bullet's rows hold.
  /// `saved` gets the points and their gaps, to be put back after the
  /// solve, and `bodies` the bodies at them, whose turn is then to follow
  /// the mean rate as well (DynamicsWorld).
  void holdMeanVelocity(double length, const BodySet& stopping,
                        std::vector<std::pair<btManifoldPoint*, btScalar>>& saved, BodySet& bodies) const;

 private:
  bool held(const btCollisionObject* object) const;
  double accelerationTowards(const btCollisionObject& a, const btCollisionObject& b, const btVector3& normalOnB) const;
  // A body's acceleration from its forces, m/s^2 (none if something
  // touches it).
  btVector3 accelerationOf(const btCollisionObject& object) const;

  btDispatcher& dispatcher_;
  Storage& storage_;
};

}  // namespace tabletop
