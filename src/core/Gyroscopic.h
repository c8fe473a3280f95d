#pragma once

#include <optional>
#include <string_view>

namespace tabletop {

/// How Bullet adds the gyroscopic term w x (I w) of a spinning body (its
/// btRigidBody flags). Without it, the angular velocity stays fixed while the
/// inertia turns with the body, so a body spinning about any axis but a
/// principal one does not keep its angular momentum:
///  - None: no term (Bullet's behaviour before 2.83);
///  - Explicit: the term from the step's start, forward Euler, clamped by
///    Bullet's largest gyroscopic force; gains energy;
///  - ImplicitWorld: one implicit Euler step in world coordinates;
///  - ImplicitBody: one implicit Euler step in the body's own axes (Bullet's
///    default), which keeps energy from growing.
/// Only bodies in contact use it: one touching nothing turns by the free
/// rigid body's exact solution (physics/step/FreeFlight.h).
enum class Gyroscopic { None, Explicit, ImplicitWorld, ImplicitBody };

/// The scenario and command-line name ("none", "explicit", "implicit_world",
/// "implicit_body").
std::string_view toString(Gyroscopic g);

/// Parses a name; nullopt if it is not one.
std::optional<Gyroscopic> gyroscopicFromString(std::string_view name);

inline constexpr Gyroscopic kAllGyroscopics[] = {Gyroscopic::None, Gyroscopic::Explicit, Gyroscopic::ImplicitWorld,
                                                 Gyroscopic::ImplicitBody};

}  // namespace tabletop
