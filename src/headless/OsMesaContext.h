#pragma once

#include <memory>
#include <vector>

#include "image/Image.h"
#include "render/GlFunctions.h"

namespace tabletop {

/// An OpenGL context without a display (Mesa's OSMesa, software rendered):
/// a width x height RGBA colour buffer with a 24-bit depth and an 8-bit
/// stencil buffer, current while this object lives. Its GL functions come
/// from OSMesaGetProcAddress, so they reach this context however the
/// executable was linked (see GlFunctions).
class OsMesaContext {
 public:
  /// Throws std::runtime_error when OSMesa cannot make the context.
  OsMesaContext(int width, int height);
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  const GlFunctions& gl() const { return gl_; }

 private:
  struct Handle;
  int width_;
  int height_;
  std::vector<unsigned char> buffer_;  // RGBA, bottom row first
  std::unique_ptr<Handle> handle_;
  GlFunctions gl_;
};

}  // namespace tabletop
