#include "core/ContactSolver.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<ContactSolver> kNames[] = {
    {ContactSolver::SequentialImpulse, "sequential_impulse"},
    {ContactSolver::Dantzig, "dantzig"}};

}  // namespace

std::string_view toString(ContactSolver s) { return nameOf(s, kNames); }

std::optional<ContactSolver> contactSolverFromString(std::string_view name) { return valueNamed(name, kNames); }

std::string describeSolver(ContactSolver s, int iterations) {
  const std::string sweeps = std::to_string(iterations) + " iterations";
  if (s == ContactSolver::SequentialImpulse) return sweeps;
  return std::string(toString(s)) + " solver (" + sweeps + " above " + std::to_string(kDirectRowLimit) + " rows)";
}

}  // namespace tabletop
