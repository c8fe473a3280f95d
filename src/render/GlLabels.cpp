#include <cmath>
#include <limits>

#include "render/GlRenderer.h"

// The label pass (GlRenderer::drawLabels): the solids drawn flat, each in
// a colour that is its label, and the depth buffer read back as metres.
namespace tabletop {
namespace {

// A label as a colour: label + 4 in 24 bits (kGround, the lowest, is 1; 0
// is the cleared sky), so any scene's 10,000 entities fit.
Colour labelColour(std::int32_t label) {
  const auto v = static_cast<std::uint32_t>(label - BodyImage::kGround + 1);
  return {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
}

}  // namespace

BodyImage GlRenderer::drawLabels(const DrawList& list, const Camera& camera, int width, int height) const {
  gl_.Viewport(0, 0, width, height);
  gl_.ClearColor(0, 0, 0, 1);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl_.MatrixMode(GL_PROJECTION);
  const double aspect = double(width) / std::max(height, 1);
  gl_.LoadMatrixd(camera.projection(aspect).m.data());
  gl_.MatrixMode(GL_MODELVIEW);
  gl_.LoadMatrixd(camera.view().m.data());
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.DepthMask(GL_TRUE);
  gl_.Disable(GL_LIGHTING);
  gl_.Disable(GL_BLEND);
  gl_.Disable(GL_DITHER);
  gl_.Disable(GL_STENCIL_TEST);
  gl_.ShadeModel(GL_FLAT);

  const ShadowReceiver& f = list.floor;
  setColour(labelColour(BodyImage::kGround));
  gl_.Begin(GL_QUADS);
  gl_.Vertex3d(f.xMin, f.height, f.zMin);
  gl_.Vertex3d(f.xMin, f.height, f.zMax);
  gl_.Vertex3d(f.xMax, f.height, f.zMax);
  gl_.Vertex3d(f.xMax, f.height, f.zMin);
  gl_.End();
  setColour(labelColour(BodyImage::kTable));
  for (const DrawShape& part : list.table) drawShape(part, false);
  for (std::size_t i = 0; i < list.entities.size(); ++i) {
    setColour(labelColour(static_cast<std::int32_t>(i)));
    drawShape(list.entities[i], false);
  }
  gl_.Finish();

  BodyImage out(width, height);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  gl_.ReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, out.depth.data());
  // Window depth w in [0, 1] back to the distance along the view axis:
  // z = 2 n f / (f + n - (2 w - 1) (f - n)); w = 1 is the cleared far plane.
  const double n = camera.nearPlane, fa = camera.farPlane;
  std::vector<float> depth(out.depth.size());
  for (int row = 0; row < height; ++row) {
    const std::size_t from = static_cast<std::size_t>(height - 1 - row) * width;  // bottom row first
    const std::size_t to = static_cast<std::size_t>(row) * width;
    for (int c = 0; c < width; ++c) {
      const std::uint8_t* p = &rgb[(from + c) * 3];
      const std::uint32_t v = (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
      out.labels[to + c] = v == 0 ? BodyImage::kNothing : static_cast<std::int32_t>(v) + BodyImage::kGround - 1;
      const double w = out.depth[from + c];
      depth[to + c] = w >= 1.0 ? std::numeric_limits<float>::infinity()
                               : static_cast<float>(2.0 * n * fa / (fa + n - (2.0 * w - 1.0) * (fa - n)));
    }
  }
  out.depth = std::move(depth);
  return out;
}

}  // namespace tabletop
