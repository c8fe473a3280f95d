#include "core/SimulationMode.h"

#include "core/EnumNames.h"

namespace tabletop {

std::string_view toString(SimulationMode m) {
  switch (m) {
    case SimulationMode::Bullet: return "bullet";
    case SimulationMode::Compat: return "compat";
    case SimulationMode::Rules: return "rules";
  }
  return "bullet";
}

std::optional<SimulationMode> simulationModeFromString(std::string_view name) {
  return enumFromName(name, kAllModes);
}

}  // namespace tabletop
