#pragma once

namespace tabletop {

/// pi to double precision (the report rounds it to 3.1416; we do not).
inline constexpr double kPi = 3.14159265358979323846;

/// Degrees to radians: the report's ConvertAngle (report 3.2).
constexpr double convertAngle(double degrees) { return degrees * kPi / 180.0; }

/// Radians to degrees.
constexpr double toDegrees(double radians) { return radians * 180.0 / kPi; }

}  // namespace tabletop
