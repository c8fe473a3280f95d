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
///  - Automatic: each island chosen for itself, by what it
///    holds: the pivoting for one that carries a load (a body resting on
///    another), sequential impulses for the rest (bodies on the table or
///    the floor alone, or striking each other side on) and for islands
///    over kDirectRowLimit rows.
enum class ContactSolver { SequentialImpulse, Dantzig, Automatic };

/// How a run's contact islands were solved, one count per island and step
/// (or part of a step) with contacts.
struct SolverUse {
  long direct = 0;     ///< exactly
  long guessed = 0;    ///< of those, by a guess of the pressing points (ActiveSetSolver); the rest by the pivoting
  long swept = 0;      ///< by sequential impulses, by choice or by size
  long longSwept = 0;  ///< carrying a load but too large to pivot: the long sweeps (IslandSolver)
  long fallbacks = 0;  ///< meant for the pivoting, which failed on them (then swept)
  /// Steps whose events used up the parts a step may be cut into (the
  /// last part then took what was left whole, its events unsplit).
  long partBudget = 0;
  /// Parts the steps were taken in, all told (a step not cut is one): each
  /// part runs the collision and the solve for the whole world.
  long parts = 0;
  /// The most moving bodies one island solved held.
  long largestIsland = 0;
};

/// The largest island (normal and friction rows together) the Dantzig
/// solver takes on: its cost grows as the cube of the rows
/// (docs/hard-cases.md).
inline constexpr int kDirectRowLimit = 300;

/// The scenario and command-line name ("sequential_impulse", "dantzig",
/// "auto").
std::string_view toString(ContactSolver s);

/// How a run's header names the solver: "10 iterations" for sequential
/// impulses; "dantzig solver (10 iterations above 300 rows)" for Dantzig,
/// whose islands ignore the count unless too large; "auto solver (dantzig
/// where a load rests or anything but a ball slides with friction, else
/// 10 iterations)".
std::string describeSolver(ContactSolver s, int iterations);

/// One line on how a run's islands were solved: "islands solved exactly
/// 480, by sweeps 12, by sweeps after the pivoting failed 0".
std::string describeUse(const SolverUse& use);

/// Parses a name; nullopt if it is not one.
std::optional<ContactSolver> contactSolverFromString(std::string_view name);

inline constexpr ContactSolver kAllContactSolvers[] = {ContactSolver::SequentialImpulse, ContactSolver::Dantzig,
                                                  ContactSolver::Automatic};

}  // namespace tabletop
