#include "scenario/Orientation.h"

#include <cmath>

#include "core/Angle.h"

namespace tabletop {

std::optional<Quat> readOrientation(fields::Fields& entity) {
  const nlohmann::json* v = entity.get("orientation", false);
  if (!v) return std::nullopt;
  fields::Fields f(*v, entity.at("orientation"), entity.problems());
  const int forms = int(f.has("quaternion")) + int(f.has("euler")) + int(f.has("axis"));
  if (f.valid() && forms != 1) {
    f.fail(entity.at("orientation"), "expected exactly one of 'quaternion', 'euler', 'axis'");
    return std::nullopt;
  }
  std::optional<Quat> q;
  if (f.has("quaternion")) {
    const std::vector<double> c = f.numbers(*f.get("quaternion", true), f.at("quaternion"), 4, 4, ranges::kFinite);
    if (c.size() == 4) {
      const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3]);
      if (n > 1e-9) {
        q = Quat{c[0] / n, c[1] / n, c[2] / n, c[3] / n};
      } else {
        f.fail(f.at("quaternion"), "expected a quaternion [w, x, y, z] that is not all 0");
      }
    }
  } else if (f.has("euler")) {
    if (const auto e = f.vec3("euler", ranges::kAngle)) {
      q = Quat::about({1, 0, 0}, convertAngle(e->x)) * Quat::about({0, 1, 0}, convertAngle(e->y)) *
          Quat::about({0, 0, 1}, convertAngle(e->z));
    }
  } else if (f.has("axis")) {
    const std::optional<Vec3> axis = f.vec3("axis", ranges::kFinite);
    const double angle = f.number("angle", ranges::kAngle, 0.0, true);
    if (axis) {
      const double n = axis->length();
      if (n > 1e-9) {
        q = Quat::about(*axis * (1.0 / n), convertAngle(angle));
      } else {
        f.fail(f.at("axis"), "expected an axis [x, y, z] that is not all 0");
      }
    }
  }
  f.finish();
  return q;
}

bool onlyYaw(const Quat& q, double& yawDegrees) {
  if (std::abs(q.x) > 1e-12 || std::abs(q.z) > 1e-12) return false;
  yawDegrees = toDegrees(2.0 * std::atan2(q.y, q.w));
  return true;
}

}  // namespace tabletop
