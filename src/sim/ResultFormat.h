#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/RunResult.h"
#include "core/Text.h"

namespace tabletop {

/// The readable outcome: settings, each entity's final position, yaw,
/// status and support, then the events with their times, then the hash.
std::string formatText(const RunResult& result);

/// The outcome as one JSON object (documented in scenarios/README.md).
nlohmann::json toJson(const RunResult& result);

/// The version of run --json's document; raised when a key changes meaning
/// or goes (schema: data/schema/run-output.schema.json).
inline constexpr int kRunFormatVersion = 1;

/// run --json's document: {"format_version": kRunFormatVersion, "runs":
/// [toJson(r) for each result]}, the same shape for one run as for several.
nlohmann::json runDocument(const std::vector<RunResult>& results);

/// One event as a readable phrase ("push A Left, step 0.200 m ...").
std::string describe(const Event& event);

}  // namespace tabletop
