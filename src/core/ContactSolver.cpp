#include "core/ContactSolver.h"

#include "core/EnumNames.h"

namespace tabletop {

std::string_view toString(ContactSolver s) {
  switch (s) {
    case ContactSolver::SequentialImpulse: return "sequential_impulse";
    case ContactSolver::Dantzig: return "dantzig";
  }
  return "sequential_impulse";
}

std::optional<ContactSolver> contactSolverFromString(std::string_view name) {
  return enumFromName(name, kAllContactSolvers);
}

std::string describeSolver(ContactSolver s, int iterations) {
  const std::string sweeps = std::to_string(iterations) + " iterations";
  if (s == ContactSolver::SequentialImpulse) return sweeps;
  return std::string(toString(s)) + " solver (" + sweeps + " above " + std::to_string(kDirectRowLimit) + " rows)";
}

}  // namespace tabletop
