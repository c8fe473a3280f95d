#include "draw/Camera.h"

#include <algorithm>
#include <cmath>

#include "core/Angle.h"

namespace tabletop {
namespace {

Vec3 unit(const Vec3& v) { return v * (1.0 / v.length()); }

}  // namespace

Vec3 Camera::eye() const {
  const double yaw = convertAngle(yawDegrees), pitch = convertAngle(pitchDegrees);
  return target + Vec3{std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)} * distance;
}

Mat4 Camera::view() const {
  // The classic look-at matrix: rows are the eye's right, up and back axes.
  const Vec3 e = eye();
  const Vec3 back = unit(e - target);
  const Vec3 right = unit(Mat4::cross({0, 1, 0}, back));
  const Vec3 up = Mat4::cross(back, right);
  Mat4 r;
  const Vec3 axes[3] = {right, up, back};
  for (int i = 0; i < 3; ++i) {
    r.at(i, 0) = axes[i].x, r.at(i, 1) = axes[i].y, r.at(i, 2) = axes[i].z;
    r.at(i, 3) = -axes[i].dot(e);
  }
  return r;
}

Mat4 Camera::projection(double aspect) const {
  const double f = 1.0 / std::tan(convertAngle(0.5 * fovyDegrees));
  Mat4 r;
  r.at(0, 0) = f / aspect;
  r.at(1, 1) = f;
  r.at(2, 2) = (farPlane + nearPlane) / (nearPlane - farPlane);
  r.at(2, 3) = 2.0 * farPlane * nearPlane / (nearPlane - farPlane);
  r.at(3, 2) = -1.0;
  r.at(3, 3) = 0.0;
  return r;
}

std::optional<PixelPoint> Camera::project(const Vec3& p, int width, int height) const {
  const std::array<double, 4> eyeSpace = view().apply(p);
  if (eyeSpace[2] >= -nearPlane) return std::nullopt;
  const std::array<double, 4> clip = projection(double(width) / height).apply({eyeSpace[0], eyeSpace[1], eyeSpace[2]});
  const double x = clip[0] / clip[3], y = clip[1] / clip[3];
  return PixelPoint{0.5 * (x + 1.0) * width, 0.5 * (1.0 - y) * height, -eyeSpace[2]};
}

void Camera::fit(const std::vector<Bound>& bounds, double aspect, double margin) {
  if (bounds.empty()) return;
  Vec3 low = bounds[0].centre, high = bounds[0].centre;
  for (const Bound& b : bounds) {
    for (const Vec3& p : {b.centre - Vec3{b.radius, b.radius, b.radius}, b.centre + Vec3{b.radius, b.radius, b.radius}}) {
      low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
  }
  target = (low + high) * 0.5;
  // In the eye's axes, a ball at height y, across x and depth z from the
  // target stands within the view from distance D when
  // |y| + r / cos(h) <= (D + z) tan(h), h the half field (and the same
  // across, with the horizontal half field).
  distance = 1.0;
  const Mat4 v = view();
  const Vec3 right{v.at(0, 0), v.at(0, 1), v.at(0, 2)}, up{v.at(1, 0), v.at(1, 1), v.at(1, 2)},
      back{v.at(2, 0), v.at(2, 1), v.at(2, 2)};
  const double halfY = convertAngle(0.5 * fovyDegrees) * (1.0 - margin);
  const double halfX = std::atan(aspect * std::tan(convertAngle(0.5 * fovyDegrees))) * (1.0 - margin);
  double needed = nearPlane;
  for (const Bound& b : bounds) {
    const Vec3 d = b.centre - target;
    const double z = -d.dot(back);  // towards the target from the eye is positive
    for (const auto& [across, half] : {std::pair{std::abs(d.dot(up)), halfY}, std::pair{std::abs(d.dot(right)), halfX}}) {
      needed = std::max(needed, (across + b.radius / std::cos(half)) / std::tan(half) - z);
    }
    needed = std::max(needed, b.radius + nearPlane - z);
  }
  distance = needed;
}

void Camera::zoom(double factor) { distance = std::clamp(distance * factor, 0.2, 40.0); }

void Camera::orbit(double yaw, double pitch) {
  yawDegrees = std::remainder(yawDegrees + yaw, 360.0);
  pitchDegrees = std::clamp(pitchDegrees + pitch, -89.0, 89.0);
}

void Camera::pan(double right, double up) {
  const Mat4 v = view();
  const double scale = 2.0 * distance * std::tan(convertAngle(0.5 * fovyDegrees));
  const Vec3 r{v.at(0, 0), v.at(0, 1), v.at(0, 2)}, u{v.at(1, 0), v.at(1, 1), v.at(1, 2)};
  target = target + r * (right * scale) + u * (up * scale);
}

std::vector<std::string> Camera::names() { return {"front", "corner", "side", "top"}; }

std::optional<Camera> Camera::named(const std::string& name, const TableSpec& table) {
  Camera c;
  const double size = std::max({table.width, table.depth, table.height});
  c.target = {table.centreX, 0.8 * table.height, table.centreZ};
  c.distance = 2.2 * size;
  if (name == "front") return c;
  if (name == "corner") {
    c.yawDegrees = 35.0, c.pitchDegrees = 30.0;
    return c;
  }
  if (name == "side") {
    c.yawDegrees = 90.0, c.pitchDegrees = 20.0;
    return c;
  }
  if (name == "top") {
    c.pitchDegrees = 89.0, c.target.y = table.height;
    c.distance = 2.0 * std::max(table.width, table.depth);
    return c;
  }
  return std::nullopt;
}

}  // namespace tabletop
