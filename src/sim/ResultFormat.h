#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/RunResult.h"
#include "core/Text.h"

namespace tabletop {

/// The readable outcome: settings, each entity's final position, yaw,
/// status and support, then the events with their times, then the hash.
std::string formatText(const RunResult& result);

/// The outcome as one JSON object (documented in scenarios/README.md).
nlohmann::json toJson(const RunResult& result);

/// One event as a readable phrase ("push A Left, step 0.200 m ...").
std::string describe(const Event& event);

}  // namespace tabletop
