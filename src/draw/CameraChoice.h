#pragma once

#include <string>
#include <variant>
#include <vector>

#include "core/EntityState.h"
#include "core/Vec3.h"
#include "draw/Camera.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// What --camera asks for, in `render` and `view` alike.
struct CameraChoice {
  enum class Kind {
    Fit,       ///< "fit" (the default): the report's direction, the whole scene in view
    Preset,    ///< "front", "corner", "side", "top": a fixed view of the table
    Follow,    ///< "follow:NAME": the report's direction, centred on one entity
    EyeTarget  ///< "EX,EY,EZ:TX,TY,TZ": an eye looking at a target, metres
  };
  Kind kind = Kind::Fit;
  std::string name;  ///< Preset: the view; Follow: the entity
  Vec3 eye, target;  ///< EyeTarget

  /// The choice `text` names, or why it names none (one line).
  static std::variant<CameraChoice, std::string> parse(const std::string& text);
  /// One line for --help: every form and the default.
  static std::string help();
  /// parse(), then problemWith(): the choice for `scenario`, or why there
  /// is none (one line).
  static std::variant<CameraChoice, std::string> forScene(const std::string& text, const Scenario& scenario);
  /// Why `scenario` cannot be shown this way (follow names no entity), or "".
  std::string problemWith(const Scenario& scenario) const;
};

/// The box a fitted camera keeps in view: the table and each entity's
/// bounding ball at every moment added (a render adds every frame of its
/// run before drawing the first, so nothing leaves the picture).
class SceneExtent {
 public:
  /// The box of the table and the entities at `states` alone.
  static SceneExtent of(const Scenario& scenario, const std::vector<EntityState>& states);
  void add(const std::vector<Camera::Bound>& bounds);
  bool empty() const { return empty_; }
  /// The box's eight corners, as balls of no radius: a view holding them
  /// holds the box, since the view is convex.
  std::vector<Camera::Bound> corners() const;
  /// The farthest the box reaches from (x, z) across the floor, metres.
  double reachFrom(double x, double z) const;

 private:
  Vec3 low_, high_;
  bool empty_ = true;
};

/// The camera `choice` gives for a frame of `scenario` with its entities
/// at `states`, in a view of `aspect` (width over height). Fit frames
/// `extent`; Follow centres the followed entity with four times its
/// bounding radius in view.
Camera cameraFor(const CameraChoice& choice, const Scenario& scenario, const std::vector<EntityState>& states,
                 const SceneExtent& extent, double aspect);

}  // namespace tabletop
