#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/RunResult.h"
#include "core/SimulationMode.h"
#include "scenario/Scenario.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {

/// Positions (m) of one entity in one mode, sampled as the run went.
struct Trajectory {
  std::vector<Vec3> points;
};

/// One entity in one mode against the rules.
struct ModeOutcome {
  EntityState state;
  std::optional<DirectionDef> edge;  ///< the table edge it left by, if it did
  double fromRules = 0.0;   ///< distance of the final centre from the rules', m
  std::string verdict;      ///< "reference", "agrees", or "diverges: <reason>"
  Trajectory trajectory;
};

/// The three modes' outcomes for one entity, indexed like kAllModes
/// (rules, compat, bullet).
struct EntityComparison {
  std::string name;
  Vec3 start;
  std::array<ModeOutcome, 3> modes;
};

struct Comparison {
  std::string scenario;
  std::string file;
  std::array<RunResult, 3> runs;  ///< like kAllModes
  std::vector<EntityComparison> entities;
};

/// On-table positions within this of the rules' agree, metres.
inline constexpr double kAgreeDistance = 1e-3;

/// One mode's run, with each entity's positions sampled as it went.
struct RecordedRun {
  RunResult run;
  std::vector<Trajectory> paths;  ///< like the scenario's entities
};

/// Runs `scenario` in `mode`, sampling trajectories every 1/120 s.
RecordedRun runRecorded(const Scenario& scenario, const Settings& settings, SimulationMode mode,
                        const StepObserver& afterStep = {});

/// Each entity's outcome in `other` (its state, edge, trajectory, distance
/// from the rules' final centre and verdict) against the run of the rules.
std::vector<ModeOutcome> againstRules(const Scenario& scenario, const RecordedRun& rules, RecordedRun other);

/// Runs `scenario` in every mode (recording trajectories) and compares each
/// entity's outcome with the rules'. Throws ScenarioError if a mode cannot
/// run the scenario. `afterStep`, when given, sees every mode's simulation
/// after every step (and may throw to stop the comparison).
Comparison compareModes(const Scenario& scenario, const Settings& settings, const StepObserver& afterStep = {});

/// Why `other` differs from the rules' outcome for an entity that started at
/// `start`: "agrees", or "diverges: " and one of: slid off (it left the
/// table, the rules kept it), stayed behind (the rules dropped it, it stayed
/// on the table), dropped from another edge, tipped (no longer upright on
/// the table), rotated (turned about the vertical by more than 2 degrees),
/// bounced back (came back more than 5 mm along the rules' line from the
/// furthest point it reached), stopped short,
/// went further, went sideways. Two entities dropped by the same edge agree
/// wherever they land: where a fall ends is physics, not a rule.
std::string verdict(const Vec3& start, const ModeOutcome& rules, const ModeOutcome& other);

/// The comparison as text: one row per entity and mode.
std::string formatComparison(const Comparison& c);

/// The comparison as JSON (documented in scenarios/README.md).
nlohmann::json comparisonJson(const Comparison& c);

}  // namespace tabletop
