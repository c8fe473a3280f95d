#pragma once

#include "draw/Camera.h"
#include "draw/DrawList.h"
#include "image/BodyImage.h"
#include "image/Image.h"
#include "render/GlFunctions.h"

namespace tabletop {

/// Draws a DrawList with fixed-function OpenGL into the current context,
/// the one renderer behind the window and the headless frames: a
/// perspective view with depth test; the floor as tiles; the table top on
/// cylinder legs; each entity in its colour, shaded by ambient light plus
/// one lamp; spheres in darker and lighter gores so their rolling shows;
/// the report's arrow; contact points; and the shadows of the entities and
/// the table on the table top and the floor (planar projection from the
/// lamp, stencilled to each surface so nothing is darkened twice).
///
/// Needs a context with a depth and a stencil buffer. Knows nothing of
/// Bullet or of the modes.
class GlRenderer {
 public:
  explicit GlRenderer(const GlFunctions& gl) : gl_(gl) {}

  /// Draws `list` seen by `camera` into a `width` x `height` viewport.
  void draw(const DrawList& list, const Camera& camera, int width, int height) const;

  /// The viewport's pixels, top row first.
  Image readPixels(int width, int height) const;
  /// Each pixel's body and depth (BodyImage) for `list` seen by `camera`:
  /// the solids drawn again, flat and in label colours (no light, shadow,
  /// arrow or contact points), into the current framebuffer
  /// (GlLabels.cpp).
  BodyImage drawLabels(const DrawList& list, const Camera& camera, int width, int height) const;

 private:
  void setUpLight(const DrawList& list) const;
  void drawFloor(const DrawList& list) const;
  void drawShape(const DrawShape& shape, bool coloured) const;
  void drawArrow(const DrawArrow& arrow, bool coloured) const;
  void drawBox(const Vec3& half) const;
  void drawSphere(double radius, const Colour& colour, bool coloured) const;
  void drawFrustum(double baseRadius, double topRadius, double height) const;
  void drawShadows(const DrawList& list) const;
  void setColour(const Colour& c, double shade = 1.0) const;

  const GlFunctions& gl_;
};

}  // namespace tabletop
