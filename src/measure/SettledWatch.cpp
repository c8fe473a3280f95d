#include "measure/SettledWatch.h"

#include <algorithm>
#include <cmath>

#include <btBulletDynamicsCommon.h>

namespace tabletop {

double mechanicalEnergy(const btRigidBody& body, double gravity) {
  if (body.getInvMass() == 0) return 0.0;
  const double m = 1.0 / body.getInvMass();
  const btVector3 w = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
  const btVector3 inv = body.getInvInertiaDiagLocal();
  double rotational = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (inv[k] > 0) rotational += w[k] * w[k] / inv[k];
  }
  return 0.5 * m * body.getLinearVelocity().length2() + 0.5 * rotational +
         m * gravity * body.getCenterOfMassPosition().y();
}

void SettledWatch::observe(double time, const std::vector<const btRigidBody*>& bodies, double deepest) {
  constexpr double kSlack = 1e-6;  // s: a step's time as a sum of steps
  if (time < from_ - kSlack || result_.measured) return;
  double energy = 0.0;
  for (const btRigidBody* b : bodies) energy += mechanicalEnergy(*b, gravity_);
  if (!started_) {
    started_ = true;
    lowest_ = energy;
    for (const btRigidBody* b : bodies) {
      const btVector3& c = b->getCenterOfMassPosition();
      start_.insert(start_.end(), {c.x(), c.y(), c.z()});
    }
    return;
  }
  result_.penetration = std::max(result_.penetration, deepest);
  result_.energyGain = std::max(result_.energyGain, energy - lowest_);
  lowest_ = std::min(lowest_, energy);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const btVector3& c = bodies[i]->getCenterOfMassPosition();
    const double moved = std::sqrt((c.x() - start_[3 * i]) * (c.x() - start_[3 * i]) +
                                   (c.y() - start_[3 * i + 1]) * (c.y() - start_[3 * i + 1]) +
                                   (c.z() - start_[3 * i + 2]) * (c.z() - start_[3 * i + 2]));
    result_.drift = std::max(result_.drift, moved);
  }
  if (time >= to_ - kSlack) result_.measured = true;
}

}  // namespace tabletop
