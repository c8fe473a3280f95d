#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/Arrow.h"
#include "core/Colour.h"
#include "core/Material.h"
#include "core/Quat.h"
#include "core/Settings.h"
#include "core/ShapeGeometry.h"
#include "core/ShapeKind.h"
#include "core/TableSpec.h"
#include "core/Support.h"
#include "core/Vec3.h"

namespace tabletop {

class JsonLocator;

/// One entity as a scenario file describes it (sizes in metres, see
/// ShapeGeometry).
struct EntitySpec {
  std::string name;
  ShapeGeometry geometry = ShapeGeometry::cube(0.1);  ///< its kind and size
  Vec3 position;           ///< centre; y is filled in when `on` is set
  Support on;              ///< what it rests on at the start; none when the position gives a height
  double yawDegrees = 0.0;
  /// A full orientation (body to world), when it turns about more than +Y;
  /// an orientation about +Y alone is given as yawDegrees.
  std::optional<Quat> orientation;
  Colour colour;
  double mass = 1.0;       ///< kg
  Material material;
  Vec3 velocity;           ///< m/s at the start, world frame (full physics only)
  Vec3 spin;               ///< angular velocity at the start, rad/s, world frame (full physics only)
  std::string path;        ///< JSON pointer of this entity in its file
};

/// One step of a scenario's script.
struct Action {
  enum class Type { Push, Rotate, WaitRest, WaitTime };
  Type type = Type::Push;
  std::optional<double> at;  ///< absolute start time, seconds
  Arrow arrow;               ///< Push
  PushMagnitude magnitude;   ///< Push
  std::string entity;        ///< Rotate
  double degrees = 0.0;      ///< Rotate
  double seconds = 0.0;      ///< WaitTime: how long; WaitRest: the timeout (0: none)
  std::string path;          ///< JSON pointer of this action in its file
};

/// A scene and its script, as read from a scenario file (see
/// scenarios/README.md for the format).
struct Scenario {
  int version = 1;
  std::string name;
  std::string description;
  std::string file;  ///< where it was read from
  /// Where each value stands in that file, so that a problem found after
  /// loading (at run time) is located too; null for a scene built in code.
  std::shared_ptr<const JsonLocator> locator;
  /// The text it was read from (the Python module pickles a scene by it);
  /// null for a scene built in code.
  std::shared_ptr<const std::string> text;
  TableSpec table;
  Material ground = kNeutralMaterial;  ///< the floor's material
  std::vector<EntitySpec> entities;
  Settings settings;
  std::vector<Action> script;
};

}  // namespace tabletop
