#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <btBulletCollisionCommon.h>

namespace tabletop {

/// Points this near in depth (m) are one face's: a face resting flat on
/// another is clipped to corners whose depths differ by rounding.
constexpr double kFlatDepths = 1e-5;

/// Twice the area spanned by four points of one contact plane: the largest
/// of the three ways to pair them as diagonals (for a convex quadrilateral,
/// its diagonals' cross product).
double spannedArea(const btVector3& a, const btVector3& b, const btVector3& c, const btVector3& d);

/// The points a narrow phase offered each manifold in one pass (one pair's
/// processCollision), and the places each manifold held before the pass.
///
/// A manifold keeps four points and takes them one at a time, so which
/// four of a flat face's clipped polygon it ends with depended on the
/// order they came in and, where two lie within the merge radius, on which
/// was deeper by rounding: two aligned 0.1 m cubes, the upper 2 cm aside,
/// swapped a corner for a point that rounding put on a shared edge after
/// 2.9 s at rest, and the upper cube tipped (1 mm at 30 Hz); a cube turned
/// on another, whose faces meet in an octagon, kept a different four every
/// step, some not around its centre, and was kicked into rocking in a pile.
/// widestFour() chooses among all the points of the pass at once.
class OfferedPoints {
 public:
  /// Forgets the last pass (keeping the storage).
  void clear();
  /// Notes `point`, offered for `manifold`; the first offer for a manifold
  /// in the pass notes the places (on body A) it holds.
  void offer(const btPersistentManifold& manifold, const btManifoldPoint& point);

  /// One manifold's offers in the pass.
  struct Offers {
    const btPersistentManifold* manifold = nullptr;
    std::vector<btManifoldPoint> points;  // in the order offered
    std::array<btVector3, 4> before;      // its places before the pass, on body A
    int beforeCount = 0;
  };
  const std::vector<Offers>& offers() const { return offers_; }

 private:
  std::vector<Offers> offers_;  // the first `used_` are this pass's
  std::size_t used_ = 0;
};

/// Of `offers`' points, when there are more than four (and at most
/// kMostOffered) and their depths lie within kFlatDepths, the four that
/// span the widest area on body A, by index; false otherwise. A four whose
/// area is within a relative kAreaTie of the widest and that holds more of
/// the places the manifold held before is preferred: the octagon where two
/// equal cubes meet turned 45 degrees holds two squares of one area, and a
/// manifold that took the other each step would rock the cube between them.
bool widestFour(const OfferedPoints::Offers& offers, std::array<int, 4>& chosen);
constexpr int kMostOffered = 12;  // C(12, 4) = 495 fours at most
constexpr double kAreaTie = 1e-9;

}  // namespace tabletop
