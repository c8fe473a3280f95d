#pragma once

#include <algorithm>

#include "core/Material.h"

namespace tabletop {

/// The coefficients Bullet uses at a contact between two materials
/// (btManifoldResult's default combiners): friction and restitution
/// multiply; rolling friction is rf_a * f_b + rf_b * f_a; friction terms
/// are capped at 10.
inline Material combine(const Material& a, const Material& b) {
  constexpr double kMaxFriction = 10.0;
  return {std::clamp(a.friction * b.friction, -kMaxFriction, kMaxFriction),
          std::clamp(a.rollingFriction * b.friction + b.rollingFriction * a.friction,
                     -kMaxFriction, kMaxFriction),
          a.restitution * b.restitution};
}

}  // namespace tabletop
