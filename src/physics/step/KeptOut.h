#pragma once

#include <vector>

#include <btBulletDynamicsCommon.h>

namespace tabletop {

/// Points on a fixed support (the table, the floor) that integration may
/// not carry into it (stage 7, docs/step.md). A body moves by the mean of
/// its velocities at the part's start and end. A point of it apart from
/// the support at the start, closing on it slower than a stop counts (a
/// body's edge rocking down after a landing), which the solve's row then
/// held at the support, still moves by the mean of its closing speeds:
/// past the support, by up to half the part times its start speed. Such
/// a point is kept at the support: the body is moved back out along the
/// normal by the deepest one's lack. A lack under kSlack is left alone
/// (rounding, the sweeps' jitter; the next part's rows take it back).
class KeptOut {
 public:
  static constexpr double kSlack = 1e-5;  // m

  /// Before integration, the bodies at the part's start and their
  /// velocities the part's end: the points of `bodies` (the world's moving
  /// bodies) apart from fixed bodies that the solve left closing no faster
  /// than their gap allows over `dt` s.
  void collect(btDispatcher& dispatcher, const btAlignedObjectArray<btRigidBody*>& bodies, double dt);
  /// Moves `pose`, body `index`'s at the part's end (`start` at its
  /// start), back out of its supports.
  void keepOut(int index, const btTransform& start, btTransform& pose) const;

 private:
  struct Held {
    int body;         // index among the moving bodies
    btVector3 local;  // on the body, its frame
    btVector3 normal;  // out of the support, unit
    double gap;        // m, at the start (above 0)
  };
  std::vector<Held> held_;  // by body
  std::vector<int> moving_;  // each world index's moving index, or -1
};

}  // namespace tabletop
