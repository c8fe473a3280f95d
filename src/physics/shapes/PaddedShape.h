#pragma once

#include <utility>

#include <btBulletCollisionCommon.h>

namespace tabletop {

/// A Bullet convex shape `Base` whose bounding box reaches `pad` metres
/// beyond it on every side; its collisions are Base's.
///
/// For the children of the table's compound. Bullet's compound algorithm
/// deletes a child's collision algorithm, and with it the child's contact
/// manifold and the impulses it carries, in any step where the child's
/// bounding box and the other body's do not overlap, and it tests the exact
/// boxes. A cube resting on the top touches it along a face: their boxes
/// share a plane, and a rounding-sized lift parted them. The cube's four
/// points went, it fell freely for one step, sank into the top and was
/// pushed back out: a body at rest moved. The broadphase pads every box by the contact breaking
/// threshold; a child padded by as much is kept while the pair is.
template <class Base>
class PaddedShape : public Base {
 public:
  template <class... Args>
  explicit PaddedShape(double pad, Args&&... args) : Base(std::forward<Args>(args)...), pad_(pad) {}

  void getAabb(const btTransform& pose, btVector3& low, btVector3& high) const override {
    Base::getAabb(pose, low, high);
    const btVector3 pad(pad_, pad_, pad_);
    low -= pad;
    high += pad;
  }

  double pad() const { return pad_; }

 private:
  double pad_;
};

// The table's two kinds of child, built once in PaddedShape.cpp.
extern template class PaddedShape<btBoxShape>;
extern template class PaddedShape<btCylinderShape>;

}  // namespace tabletop
