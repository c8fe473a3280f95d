#include "core/SimulationMode.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<SimulationMode> kNames[] = {
    {SimulationMode::Bullet, "bullet"},
    {SimulationMode::Compat, "compat"},
    {SimulationMode::Rules, "rules"}};

}  // namespace

std::string_view toString(SimulationMode m) { return nameOf(m, kNames); }

std::optional<SimulationMode> simulationModeFromString(std::string_view name) { return valueNamed(name, kNames); }

}  // namespace tabletop
