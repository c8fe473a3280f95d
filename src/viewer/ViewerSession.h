#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/Arrow.h"
#include "core/SimulationMode.h"
#include "draw/Camera.h"
#include "draw/CameraChoice.h"
#include "draw/DrawList.h"
#include "scenario/Scenario.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {

/// The report's Set Rotation Entities menu: what + and - turn.
enum class RotationTarget {
  TableAndEntities,  ///< the whole scene turns about the table's centre (the view)
  EntitiesOnTable,   ///< each entity on the table turns about its own centre
};

/// How a viewer starts.
struct ViewerSettings {
  SimulationMode mode = SimulationMode::Bullet;
  bool playScript = true;           ///< play the scenario's script from the start
  std::optional<double> step;       ///< G's step, metres; else the script's first step, else 0.2
  std::string camera = "fit";       ///< a CameraChoice (fit, a preset, follow:NAME, an eye and target)
  double aspect = 4.0 / 3.0;        ///< the window's width over its height, for fitting
  double rotationDegrees = 15.0;    ///< one press of + or -
};

/// Everything the interactive viewer does, without a window: the scene in
/// one mode, its script played against the wall clock, the report's
/// controls (arrow, push, rotation, zoom, reset) and the ones users of
/// physics viewers expect (pause, single step, slow motion, contacts). The
/// window (Viewer) only maps keys, mouse and menus onto it and draws what
/// it says, so all of it is tested headless.
///
/// Pushes from the keyboard go through ScriptPlayer::push, the code the
/// scripted pushes take.
class ViewerSession {
 public:
  /// Throws ScenarioError for a scene the mode refuses, and
  /// std::invalid_argument for a camera the scene cannot have.
  ViewerSession(Scenario scenario, Settings settings, ViewerSettings viewer);
  ViewerSession(const ViewerSession&) = delete;  // the script player holds on to the scenario
  ViewerSession& operator=(const ViewerSession&) = delete;

  // The report's controls.
  /// Space: moves the arrow to the next face of the arrowed entity, and
  /// after its last face to the next entity.
  void cycleArrow();
  /// G, Move entity: pushes the arrowed entity one step.
  void pushArrowed();
  /// + (sign +1) and - (sign -1): turns the view or the entities on the
  /// table, as the rotation target says.
  void rotate(int sign);
  void setArrowVisible(bool visible) { arrowVisible_ = visible; }
  bool arrowVisible() const { return arrowVisible_; }
  void setRotationTarget(RotationTarget target) { rotationTarget_ = target; }
  RotationTarget rotationTarget() const { return rotationTarget_; }
  /// Reset: everything back to its initial place; with `playScript` the
  /// script plays again from time 0.
  void reset(bool playScript);

  // The simulate-style controls.
  /// Pauses or plays; a scene that diverged stays paused until reset.
  void togglePause() { paused_ = !paused_ || diverged_; }
  bool paused() const { return paused_; }
  /// True once a step diverged (see DivergenceGuard): the scene is paused
  /// and the message says where; reset starts it again.
  bool diverged() const { return diverged_; }
  /// One simulation step, when paused.
  void singleStep();
  /// Simulated seconds per wall second (1: real time), within 1/64..4.
  void setSpeed(double speed);
  double speed() const { return speed_; }
  void toggleContacts() { contacts_ = !contacts_; }
  bool contactsShown() const { return contacts_; }
  void showMessage(std::string message) { message_ = std::move(message); }

  /// Lets `wallSeconds` of real time pass: steps the simulation to keep
  /// pace at the chosen speed (never more than a quarter second of steps
  /// at once, so a slow machine falls behind instead of freezing).
  void advance(double wallSeconds);

  // The camera.
  /// F: keeps the view's direction and fits the table and every entity as
  /// they are now into a view of `aspect`.
  void fitCamera(double aspect);
  /// T: the camera's target follows the arrowed entity (or stops following).
  void toggleFollow();
  /// The entity the camera follows, or "" when none.
  const std::string& followed() const { return followed_; }
  /// Tab: the arrow to the next entity (its first face).
  void nextEntity();
  /// A click at pixel (`column`, `row`) of a `width` x `height` view: the
  /// arrow moves to the nearest entity whose outline (its bounding ball as
  /// seen) holds the pixel, on the face turned most towards the eye (a
  /// sphere keeps its angle). False when the click hits no entity.
  bool pick(double column, double row, int width, int height);

  // The overlay.
  /// I: the overlay on or off.
  void toggleOverlay() { overlayShown_ = !overlayShown_; }
  bool overlayShown() const { return overlayShown_; }
  /// L: every entity's line in the overlay, or only the arrowed one's.
  void toggleEntityList() { entityList_ = !entityList_; }

  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  const Scenario& scenario() const { return scenario_; }
  const Simulation& simulation() const { return *simulation_; }
  /// The arrow now: on which entity and face.
  const Arrow& arrow() const { return arrow_; }
  double stepLength() const { return step_; }
  /// Simulated over wall seconds, measured over the last half second.
  double realTimeFactor() const { return realTimeFactor_; }

  /// The frame to draw now.
  DrawList drawList() const;
  /// The overlay's lines, at most `maxLines` (at least 4): scene, time and
  /// speed, the arrow, the arrowed entity's status and the entity count
  /// (every entity's with L, cut to fit with "... N more"), and the last
  /// message. Empty when hidden.
  std::vector<std::string> overlay(std::size_t maxLines) const;
  /// The keys and the mouse, one line each.
  static std::vector<std::string> help();

 private:
  void build(bool playScript);
  /// One step of the player; on divergence, pauses and says why.
  bool stepOnce();
  std::string arrowText() const;
  std::string entityLine(const EntityState& s) const;
  /// Puts the camera's target on the followed entity, if any.
  void followCamera();

  Scenario scenario_;
  Scenario noScript_;  // the scene without its script
  Settings settings_;
  ViewerSettings viewer_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<ScriptPlayer> player_;
  Camera camera_;
  Arrow arrow_;
  int pushesSeen_ = 0;
  double step_ = 0.2;
  bool arrowVisible_ = true;
  RotationTarget rotationTarget_ = RotationTarget::TableAndEntities;
  bool paused_ = false;
  bool diverged_ = false;
  double speed_ = 1.0;
  bool contacts_ = false;
  std::string followed_;
  bool overlayShown_ = true;
  bool entityList_ = false;
  double budget_ = 0.0;  // simulated seconds owed to the wall clock
  double windowWall_ = 0.0, windowSim_ = 0.0;
  double realTimeFactor_ = 0.0;
  std::string message_;
};

}  // namespace tabletop
