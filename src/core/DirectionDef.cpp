#include "core/DirectionDef.h"

#include <cmath>

#include "core/Angle.h"
#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<DirectionDef> kNames[] = {
    {DirectionDef::Left, "Left"},
    {DirectionDef::Right, "Right"},
    {DirectionDef::Front, "Front"},
    {DirectionDef::Back, "Back"}};

}  // namespace

std::string_view toString(DirectionDef d) { return nameOf(d, kNames); }

std::optional<DirectionDef> directionFromString(std::string_view name) { return valueNamed(name, kNames); }

double directionAngleDegrees(DirectionDef d) {
  switch (d) {
    case DirectionDef::Left: return 0.0;     // force from -X: moves to +X
    case DirectionDef::Right: return 180.0;  // force from +X: moves to -X
    case DirectionDef::Front: return 90.0;   // force from +Z: moves to -Z
    case DirectionDef::Back: return 270.0;   // force from -Z: moves to +Z
  }
  return 0.0;
}

// Report 3.8: the step's X component is +cos, its Z component -sin.
Vec3 pushDirection(double angleDegrees) {
  const double a = convertAngle(angleDegrees);
  return {std::cos(a), 0.0, -std::sin(a)};
}

}  // namespace tabletop
