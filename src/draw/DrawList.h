#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/Colour.h"
#include "core/Vec3.h"

namespace tabletop {

/// A solid the renderer knows how to draw.
enum class Primitive { Box, Sphere, Cylinder };

/// One solid of the scene, in plain numbers: no Bullet type reaches the
/// renderer, and the renderer draws whatever mode produced the poses.
struct DrawShape {
  std::string name;
  Primitive primitive = Primitive::Box;
  /// Box: half extents. Sphere: the radius in x. Cylinder: base radius in
  /// x, top radius in y, height in z; the axis is local +Y.
  Vec3 size;
  Vec3 position;                                    ///< box and sphere: centre; cylinder: centre of mass
  std::array<double, 4> orientation{1, 0, 0, 0};  ///< unit quaternion w, x, y, z
  double baseOffset = 0.0;                         ///< cylinder: base below `position`, metres
  Colour colour;
};

/// The report's force arrow as drawn: a shaft and a head from `tail` to
/// `head`, with the head touching the pushed face.
struct DrawArrow {
  Vec3 tail;
  Vec3 head;
  double radius = 0.008;  ///< of the shaft, metres
  Colour colour{20, 205, 215};  // cyan: no report entity wears it
};

/// A horizontal surface that shows shadows: the table top or the floor.
struct ShadowReceiver {
  double height = 0.0;  ///< y of the surface, metres
  double xMin = 0.0, xMax = 0.0, zMin = 0.0, zMax = 0.0;
};

/// Everything one frame shows, built from a snapshot of any mode
/// (SceneDrawing) and drawn by one renderer (GlRenderer).
struct DrawList {
  std::vector<DrawShape> table;     ///< the top, then the four legs
  std::vector<DrawShape> entities;  ///< in scenario order
  std::optional<DrawArrow> arrow;
  std::vector<Vec3> contacts;       ///< contact points, metres
  ShadowReceiver tableTop;
  ShadowReceiver floor;
  double floorTile = 0.5;  ///< side of a floor tile, metres
  Colour floorColours[2] = {{205, 205, 200}, {175, 175, 170}};
  Colour contactColour{255, 0, 255};
  double contactPixels = 7.0;       ///< a contact point's width in pixels
  Vec3 lamp;  ///< the light's position, metres
};

}  // namespace tabletop
