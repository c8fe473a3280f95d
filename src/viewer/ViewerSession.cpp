#include "viewer/ViewerSession.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/Angle.h"
#include "core/Text.h"
#include "draw/SceneDrawing.h"
#include "sim/SceneBuilder.h"

namespace tabletop {
namespace {

// The faces Space visits, going round the entity.
constexpr DirectionDef kFaces[4] = {DirectionDef::Left, DirectionDef::Back, DirectionDef::Right, DirectionDef::Front};
// Entities without faces take these world angles (report 3.8), degrees.
constexpr double kAngles[4] = {0.0, 90.0, 180.0, 270.0};

constexpr double kDefaultStep = 0.2;      // metres
constexpr double kMostAtOnce = 0.25;      // wall seconds of steps per advance()
constexpr double kRateWindow = 0.5;       // wall seconds per real-time factor
constexpr double kSlowest = 1.0 / 64.0, kFastest = 4.0;

bool hasFaces(ShapeKind k) { return k == ShapeKind::Cube || k == ShapeKind::SolidBox; }

}  // namespace

ViewerSession::ViewerSession(Scenario scenario, Settings settings, ViewerSettings viewer)
    : scenario_(std::move(scenario)), settings_(settings), viewer_(std::move(viewer)) {
  noScript_ = scenario_;
  noScript_.script.clear();
  // The arrow starts where the script first pushes, else on the first
  // entity's Left face; G's step is the script's first step.
  step_ = viewer_.step.value_or(kDefaultStep);
  bool found = false;
  for (const Action& a : scenario_.script) {
    if (a.type != Action::Type::Push) continue;
    arrow_ = a.arrow;
    if (!viewer_.step && a.magnitude.kind == PushMagnitude::Kind::Step) step_ = a.magnitude.value;
    found = true;
    break;
  }
  if (!found && !scenario_.entities.empty()) {
    arrow_.entity = scenario_.entities.front().name;
    if (hasFaces(scenario_.entities.front().geometry.kind())) arrow_.face = DirectionDef::Left;
  }
  build(viewer_.playScript);
  // The camera (the command has checked the choice against the scene).
  const auto chosen = CameraChoice::forScene(viewer_.camera, scenario_);
  if (const auto* why = std::get_if<std::string>(&chosen)) throw std::invalid_argument("camera: " + *why);
  const CameraChoice& choice = std::get<CameraChoice>(chosen);
  const std::vector<EntityState> states = simulation_->snapshot();
  camera_ = cameraFor(choice, scenario_, states, SceneExtent::of(scenario_, states), viewer_.aspect);
  if (choice.kind == CameraChoice::Kind::Follow) followed_ = choice.name;
}

void ViewerSession::build(bool playScript) {
  player_.reset();
  simulation_ = buildSimulation(scenario_, settings_, viewer_.mode);
  player_ = std::make_unique<ScriptPlayer>(playScript ? scenario_ : noScript_, settings_, *simulation_);
  player_->runDue();
  pushesSeen_ = player_->pushes();
  budget_ = 0.0;
  if (diverged_) paused_ = false;
  diverged_ = false;
}

void ViewerSession::cycleArrow() {
  const auto& entities = scenario_.entities;
  if (entities.empty()) return;
  std::size_t i = 0;
  while (i < entities.size() && entities[i].name != arrow_.entity) ++i;
  if (i == entities.size()) i = 0;
  // The arrow's place among the entity's four.
  int slot = 0;
  for (int k = 0; k < 4; ++k) {
    if (arrow_.face ? kFaces[k] == *arrow_.face : std::abs(kAngles[k] - arrow_.angleDegrees) < 1e-9) slot = k;
  }
  if (++slot == 4) {
    slot = 0;
    i = (i + 1) % entities.size();
  }
  arrow_ = Arrow{};
  arrow_.entity = entities[i].name;
  if (hasFaces(entities[i].geometry.kind())) {
    arrow_.face = kFaces[slot];
  } else {
    arrow_.angleDegrees = kAngles[slot];
  }
  message_ = "arrow on " + arrowText();
}

void ViewerSession::fitCamera(double aspect) {
  camera_.fit(SceneExtent::of(scenario_, simulation_->snapshot()).corners(), aspect);
  camera_.farPlane = std::max(camera_.farPlane, 4.0 * camera_.distance);
  followed_.clear();
  message_ = "view fitted to the scene";
}

void ViewerSession::toggleFollow() {
  followed_ = followed_.empty() ? arrow_.entity : std::string();
  message_ = followed_.empty() ? "camera stays" : "camera follows " + followed_;
  followCamera();
}

void ViewerSession::followCamera() {
  if (followed_.empty()) return;
  for (const EntityState& s : simulation_->snapshot()) {
    if (s.name == followed_) camera_.target = s.position;
  }
}

void ViewerSession::nextEntity() {
  const auto& entities = scenario_.entities;
  if (entities.empty()) return;
  std::size_t i = 0;
  while (i < entities.size() && entities[i].name != arrow_.entity) ++i;
  i = i == entities.size() ? 0 : (i + 1) % entities.size();
  arrow_ = Arrow{};
  arrow_.entity = entities[i].name;
  if (hasFaces(entities[i].geometry.kind())) arrow_.face = kFaces[0];
  if (!followed_.empty()) followed_ = arrow_.entity, followCamera();
  message_ = "arrow on " + arrowText();
}

bool ViewerSession::pick(double column, double row, int width, int height) {
  const std::vector<EntityState> states = simulation_->snapshot();
  const Vec3 eye = camera_.eye();
  std::size_t best = states.size();
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < states.size() && i < scenario_.entities.size(); ++i) {
    const auto centre = camera_.project(states[i].position, width, height);
    if (!centre) continue;
    // The ball's outline on the image: its radius over its depth, at the
    // focal length in pixels.
    const double focal = 0.5 * height / std::tan(convertAngle(0.5 * camera_.fovyDegrees));
    const double outline = focal * scenario_.entities[i].geometry.boundingRadius() / centre->depth;
    if (std::hypot(centre->column - column, centre->row - row) > outline || centre->depth >= nearest) continue;
    nearest = centre->depth, best = i;
  }
  if (best == states.size()) return false;
  arrow_ = Arrow{};
  arrow_.entity = scenario_.entities[best].name;
  if (hasFaces(scenario_.entities[best].geometry.kind())) {
    // The face whose outward normal, against the push it takes, points
    // most towards the eye.
    const Vec3 toEye = eye - states[best].position;
    double most = -std::numeric_limits<double>::infinity();
    for (DirectionDef face : kFaces) {
      const double towards = -pushDirection(directionAngleDegrees(face) + states[best].yawDegrees).dot(toEye);
      if (towards > most) most = towards, arrow_.face = face;
    }
  }
  if (!followed_.empty()) followed_ = arrow_.entity, followCamera();
  message_ = "arrow on " + arrowText();
  return true;
}

void ViewerSession::pushArrowed() {
  try {
    player_->push(arrow_, PushMagnitude{PushMagnitude::Kind::Step, step_});
    pushesSeen_ = player_->pushes();
    message_ = "pushed " + arrowText() + ", step " + fixed(step_, 3) + " m";
  } catch (const std::invalid_argument& e) {
    message_ = std::string("cannot push: ") + e.what();
  }
}

void ViewerSession::rotate(int sign) {
  const double degrees = sign * viewer_.rotationDegrees;
  if (rotationTarget_ == RotationTarget::TableAndEntities) {
    camera_.orbit(-degrees, 0.0);  // the scene turns one way, so the eye turns the other
    return;
  }
  const std::vector<EntityState> states = simulation_->snapshot();
  int turned = 0;
  try {
    for (const EntityState& s : states) {
      if (s.status != EntityPositionStatus::OnTable) continue;
      simulation_->rotate(s.name, degrees);
      ++turned;
    }
    message_ = "turned " + std::to_string(turned) + " entities on the table by " + fixed(degrees, 0) + " deg";
  } catch (const std::invalid_argument& e) {
    message_ = std::string("cannot turn: ") + e.what();
  }
}

void ViewerSession::reset(bool playScript) {
  build(playScript);
  message_ = playScript ? "reset; playing the script" : "reset";
}

bool ViewerSession::stepOnce() {
  if (diverged_) return false;
  // The viewer paces steps by the clock, so the work limit is each step's.
  player_->restartWorkCount();
  try {
    player_->step();
    return true;
  } catch (const std::runtime_error& e) {  // a DivergenceError, or the work limit's ScenarioError
    diverged_ = paused_ = true;
    budget_ = 0.0;
    message_ = std::string(e.what()) + "; R resets";
    return false;
  }
}

void ViewerSession::singleStep() {
  if (!paused_) return;
  stepOnce();
}

void ViewerSession::setSpeed(double speed) {
  speed_ = std::clamp(speed, kSlowest, kFastest);
  message_ = "speed x" + fixed(speed_, speed_ < 0.1 ? 4 : 2);
}

void ViewerSession::advance(double wallSeconds) {
  wallSeconds = std::max(0.0, wallSeconds);
  const double before = simulation_->time();
  if (!paused_) {
    budget_ += std::min(wallSeconds, kMostAtOnce) * speed_;
    while (budget_ >= settings_.timestep && stepOnce()) budget_ -= settings_.timestep;
  }
  // The arrow follows the script's pushes.
  if (player_->pushes() != pushesSeen_) {
    pushesSeen_ = player_->pushes();
    if (const auto a = player_->arrow()) arrow_ = *a;
  }
  followCamera();
  windowWall_ += wallSeconds;
  windowSim_ += simulation_->time() - before;
  if (windowWall_ >= kRateWindow) {
    realTimeFactor_ = windowSim_ / windowWall_;
    windowWall_ = windowSim_ = 0.0;
  }
}

DrawList ViewerSession::drawList() const {
  DrawOptions options;
  options.arrow = arrowVisible_;
  options.contacts = contacts_;
  return makeDrawList(scenario_, simulation_->snapshot(), arrow_,
                      contacts_ ? simulation_->contactPoints() : std::vector<Vec3>{}, options);
}

std::string ViewerSession::arrowText() const {
  if (arrow_.face) return arrow_.entity + ", " + std::string(toString(*arrow_.face)) + " face";
  return arrow_.entity + ", angle " + fixed(arrow_.angleDegrees, 0) + " deg";
}

std::string ViewerSession::entityLine(const EntityState& s) const {
  return "  " + s.name + "  " + std::string(toString(s.status)) + "  (" + fixed(s.position.x, 3) + ", " +
         fixed(s.position.y, 3) + ", " + fixed(s.position.z, 3) + ") m  on " + s.support.name();
}

std::vector<std::string> ViewerSession::overlay(std::size_t maxLines) const {
  std::vector<std::string> lines;
  if (!overlayShown_) return lines;
  maxLines = std::max<std::size_t>(maxLines, 4);
  lines.push_back(scenario_.name + "   mode " + std::string(simulation_->modeName()) + "   (H: help, I: hide)");
  std::string timing = "t " + fixed(simulation_->time(), 3) + " s   real-time x" + fixed(realTimeFactor_, 2);
  if (speed_ != 1.0) timing += "   speed x" + fixed(speed_, speed_ < 0.1 ? 4 : 2);
  if (paused_) timing += "   PAUSED";
  if (!followed_.empty()) timing += "   following " + followed_;
  lines.push_back(timing);
  lines.push_back("arrow: " + arrowText() + ", step " + fixed(step_, 3) + " m" + (arrowVisible_ ? "" : " (hidden)") +
                  "   +/- turn " +
                  (rotationTarget_ == RotationTarget::TableAndEntities ? "table and entities" : "entities on the table"));
  const std::vector<EntityState> states = simulation_->snapshot();
  const std::size_t room = maxLines - lines.size() - (message_.empty() ? 0 : 1);
  if (entityList_) {
    // Every entity that fits, the last line saying how many do not.
    const std::size_t shown = states.size() <= room ? states.size() : room - 1;
    for (std::size_t i = 0; i < shown; ++i) lines.push_back(entityLine(states[i]));
    if (shown < states.size()) lines.push_back("  ... " + std::to_string(states.size() - shown) + " more (L: fewer)");
  } else {
    for (const EntityState& s : states) {
      if (s.name == arrow_.entity) lines.push_back(entityLine(s));
    }
    lines.push_back("  " + std::to_string(states.size()) + (states.size() == 1 ? " entity" : " entities") +
                    " (L: list them)");
  }
  if (!message_.empty()) lines.push_back("> " + message_);
  return lines;
}

std::vector<std::string> ViewerSession::help() {
  return {
      "Space  move the arrow to the next face / entity",
      "G      push the arrowed entity one step",
      "+ -    turn (see the menu's Set Rotation Entities)",
      "A      arrow on/off          C  contact points",
      "P      pause                 O  one step (paused)",
      "S      slow motion x1/4      [ ]  slower / faster",
      "R      reset                 Enter  reset and play the script",
      "Z X    zoom in / out         F12  screenshot (PNG)",
      "F      fit the scene in view T  follow the arrowed entity",
      "Tab    arrow to the next entity",
      "I      overlay on/off        L  list every entity",
      "mouse  left drag: orbit; middle or Shift+left drag: pan; wheel: zoom",
      "       right button: the report's menu",
      "H      this help             Q Esc  quit (Esc first closes a menu)",
  };
}

}  // namespace tabletop
