#pragma once

#include <utility>
#include <vector>

#include <btBulletCollisionCommon.h>

#include "physics/collision/FlatFour.h"

namespace tabletop {

/// Where the narrow phase puts the contact points it finds: Bullet's
/// btManifoldResult, but a new point replaces a kept one only within the
/// merge radius, half the smallest extent of either shape (mergeRadius()),
/// not within the manifold's breaking threshold; of two points found in one
/// pass within it, the deeper stays, not the later.
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
  /// The points added since the result was made or distinctness last
  /// changed, by manifold and index: kept by the caller, who makes a result
  /// for every pair in every step, so that the storage is reused.
  using FoundPoints = std::vector<std::pair<const btPersistentManifold*, int>>;

  /// Cleared here, as `offered`: each result starts with none found.
  ContactResult(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1, FoundPoints& found,
                OfferedPoints& offered);

  void addContactPoint(const btVector3& normalOnBInWorld, const btVector3& pointInWorld, btScalar depth) override;

  /// Within this distance (m) of a kept point, as a feature of either body, a new
  /// point replaces it: half the smallest extent of either shape, and never
  /// more than `breakingThreshold`.
  static double mergeRadius(const btCollisionShape& a, const btCollisionShape& b, double breakingThreshold);

  /// After the pair's pass: a manifold offered more than four points of one
  /// flat face, all four it holds found in the pass, keeps the widest four
  /// of them all (FlatFour.h), not those the order of offering left it.
  void keepWidestFlatFour();

  /// While on, each point added is a point of its own: it replaces a kept
  /// point within the merge radius only if no other point added since did
  /// (SolidCorners' chosen corners, each one the solid rests on). The narrow
  /// end of a cone lying on its side is a ring narrower than the merge
  /// radius, and its corners replaced each other, the last one added, not
  /// the deepest, staying: the end sank into the table unseen, and rose
  /// when a later choice found it, gaining energy.
  /// Bullet's own algorithms add points that are meant to merge.
  void setEachPointDistinct(bool on) {
    distinct_ = on;
    found_.clear();
  }

 private:
  // mergeRadius() for the pair of shapes the points are added for, kept
  // while the shapes and the threshold stay the same: each point asked
  // both shapes for their boxes (a twentieth of a sliding cube's step).
  double radiusFor(const btCollisionShape& a, const btCollisionShape& b, double breakingThreshold);
  const btCollisionShape* radiusShapes_[2] = {nullptr, nullptr};
  double radiusThreshold_ = 0.0;
  double radius_ = 0.0;

  bool distinct_ = false;
  FoundPoints& found_;
  OfferedPoints& offered_;
};

/// Carries warm-start impulses over Bullet's compound algorithm, which
/// refreshes its children's manifolds before it finds their points and so
/// drops every point whose sides slid more than the breaking threshold
/// since the last step: a body sliding fast over the table started every
/// step cold, and turned and stopped short (docs/bullet-corrections.md). save() before
/// the narrow phase; restore() after it gives a point made anew the
/// impulses of the dropped point it stands for: the nearest within the
/// merge radius as a feature of either body (ContactResult), each at most
/// once.
class CarriedImpulses {
 public:
  void save(btDispatcher& dispatcher);
  void restore(btDispatcher& dispatcher);
  /// save() as it is made, restore() as it ends: around the narrow phase.
  class Guard {
   public:
    Guard(CarriedImpulses& carried, btDispatcher& dispatcher) : carried_(carried), dispatcher_(dispatcher) {
      carried_.save(dispatcher_);
    }
    ~Guard() { carried_.restore(dispatcher_); }
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;

   private:
    CarriedImpulses& carried_;
    btDispatcher& dispatcher_;
  };

 private:
  struct Saved {
    const btCollisionObject* body0;
    const btCollisionObject* body1;
    btVector3 localA, localB;  // in each body's frame
    btScalar impulse, lateral1, lateral2;
    int lifeTime;
  };
  // A manifold's saved points: saved_[first, first + count).
  struct Range {
    const btPersistentManifold* manifold;
    std::size_t first, count;
  };
  std::vector<Saved> saved_;   // a manifold's points together, in its order
  std::vector<Range> ranges_;  // by manifold: restore() finds one by a search
  std::vector<Saved*> gone_;   // restore's, kept to reuse its storage
};

/// Removes the points of `manifold` that no longer mark where its bodies
/// touch: those whose two sides have slid apart along the contact plane,
/// for pairs whose touching points are all found again every step.
void dropDriftedPoints(btPersistentManifold& manifold);

}  // namespace tabletop
