#pragma once

#include <cmath>

namespace tabletop {

/// A plain 3-vector in metres (or m/s), Y up, as in OpenGL (report 1).
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  double dot(const Vec3& o) const { return x * o.x + y * o.y + z * o.z; }
  double length() const { return std::sqrt(dot(*this)); }
  bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
};

}  // namespace tabletop
