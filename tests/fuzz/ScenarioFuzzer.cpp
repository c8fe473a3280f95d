// libFuzzer target over the scenario loader and the whole `run` path: each
// input that loads is built and run in every mode for at most a few hundred
// steps, and its outcome formatted as text and JSON. A ScenarioError is the
// expected answer to bad input; anything else (another exception, a crash,
// a sanitizer report, a leak, a hang) is a bug.
//
// Built with -DTABLETOP_FUZZ=ON and clang; see tests/fuzz/run.sh.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/SimulationMode.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "sim/ResultFormat.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace {

// Enough steps to reach the collisions and drops of a small scene, few
// enough that every input runs in milliseconds.
constexpr double kMaxFuzzSteps = 300.0;

void runEveryMode(const tabletop::Scenario& scenario) {
  tabletop::Settings settings = scenario.settings;
  settings.duration = std::min(settings.duration, kMaxFuzzSteps * settings.timestep);
  for (tabletop::SimulationMode mode : tabletop::kAllModes) {
    try {
      auto simulation = tabletop::buildSimulation(scenario, settings, mode);
      const tabletop::RunResult result = tabletop::runScript(scenario, settings, *simulation);
      (void)tabletop::formatText(result);
      (void)tabletop::toJson(result).dump();
    } catch (const tabletop::ScenarioError&) {
      // Overlapping bodies, or an action the mode cannot do: refused input.
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tabletop::Scenario scenario;
  try {
    scenario = tabletop::ScenarioLoader::loadText(text, "fuzz.json");
  } catch (const tabletop::ScenarioError& e) {
    (void)e.lines();
    return 0;
  }
  runEveryMode(scenario);
  return 0;
}
