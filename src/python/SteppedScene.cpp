#include "python/SteppedScene.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "draw/SceneDrawing.h"
#include "headless/HeadlessFrames.h"
#include "scenario/ScenarioLoader.h"
#include "scenario/ValueRanges.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop::python {

SteppedScene::SteppedScene(Scenario scenario, SimulationMode mode, bool script)
    : scenario_(std::make_unique<Scenario>(std::move(scenario))), mode_(mode) {
  if (!script) scenario_->script.clear();
  built_ = scenario_->settings;
  build();
}

void SteppedScene::build() {
  player_.reset();
  scenario_->settings = built_;
  simulation_ = buildSimulation(*scenario_, scenario_->settings, mode_);
  player_ = std::make_unique<ScriptPlayer>(*scenario_, scenario_->settings, *simulation_);
  player_->runDue();
  history_.clear();
  failed_.clear();
}

// Each step is kept as it is taken: a Ctrl-C seen between steps leaves a
// state the history gives back; a step that raised (divergence, the work
// limit) leaves one it cannot.
void SteppedScene::stepPlayer(long long n, const std::function<void()>& between) {
  for (long long k = 0; k < n; ++k) {
    try {
      player_->step();
    } catch (const std::exception& e) {
      failed_ = e.what();
      throw;
    }
    history_.add(SceneCall::of(SceneCall::Kind::Steps, 1));
    between();
  }
}

// Each call's work is bounded as a whole run's is (ScriptPlayer).
void SteppedScene::step(long long n, const std::function<void()>& between) {
  player_->restartWorkCount();
  stepPlayer(n, between);
}

void SteppedScene::runToEnd(const std::function<void()>& between) {
  player_->restartWorkCount();
  player_->runDue();
  history_.add(SceneCall::of(SceneCall::Kind::RunDue));
  while (!player_->finished()) stepPlayer(1, between);
}

void SteppedScene::push(const Arrow& arrow, const PushMagnitude& magnitude) {
  player_->push(arrow, magnitude);
  SceneCall call = SceneCall::of(SceneCall::Kind::Push);
  call.arrow = arrow;
  call.magnitude = magnitude;
  history_.add(call);
}

void SteppedScene::rotate(const std::string& entity, double degrees) {
  simulation_->rotate(entity, degrees);
  SceneCall call = SceneCall::of(SceneCall::Kind::Rotate);
  call.arrow.entity = entity;
  call.value = degrees;
  history_.add(call);
}

void SteppedScene::applyImpulse(const std::string& entity, const Vec3& impulse, const std::optional<Vec3>& point) {
  simulation_->applyImpulse(entity, impulse, point);
  SceneCall call = SceneCall::of(SceneCall::Kind::Impulse);
  call.arrow.entity = entity;
  call.vector = impulse;
  call.point = point;
  history_.add(call);
}

void SteppedScene::applyForce(const std::string& entity, const Vec3& force, const Vec3& torque,
                              const std::optional<Vec3>& point) {
  simulation_->applyForce(entity, force, torque, point);
  SceneCall call = SceneCall::of(SceneCall::Kind::Load);
  call.arrow.entity = entity;
  call.vector = force;
  call.torque = torque;
  call.point = point;
  history_.add(call);
}

void SteppedScene::setTimestep(double seconds) {
  simulation_->setTimestep(seconds);
  scenario_->settings.timestep = seconds;
  history_.add(SceneCall::of(SceneCall::Kind::Timestep, 0, seconds));
}

void SteppedScene::setGravity(double g) {
  simulation_->setGravity(g);
  scenario_->settings.gravity = g;
  history_.add(SceneCall::of(SceneCall::Kind::Gravity, 0, g));
}

void SteppedScene::reset() { build(); }

void SteppedScene::restore(const SceneHistory& history, const std::function<void()>& between) {
  for (const SceneCall& call : history.calls()) {
    if (call.namesEntity() && std::none_of(scenario_->entities.begin(), scenario_->entities.end(),
                              [&](const EntitySpec& e) { return e.name == call.arrow.entity; })) {
      throw std::invalid_argument("history: no entity named \"" + call.arrow.entity + "\" in this scene");
    }
  }
  const std::string tooMuch = tooLong(history);
  if (!tooMuch.empty()) throw std::invalid_argument("history: " + tooMuch);
  build();
  // The calls were bounded as they were made; their steps are bounded
  // above as a whole, so the run's limit is not counted again.
  player_->setWorkLimit(std::numeric_limits<double>::infinity());
  struct Limit {
    ScriptPlayer& player;
    ~Limit() { player.setWorkLimit(WorkCount::kRunLimit); }
  } const limit{*player_};
  for (const SceneCall& call : history.calls()) {
    switch (call.kind) {
      case SceneCall::Kind::Steps: stepPlayer(call.count, between); break;
      case SceneCall::Kind::RunDue:
        player_->runDue();
        history_.add(call);
        break;
      case SceneCall::Kind::Push: push(call.arrow, call.magnitude); break;
      case SceneCall::Kind::Rotate: rotate(call.arrow.entity, call.value); break;
      case SceneCall::Kind::Timestep: setTimestep(call.value); break;
      case SceneCall::Kind::Gravity: setGravity(call.value); break;
      case SceneCall::Kind::Impulse: applyImpulse(call.arrow.entity, call.vector, call.point); break;
      case SceneCall::Kind::Load: applyForce(call.arrow.entity, call.vector, call.torque, call.point); break;
    }
  }
}

std::string SteppedScene::tooLong(const SceneHistory& history) const {
  if (history.steps() > kMaxSteps) return "expected at most 1e7 steps in all, got " + ranges::number(history.steps());
  return ScenarioLoader::workProblem(history.steps(), scenario_->settings, scenario_->entities.size());
}

std::string SteppedScene::unsaveable() const {
  if (!failed_.empty()) return "a step raised (" + failed_ + "); reset() or set_state() first";
  if (!history_.complete()) return "more than 1e5 calls were made since the scene was built or reset";
  const std::string tooMuch = tooLong(history_);
  if (!tooMuch.empty()) return "the steps since the scene was built or reset are more than one run may take: " + tooMuch;
  return {};
}

// A run that stops early (divergence, the work limit) frames what it
// reached.
SceneExtent SteppedScene::fittedExtent(const std::vector<EntityState>& now) const {
  if (!runExtent_) {
    Scenario scenario = *scenario_;
    scenario.settings = built_;
    SteppedScene trial(std::move(scenario), mode_, true);
    SceneExtent extent = SceneExtent::of(*scenario_, trial.simulation().snapshot());
    try {
      while (!trial.finished()) {
        trial.player_->step();
        extent.add(sceneBounds(*scenario_, trial.simulation().snapshot()));
      }
    } catch (const std::exception&) {
    }
    runExtent_ = extent;
  }
  SceneExtent extent = *runExtent_;
  extent.add(sceneBounds(*scenario_, now));
  return extent;
}

Image SteppedScene::render(int width, int height, const CameraChoice& camera, bool arrow, bool fitNow,
                           BodyImage* bodies) const {
  const std::vector<EntityState> states = simulation_->snapshot();
  if (!frames_ || frames_->width() != width || frames_->height() != height) {
    frames_.reset();
    frames_ = std::make_unique<HeadlessFrames>(width, height);
  }
  DrawOptions options;
  options.arrow = arrow;
  const DrawList list = makeDrawList(*scenario_, states, player_->arrow(), {}, options);
  const Camera view = cameraFor(
      camera, *scenario_, states,
      fitNow || camera.kind != CameraChoice::Kind::Fit ? SceneExtent::of(*scenario_, states) : fittedExtent(states),
      double(width) / height);
  Image image = frames_->draw(list, view);
  if (bodies) *bodies = frames_->drawBodies(list, view);
  return image;
}

RunResult SteppedScene::result() const { return outcomeNow(*scenario_, scenario_->settings, *simulation_); }

}  // namespace tabletop::python
