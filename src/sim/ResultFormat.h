#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/RunResult.h"

namespace tabletop {

/// The readable outcome: settings, each entity's final position, yaw,
/// status and support, then the events with their times, then the hash.
std::string formatText(const RunResult& result);

/// The outcome as one JSON object (documented in scenarios/README.md).
nlohmann::json toJson(const RunResult& result);

/// `v` with `digits` decimals ("%.*f").
std::string fixed(double v, int digits);

/// `s` padded with spaces to `width` columns, and at least one space after.
std::string padded(const std::string& s, std::size_t width);

/// One event as a readable phrase ("push A Left, step 0.200 m ...").
std::string describe(const Event& event);

}  // namespace tabletop
