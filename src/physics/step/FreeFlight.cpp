#include "physics/step/FreeFlight.h"

namespace tabletop {

void FreeFlight::find(const btAlignedObjectArray<btRigidBody*>& bodies, btDispatcher& dispatcher) {
  free_.clear();
  touching_.clear();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    if (manifold->getNumContacts() == 0) continue;
    touching_.insert(manifold->getBody0());
    touching_.insert(manifold->getBody1());
  }
  for (int i = 0; i < bodies.size(); ++i) {
    btRigidBody* body = bodies[i];
    if (!body->isActive() || body->isStaticOrKinematicObject() || touching_.contains(body)) continue;
    if (!body->getTotalTorque().isZero()) continue;  // a torque acts: not free
    const btVector3 inverse = body->getInvInertiaDiagLocal();
    if (!(inverse.x() > 0 && inverse.y() > 0 && inverse.z() > 0)) continue;
    free_.push_back({body, i, body->getFlags()});
    body->setFlags(body->getFlags() & ~kGyroscopicFlags);
  }
}

void FreeFlight::start(const std::vector<btVector3>& startSpins, double dt) {
  for (Free& f : free_) {
    btRigidBody* body = f.body;
    body->setFlags(f.flags);
    if (static_cast<std::size_t>(f.index) >= startSpins.size()) continue;
    const btVector3 inverse = body->getInvInertiaDiagLocal();
    const btQuaternion turn = body->getWorldTransform().getRotation();
    const btVector3 spin = quatRotate(turn.inverse(), startSpins[static_cast<std::size_t>(f.index)]);
    Quat q{turn.w(), turn.x(), turn.y(), turn.z()};
    Vec3 w{spin.x(), spin.y(), spin.z()};
    const FreeRotation rotation{{1.0 / inverse.x(), 1.0 / inverse.y(), 1.0 / inverse.z()}};
    rotation.advance(q, w, dt);
    f.orientation = btQuaternion(q.x, q.y, q.z, q.w);
    f.turned = true;
    body->setAngularVelocity(quatRotate(f.orientation, btVector3(w.x, w.y, w.z)));
  }
}

void FreeFlight::finish() {
  for (const Free& f : free_) {
    if (!f.turned || f.body->getHitFraction() < 1) continue;
    btTransform pose = f.body->getWorldTransform();
    pose.setRotation(f.orientation);
    f.body->proceedToTransform(pose);
  }
  free_.clear();
}

}  // namespace tabletop
