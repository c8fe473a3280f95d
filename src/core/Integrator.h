#pragma once

#include <optional>
#include <string_view>

namespace tabletop {

/// How bodies' positions follow from their velocities over a step (see
/// physics/step/DynamicsWorld.h):
///  - Euler: Bullet's own semi-implicit Euler, x += v1 dt, first order;
///  - Trapezoid: x += (v0 + v1) dt / 2 wherever the velocity changed
///    smoothly, exact for accelerations constant through a step.
enum class Integrator { Euler, Trapezoid };

/// The scenario and command-line name ("euler", "trapezoid").
std::string_view toString(Integrator i);

/// Parses a name; nullopt if it is not one.
std::optional<Integrator> integratorFromString(std::string_view name);

inline constexpr Integrator kAllIntegrators[] = {Integrator::Euler, Integrator::Trapezoid};

}  // namespace tabletop
