#pragma once

#include <optional>
#include <string_view>

namespace tabletop {

/// The three ways to run a scene: full Bullet physics, Bullet constrained to
/// the report's rules, and the report's rules alone.
enum class SimulationMode { Bullet, Compat, Rules };

/// The command-line name of a mode ("bullet", "compat", "rules").
std::string_view toString(SimulationMode m);

/// Parses a mode name; nullopt if it is not one.
std::optional<SimulationMode> simulationModeFromString(std::string_view name);

/// All modes, in the order `compare` prints them.
inline constexpr SimulationMode kAllModes[] = {SimulationMode::Rules, SimulationMode::Compat, SimulationMode::Bullet};

}  // namespace tabletop
