#include "physics/step/KeptOut.h"

#include <algorithm>

#include "physics/contact/ContactKinematics.h"

namespace tabletop {

void KeptOut::collect(btDispatcher& dispatcher, const btAlignedObjectArray<btRigidBody*>& bodies, double dt) {
  held_.clear();
  std::size_t size = 0;
  for (int i = 0; i < bodies.size(); ++i) size = std::max(size, static_cast<std::size_t>(bodies[i]->getWorldArrayIndex() + 1));
  moving_.assign(size, -1);
  for (int i = 0; i < bodies.size(); ++i) {
    const int at = bodies[i]->getWorldArrayIndex();
    if (at >= 0) moving_[static_cast<std::size_t>(at)] = i;
  }
  const auto movingIndex = [&](const btCollisionObject* o) {
    const int at = o->getWorldArrayIndex();
    return at >= 0 && static_cast<std::size_t>(at) < moving_.size() ? moving_[static_cast<std::size_t>(at)] : -1;
  };
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() <= 0) continue;
      for (const bool first : {true, false}) {
        const btCollisionObject* body = first ? manifold->getBody0() : manifold->getBody1();
        const btCollisionObject* support = first ? manifold->getBody1() : manifold->getBody0();
        if (!support->isStaticObject()) continue;
        const int index = movingIndex(body);
        if (index < 0) continue;
        const btVector3 normal = first ? point.m_normalWorldOnB : -point.m_normalWorldOnB;
        const btVector3 at = first ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
        // Let in by the solve (closing faster than its gap allows): not held.
        if (normal.dot(velocityAt(body, at)) * dt < -point.getDistance() - 1e-9) continue;
        const btTransform& pose = body->getWorldTransform();
        held_.push_back({index, pose.invXform(at), normal, point.getDistance()});
      }
    }
  }
  std::stable_sort(held_.begin(), held_.end(), [](const Held& a, const Held& b) { return a.body < b.body; });
}

void KeptOut::keepOut(int index, const btTransform& start, btTransform& pose) const {
  auto it = std::lower_bound(held_.begin(), held_.end(), index, [](const Held& h, int key) { return h.body < key; });
  double lack = 0;
  btVector3 normal(0, 0, 0);
  for (; it != held_.end() && it->body == index; ++it) {
    const double gap = it->gap + it->normal.dot(pose * it->local - start * it->local);
    const double under = -gap;
    if (under > lack) lack = under, normal = it->normal;
  }
  if (lack >= kSlack) pose.setOrigin(pose.getOrigin() + normal * lack);
}

}  // namespace tabletop
