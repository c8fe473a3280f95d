#include "core/ContactSolver.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<ContactSolver> kNames[] = {
    {ContactSolver::SequentialImpulse, "sequential_impulse"},
    {ContactSolver::Dantzig, "dantzig"},
    {ContactSolver::Automatic, "auto"}};

}  // namespace

std::string_view toString(ContactSolver s) { return nameOf(s, kNames); }

std::string describeUse(const SolverUse& use) {
  return "islands solved exactly " + std::to_string(use.direct) + " (by the guess " + std::to_string(use.guessed) +
         ", by the pivoting " + std::to_string(use.direct - use.guessed) + "), by sweeps " + std::to_string(use.swept) +
         (use.longSwept > 0 ? ", by long sweeps (a load too large to pivot) " + std::to_string(use.longSwept) : "") +
         ", by sweeps after the pivoting failed " + std::to_string(use.fallbacks) +
         (use.partBudget > 0 ? "; steps that used every part " + std::to_string(use.partBudget) : "");
}

std::optional<ContactSolver> contactSolverFromString(std::string_view name) { return valueNamed(name, kNames); }

std::string describeSolver(ContactSolver s, int iterations) {
  const std::string sweeps = std::to_string(iterations) + " iterations";
  if (s == ContactSolver::SequentialImpulse) return sweeps;
  if (s == ContactSolver::Automatic) {
    return "auto solver (dantzig where a load rests or anything but a ball slides with friction, else " + sweeps + ")";
  }
  return std::string(toString(s)) + " solver (" + sweeps + " above " + std::to_string(kDirectRowLimit) + " rows)";
}

}  // namespace tabletop
