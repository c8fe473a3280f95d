#include "core/Simulation.h"

#include <cmath>
#include <stdexcept>

#include "core/Angle.h"

namespace tabletop {

// The report's modes push only along the table, through the centre (report
// 3.5): such an impulse is their push by impulse at the angle it points to
// (0 deg is +X, 90 deg is -Z, as report 3.8's step).
void Simulation::applyImpulse(const std::string& entity, const Vec3& impulse, const std::optional<Vec3>& point) {
  if (point || impulse.y != 0.0) {
    throw std::invalid_argument(std::string(modeName()) +
                                " mode: only a horizontal impulse through the centre can be applied (the report's "
                                "push, report 3.5); use mode 'bullet' for one at a point or with a vertical part");
  }
  Arrow arrow;
  arrow.entity = entity;
  arrow.angleDegrees = toDegrees(std::atan2(-impulse.z, impulse.x));
  push(arrow, {PushMagnitude::Kind::Impulse, std::hypot(impulse.x, impulse.z)});
}

void Simulation::applyForce(const std::string&, const Vec3&, const Vec3&, const std::optional<Vec3>&) {
  throw std::invalid_argument(std::string(modeName()) +
                              " mode: bodies move by the report's pushes alone, not by forces; use mode 'bullet'");
}

std::vector<Vec3> Simulation::contactPoints() const {
  std::vector<Vec3> points;
  for (const ContactReport& c : contacts()) points.push_back(c.point);
  return points;
}

}  // namespace tabletop
