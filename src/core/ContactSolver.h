#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tabletop {

/// How the contact impulses of each step are found (full physics):
///  - SequentialImpulse: Bullet's projected Gauss-Seidel, `iterations`
///    sweeps over the contact rows. Cheap per row, but a heavy body on a
///    light one, or a tall stack, needs far more sweeps than it gets.
///  - Dantzig: Bullet's MLCP solver with Dantzig's pivoting method, each
///    island of touching bodies solved exactly as one linear
///    complementarity problem; an island of more than
///    kDirectRowLimit rows, or one the pivoting cannot solve, is left to
///    sequential impulses.
enum class ContactSolver { SequentialImpulse, Dantzig };

/// The largest island (normal and friction rows together) the Dantzig
/// solver takes on: its cost grows as the cube of the rows
/// (docs/hard-cases.md).
inline constexpr int kDirectRowLimit = 300;

/// The scenario and command-line name ("sequential_impulse", "dantzig").
std::string_view toString(ContactSolver s);

/// How a run's header names the solver: "10 iterations" for sequential
/// impulses; "dantzig solver (10 iterations above 300 rows)" for Dantzig,
/// whose islands ignore the count unless too large.
std::string describeSolver(ContactSolver s, int iterations);

/// Parses a name; nullopt if it is not one.
std::optional<ContactSolver> contactSolverFromString(std::string_view name);

inline constexpr ContactSolver kAllContactSolvers[] = {ContactSolver::SequentialImpulse, ContactSolver::Dantzig};

}  // namespace tabletop
