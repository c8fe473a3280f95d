#include "python/SteppedScene.h"

#include "draw/SceneDrawing.h"
#include "headless/HeadlessFrames.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop::python {

SteppedScene::SteppedScene(Scenario scenario, SimulationMode mode, bool script)
    : scenario_(std::make_unique<Scenario>(std::move(scenario))) {
  if (!script) scenario_->script.clear();
  simulation_ = buildSimulation(*scenario_, scenario_->settings, mode);
  player_ = std::make_unique<ScriptPlayer>(*scenario_, scenario_->settings, *simulation_);
  player_->runDue();
}

// Each call's work is bounded as a whole run's is (ScriptPlayer).
void SteppedScene::step(long long n, const std::function<void()>& between) {
  player_->restartWorkCount();
  for (long long k = 0; k < n; ++k) {
    player_->step();
    between();
  }
}

void SteppedScene::runToEnd(const std::function<void()>& between) {
  player_->restartWorkCount();
  player_->runDue();
  while (!player_->finished()) {
    player_->step();
    between();
  }
}

Image SteppedScene::render(int width, int height, const CameraChoice& camera, bool arrow) const {
  const std::vector<EntityState> states = simulation_->snapshot();
  if (!frames_ || frames_->width() != width || frames_->height() != height) {
    frames_.reset();
    frames_ = std::make_unique<HeadlessFrames>(width, height);
  }
  DrawOptions options;
  options.arrow = arrow;
  return frames_->draw(makeDrawList(*scenario_, states, player_->arrow(), {}, options),
                     cameraFor(camera, *scenario_, states, SceneExtent::of(*scenario_, states), double(width) / height));
}

RunResult SteppedScene::result() const { return outcomeNow(*scenario_, scenario_->settings, *simulation_); }

}  // namespace tabletop::python
