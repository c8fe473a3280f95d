#pragma once

#include "core/Support.h"
#include "core/Vec3.h"

namespace tabletop {

/// One point where two bodies touch after the last step, as a user reads it
/// (MuJoCo's data.contact, PyBullet's getContactPoints): the two bodies
/// (an entity, the table or the ground), the point midway between their
/// surfaces, the normal pointing from `b` to `a`, how far the surfaces
/// overlap along it, and the normal impulse the last solve gave the point.
struct ContactReport {
  Support a;
  Support b;
  Vec3 point;              ///< m, world frame
  Vec3 normal;             ///< unit, from b towards a
  double depth = 0.0;      ///< overlap, m; negative while a gap is left
  double impulse = 0.0;    ///< normal impulse of the step's last solve, N s
};

}  // namespace tabletop
