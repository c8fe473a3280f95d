#include "headless/HeadlessFrames.h"

namespace tabletop {

HeadlessFrames::HeadlessFrames(int width, int height)
    : width_(width),
      height_(height),
      scale_(double(width) * height * kSupersample * kSupersample <= kMostDrawnPixels ? kSupersample : 1),
      context_(width * scale_, height * scale_),
      renderer_(context_.gl()) {}

// The context is taken for the frame and let go after it, so frames of one
// HeadlessFrames may be drawn from any thread, one at a time.
Image HeadlessFrames::draw(DrawList list, const Camera& camera) const {
  list.contactPixels *= scale_;  // points keep their size in the frame
  context_.makeCurrent();
  struct Release {
    const OsMesaContext& context;
    ~Release() { context.release(); }
  } release{context_};
  renderer_.draw(list, camera, context_.width(), context_.height());
  return renderer_.readPixels(context_.width(), context_.height()).shrunk(scale_);
}

BodyImage HeadlessFrames::drawBodies(const DrawList& list, const Camera& camera) const {
  context_.makeCurrent();
  struct Release {
    const OsMesaContext& context;
    ~Release() { context.release(); }
  } release{context_};
  return renderer_.drawLabels(list, camera, width_, height_);
}

}  // namespace tabletop
