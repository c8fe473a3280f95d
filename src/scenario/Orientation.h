#pragma once

#include <optional>

#include "core/Quat.h"
#include "scenario/JsonFields.h"

namespace tabletop {

/// An entity's "orientation", one of three forms as MuJoCo takes them:
/// {"quaternion": [w, x, y, z]} (normalised; not all zero), {"euler":
/// [a, b, c]} in degrees about x, then the turned y, then the turned z
/// (intrinsic x-y-z, MuJoCo's default "xyz" sequence), or {"axis": [x,
/// y, z], "angle": degrees}. None when absent or wrong (a problem then).
std::optional<Quat> readOrientation(fields::Fields& entity);

/// True when `q` turns only about +Y (the report's yaw), to rounding;
/// `yawDegrees` is then that turn.
bool onlyYaw(const Quat& q, double& yawDegrees);

}  // namespace tabletop
