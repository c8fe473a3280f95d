#include "headless/HeadlessFrames.h"

namespace tabletop {

HeadlessFrames::HeadlessFrames(int width, int height)
    : width_(width),
      height_(height),
      scale_(double(width) * height * kSupersample * kSupersample <= kMostDrawnPixels ? kSupersample : 1),
      context_(width * scale_, height * scale_),
      renderer_(context_.gl()) {}

Image HeadlessFrames::draw(DrawList list, const Camera& camera) const {
  list.contactPixels *= scale_;  // points keep their size in the frame
  renderer_.draw(list, camera, context_.width(), context_.height());
  return renderer_.readPixels(context_.width(), context_.height()).shrunk(scale_);
}

}  // namespace tabletop
