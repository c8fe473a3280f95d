#pragma once

#include <algorithm>

#include "core/Material.h"

namespace tabletop {

/// The coefficients Bullet uses at a contact between two materials
/// (btManifoldResult's default combiners): friction and restitution
/// multiply; rolling and spinning friction are x_a * f_b + x_b * f_a;
/// friction terms are capped at 10.
inline Material combine(const Material& a, const Material& b) {
  constexpr double kMaxFriction = 10.0;
  const auto mixed = [&](double xa, double xb) {
    return std::clamp(xa * b.friction + xb * a.friction, -kMaxFriction, kMaxFriction);
  };
  return {std::clamp(a.friction * b.friction, -kMaxFriction, kMaxFriction),
          mixed(a.rollingFriction, b.rollingFriction), mixed(a.spinningFriction, b.spinningFriction),
          a.restitution * b.restitution};
}

}  // namespace tabletop
