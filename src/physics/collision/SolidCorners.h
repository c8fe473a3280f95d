#pragma once

#include <array>
#include <vector>

#include <btBulletCollisionCommon.h>

namespace tabletop {

struct RoundEnds;

/// A solid's corners in its own frame, the candidate contact points
/// against a flat support (the floor, a box's face): a polyhedron's
/// vertices (a hull's drawn out by its margin along `down`, the way to the
/// support, where its surface is), or a round solid's rims (rimCorners).
std::vector<btVector3> solidCorners(const btConvexShape& solid, const btVector3& down);
/// The same into `out` (cleared first), whose storage the caller keeps.
void solidCorners(const btConvexShape& solid, const btVector3& down, std::vector<btVector3>& out);

/// Points to a rim of a round solid.
constexpr int kRimPoints = 32;

/// A round solid's corners, appended to `out`: each end in turn, a rim as
/// kRimPoints points on the true circle, a cone's point as one. A rim
/// marked in `lowestFirst` starts at its lowest point along `down` (the
/// solid's frame), so a body rolling on it touches exactly under its axis;
/// the others keep their points at fixed angles on the body, as a resting
/// face needs. solidCorners() marks both.
void rimCorners(const RoundEnds& ends, const btVector3& down, const std::array<bool, 2>& lowestFirst,
                std::vector<btVector3>& out);

/// A corner near the support: its index in solidCorners(), its distance
/// to the support's plane (m, negative inside), where it is (world), and
/// its distance at the end of the coming step if it goes on closing as
/// fast as now (m, at most `distance`).
struct NearCorner {
  int corner;
  btScalar distance;
  btVector3 point;
  btScalar arrival;
  bool below;  // nearer the plane than the solid's centre
  int end;     // 0 in the solid's -y half, 1 in its +y half
};

/// How the solid and its support move over the coming step (either may be
/// null: not moving).
struct Approach {
  const btCollisionObject* solid = nullptr;
  const btCollisionObject* support = nullptr;
  btScalar timeStep = 0;  ///< s
};

/// The corners of `solid` (at `pose`) within `threshold` of the plane
/// normal . x = offset, on its side of it (`normal` points out of the
/// support), each with where `approach` takes it.
/// Into `near` (cleared first), with `corners` for the solid's corners:
/// storage the caller keeps, as this runs for every pair every step.
void nearCorners(const btConvexShape& solid, const btTransform& pose, const btVector3& normal, btScalar offset,
                 btScalar threshold, const Approach& approach, std::vector<btVector3>& corners,
                 std::vector<NearCorner>& near);

/// Adds `chosen` to `result` as points of the solid on the support's plane;
/// `supportFirst` when the support is the result's first body (the normal
/// points from the second body to the first). Kept points at corners not
/// chosen are removed first: with the manifold full, Bullet keeps the four
/// points spanning the largest area and could drop a corner just chosen.
void addCornerPoints(btManifoldResult& result, const std::vector<NearCorner>& chosen, const btVector3& normal,
                     bool supportFirst);

/// Which corners are a solid's contact points on one flat support, kept
/// from step to step by the pair's algorithm.
///
/// The face nearest the plane is the corners within a twentieth of the
/// solid's smallest size of the lowest (a small cube's top corners are
/// near the plane too), and those that will be by the step's end at the
/// speed they close at; of them at most four are kept, spread out (a
/// rim's 32 points give four at right angles, not four neighbours), the
/// lowest first. While the face lies flat the same corners stay chosen,
/// as a box's four are, and the solver starts warm: a new choice is made
/// only when the kept ones are no longer all on the face, fewer than a
/// fresh choice would take, or another corner lies, or will lie by the
/// step's end, more than kReach below them. Without the corners on their
/// way, a tall cone falling onto its side held only the end that landed
/// first, and the other end, swinging down, sank into the table before it
/// was found. The lowest corner of each end
/// (the solid's -y and +y halves) that lies nearer the plane than the
/// centre is kept even outside the band and chosen right after the
/// lowest: a cylinder toppling onto its side rests on both rims, and with
/// one rim's points alone the other end landed millimetres deep.
/// Chosen afresh each step by depth, the tie between level corners was
/// broken by rounding: a standing cylinder took a new set of rim
/// points most steps, and yawed and stopped short while sliding on the
/// floor (docs/bullet-corrections.md).
class CornerChoice {
 public:
  /// How far (m) another corner may lie below the kept ones before they
  /// are chosen again: well under the 0.1 mm a slide is held to.
  static constexpr btScalar kReach = 1e-5;

  /// The contact points among `near` (in corner order, not empty), in
  /// storage this choice keeps (valid until the next call); `near` is
  /// pared down to the candidates on the way.
  const std::vector<NearCorner>& choose(const btConvexShape& solid, std::vector<NearCorner>& near);
  void forget() { kept_.clear(); }

 private:
  std::vector<int> kept_;  // corner indices
  std::vector<NearCorner> chosen_;
};

}  // namespace tabletop
