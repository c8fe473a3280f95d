#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/TableSpec.h"
#include "core/Vec3.h"
#include "draw/Mat4.h"

namespace tabletop {

/// Where a point lands in an image: column and row in pixels from the top
/// left corner, and its depth along the view (metres in front of the eye).
struct PixelPoint {
  double column = 0.0;
  double row = 0.0;
  double depth = 0.0;
};

/// A perspective camera orbiting a target point, as the report's viewer
/// and the renderer use it. Yaw 0 looks from +Z (the table's front) towards
/// -Z; positive pitch looks down from above.
struct Camera {
  Vec3 target{0.0, 0.6, 0.0};
  double yawDegrees = 0.0;
  double pitchDegrees = 25.0;
  double distance = 2.6;      ///< eye to target, metres
  double fovyDegrees = 40.0;  ///< vertical field of view
  double nearPlane = 0.05;    ///< metres
  double farPlane = 60.0;

  Vec3 eye() const;
  Mat4 view() const;
  Mat4 projection(double aspect) const;
  /// Where the world point `p` appears in a `width` x `height` image; empty
  /// when it is behind the eye.
  std::optional<PixelPoint> project(const Vec3& p, int width, int height) const;

  /// Zooms by `factor` (< 1 moves closer), within sensible limits.
  void zoom(double factor);
  /// Orbits by the given angles in degrees; pitch stays within +-89.
  void orbit(double yawDegrees, double pitchDegrees);
  /// Moves the target across the view by a fraction of the view's height.
  void pan(double right, double up);

  /// A ball of the scene to keep in view: centre and radius, metres.
  struct Bound {
    Vec3 centre;
    double radius = 0.0;
  };
  /// Keeps the direction and field of view, and sets the target and the
  /// distance so that every bound is wholly in a view of `aspect` (width
  /// over height), with `margin` (a fraction of the view) to spare.
  void fit(const std::vector<Bound>& bounds, double aspect, double margin = 0.05);

  /// The names `named` accepts, in the order --help lists them.
  static std::vector<std::string> names();
  /// A view framing `table`: "front" (the report's view), "corner",
  /// "side" or "top". Empty for an unknown name.
  static std::optional<Camera> named(const std::string& name, const TableSpec& table);
};

}  // namespace tabletop
