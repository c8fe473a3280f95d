#pragma once

#include <memory>
#include <vector>

#include "image/Image.h"
#include "render/GlFunctions.h"

namespace tabletop {

/// An OpenGL context without a display (Mesa's OSMesa, software rendered):
/// a width x height RGBA colour buffer with a 24-bit depth and an 8-bit
/// stencil buffer. It is current on the thread that made it until that
/// thread calls release(); makeCurrent() takes it on another thread, so one
/// context serves many frames from any thread, one at a time. Its GL functions come
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
  /// Makes the context current on the calling thread. Throws
  /// std::runtime_error if OSMesa cannot.
  void makeCurrent() const;
  /// Leaves the calling thread with no current context.
  void release() const;

 private:
  struct Handle;
  int width_;
  int height_;
  std::vector<unsigned char> buffer_;  // RGBA, bottom row first
  std::unique_ptr<Handle> handle_;
  GlFunctions gl_;
};

}  // namespace tabletop
