#pragma once

#include <vector>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>

#include "physics/collision/SolidCorners.h"

namespace tabletop {

/// A box, a cylinder or a convex hull (a cone) against a box (the table's
/// top, a cube, a box) or a standing cylinder's ends: while the solid rests
/// on one of the faces (a box's six, a cylinder's two discs), that is on the
/// face's plane with every corner near it over the face, its corners there
/// are the contact points, chosen as on the floor (SolidOnPlaneAlgorithm,
/// CornerChoice), so a cylinder or a cone slides on the table as it does
/// on the floor. Otherwise (the solid reaches over the face's edge, or
/// meets the body at an edge or a corner) Bullet's algorithm for the pair
/// finds the points, and a solid's corners that are over the face are
/// added beside them.
///
/// Bullet's algorithms found a standing cylinder's face on the table by
/// GJK at three small turns, and a cone's by clipping its 32-sided base,
/// of which a manifold keeps four; the points changed from step to step,
/// and slides ended short and turned (docs/bullet-corrections.md).
class SolidOnFaceAlgorithm : public btActivatingCollisionAlgorithm {
 public:
  SolidOnFaceAlgorithm(const btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
               const btCollisionObjectWrapper* body1, btCollisionAlgorithmCreateFunc& otherwise);
  ~SolidOnFaceAlgorithm() override;

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override;

  /// Registered with a dispatcher for box, cylinder and hull against a box
  /// or a cylinder; `otherwise` makes Bullet's algorithm for the pair.
  struct CreateFunc : public btCollisionAlgorithmCreateFunc {
    explicit CreateFunc(btCollisionAlgorithmCreateFunc* pairs) : otherwise(pairs) {}
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;
    btCollisionAlgorithmCreateFunc* otherwise;
  };

 private:
  // The face's points, or false when the solid does not rest on a face;
  // `timeStep` (s) is the coming step's, over which corners close.
  bool touchFace(const btCollisionObjectWrapper* boxWrap, const btCollisionObjectWrapper* solidWrap, bool boxFirst,
                 btScalar timeStep, btManifoldResult* result);
  // The box's face the solid lies farthest out from, and whether the
  // solid's centre is out over its plane; if it is, the solid's corners
  // near it go into near_.
  struct Face {
    btVector3 normal;
    int axis = 0;
    bool out = false;
    bool round = false;    // a disc (a cylinder's or a cone's end), not a box's rectangle
    btVector3 half;        // a box's half extents, margin included
    btScalar radius = 0;   // a disc's
    btScalar thickness = 0;  // how far the body reaches behind the face, m
  };
  // The faces a shape has: a box's six, a standing cylinder's two ends,
  // and a truncated cone's two ends (the discs inscribed in its hull's
  // rings), across its own axes `first` to `last` (none if first > last).
  struct FacedShape {
    int first = 0, last = -1;
    bool round = false;
    btVector3 half{0, 0, 0};
    btScalar radius[2] = {0, 0};  // each end's disc: along +axis, then -axis
    btScalar ends[2] = {0, 0};    // a disc's distance from the centre, likewise
    // How far the face on `axis` at `end` lies from the centre, m.
    btScalar out(int axis, int end) const { return round ? ends[end] : half[axis]; }
  };
  static FacedShape facesOf(const btCollisionShape& shape);
  // facesOf, kept for the pair's two shapes, which do not change.
  const FacedShape& facesFor(const btCollisionShape& shape);
  // Which of two bodies' faces are tried first: a box's (kBoxRank), then a
  // cylinder's, then a cone's; 0 for a shape with none.
  static constexpr int kBoxRank = 3;
  static int faceRank(const btCollisionShape& shape);
  Face outerFace(const btCollisionObjectWrapper* boxWrap, const btCollisionObjectWrapper* solidWrap,
                 btScalar timeStep);
  static bool overFace(const btCollisionObjectWrapper* boxWrap, const Face& face, const NearCorner& corner);
  // A cylinder or a cone that reaches over the face's edge: Bullet's
  // algorithm for the pair finds one point a step (GJK), where the two are
  // nearest. The corners over the face within the breaking threshold are
  // chosen as on a face (CornerChoice) into this algorithm's own manifold,
  // beside Bullet's, so that the rest of a base swinging down onto the
  // face is seen before it arrives: a cone struck onto a box's edge landed
  // on one rim point, turned about it, and its far rim sank into the box
  // within the step, unseen. False if no corner is over the face.
  bool addCornersOverFace(const btCollisionObjectWrapper* boxWrap, const btCollisionObjectWrapper* solidWrap,
                          bool boxFirst, btScalar timeStep, btManifoldResult* result);
  void clearOtherwise();
  // Two boxes a hair apart where neither rests on the other's face (a cube
  // tipping over the table's edge, lifted a nanometre by the last solve):
  // Bullet's separating-axis test finds an axis between them and clips
  // nothing, and the cube fell freely for a step, then struck. Within the breaking threshold their faces are clipped along
  // GJK's normal, as Bullet clips them once they touch.
  void clipApart(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                 btManifoldResult* result);

  const btCollisionShape* facedShapes_[2] = {nullptr, nullptr};
  FacedShape faces_[2];
  btCollisionAlgorithmCreateFunc& otherwiseFunc_;
  btCollisionAlgorithm* otherwise_ = nullptr;  // made when first needed
  btPersistentManifold* manifold_ = nullptr;
  CornerChoice choice_;
  int solid_ = -1;  // which body's corners are the points (0 or 1), -1: none
  // Kept from step to step for their storage: the solid's corners, those
  // near the face, and those of them over it.
  std::vector<btVector3> corners_;
  std::vector<NearCorner> near_, over_;

  // How far past a face's edge a corner still counts as over it, m: two
  // equal boxes stacked square have their corners on each other's edges.
  static constexpr btScalar kOverEdge = 1e-6;
};

}  // namespace tabletop
