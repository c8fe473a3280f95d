#pragma once

#include "draw/Camera.h"
#include "draw/DrawList.h"
#include "headless/OsMesaContext.h"
#include "image/Image.h"
#include "render/GlRenderer.h"

namespace tabletop {

/// Frames of one size drawn without a display, anti-aliased: each is drawn
/// kSupersample times larger on each side (when that stays within
/// kMostDrawnPixels) and averaged down. What `render` and the Python
/// module's render() both draw with.
class HeadlessFrames {
 public:
  static constexpr int kSupersample = 2;
  static constexpr double kMostDrawnPixels = 4096.0 * 4096.0;

  /// Throws std::runtime_error when OSMesa cannot make the context.
  HeadlessFrames(int width, int height);
  /// `list` seen by `camera`, width x height pixels, top row first, on
  /// the calling thread (one thread at a time).
  Image draw(DrawList list, const Camera& camera) const;
  /// Each pixel's body and depth for the same frame (GlRenderer::drawLabels),
  /// drawn at the frame's own size in a corner of the larger one: a label
  /// is no average, so each pixel shows what its centre's ray meets.
  BodyImage drawBodies(const DrawList& list, const Camera& camera) const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_, scale_;
  OsMesaContext context_;
  GlRenderer renderer_;
};

}  // namespace tabletop
