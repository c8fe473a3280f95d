#pragma once

#include <array>
#include <cmath>

#include "core/Vec3.h"

namespace tabletop {

/// A 4x4 matrix of doubles in OpenGL's column-major order (element (row r,
/// column c) at index 4c + r), for the camera and the renderer.
struct Mat4 {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  double& at(int row, int col) { return m[static_cast<std::size_t>(4 * col + row)]; }
  double at(int row, int col) const { return m[static_cast<std::size_t>(4 * col + row)]; }

  Mat4 operator*(const Mat4& o) const {
    Mat4 r;
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        double s = 0.0;
        for (int k = 0; k < 4; ++k) s += at(i, k) * o.at(k, j);
        r.at(i, j) = s;
      }
    }
    return r;
  }

  /// This matrix applied to the point (p, w); returns the 4 components.
  std::array<double, 4> apply(const Vec3& p, double w = 1.0) const {
    std::array<double, 4> r{};
    for (int i = 0; i < 4; ++i) r[static_cast<std::size_t>(i)] = at(i, 0) * p.x + at(i, 1) * p.y + at(i, 2) * p.z + at(i, 3) * w;
    return r;
  }

  /// A rigid pose: the rotation of the unit quaternion (w, x, y, z), then
  /// the translation `position`.
  static Mat4 pose(const Vec3& position, const std::array<double, 4>& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    Mat4 r;
    r.at(0, 0) = 1 - 2 * (y * y + z * z), r.at(0, 1) = 2 * (x * y - w * z), r.at(0, 2) = 2 * (x * z + w * y);
    r.at(1, 0) = 2 * (x * y + w * z), r.at(1, 1) = 1 - 2 * (x * x + z * z), r.at(1, 2) = 2 * (y * z - w * x);
    r.at(2, 0) = 2 * (x * z - w * y), r.at(2, 1) = 2 * (y * z + w * x), r.at(2, 2) = 1 - 2 * (x * x + y * y);
    r.at(0, 3) = position.x, r.at(1, 3) = position.y, r.at(2, 3) = position.z;
    return r;
  }

  static Mat4 translation(const Vec3& t) { return pose(t, {1, 0, 0, 0}); }

  static Mat4 scale(const Vec3& s) {
    Mat4 r;
    r.at(0, 0) = s.x, r.at(1, 1) = s.y, r.at(2, 2) = s.z;
    return r;
  }

  /// A frame whose local +Y runs along the unit vector `axis`, from `origin`.
  static Mat4 alongAxis(const Vec3& origin, const Vec3& axis) {
    // Any unit vector not parallel to the axis completes the frame.
    const Vec3 helper = std::abs(axis.y) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    Vec3 u = cross(helper, axis);
    u = u * (1.0 / u.length());
    const Vec3 v = cross(axis, u);
    Mat4 r;
    r.at(0, 0) = u.x, r.at(1, 0) = u.y, r.at(2, 0) = u.z;
    r.at(0, 1) = axis.x, r.at(1, 1) = axis.y, r.at(2, 1) = axis.z;
    r.at(0, 2) = v.x, r.at(1, 2) = v.y, r.at(2, 2) = v.z;
    r.at(0, 3) = origin.x, r.at(1, 3) = origin.y, r.at(2, 3) = origin.z;
    return r;
  }

  static Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  }
};

}  // namespace tabletop
