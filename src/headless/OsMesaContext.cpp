#include "headless/OsMesaContext.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace tabletop {
namespace {

// The OSMesa functions used, looked up in the library opened below.
struct OsMesa {
  void* library = nullptr;
  decltype(&::OSMesaCreateContextExt) createContextExt = nullptr;
  decltype(&::OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&::OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&::OSMesaGetProcAddress) getProcAddress = nullptr;
};

template <typename F>
void find(void* library, const char* name, F& f) {
  f = reinterpret_cast<F>(dlsym(library, name));
  if (!f) throw std::runtime_error(std::string(TABLETOP_OSMESA_LIBRARY " has no ") + name);
}

// OSMesa is opened with RTLD_LOCAL instead of being linked: its gl*
// symbols then never join the process's global ones, where they would
// compete with libGL's (the window's). Linked, whichever library the
// dynamic linker met first would win every gl* call, and calls meant for
// one context would silently go to the other (black images, or a black
// window). The renderer reaches OSMesa's context only through
// OSMesaGetProcAddress.
OsMesa openOsMesa() {
  OsMesa m;
  m.library = dlopen(TABLETOP_OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  if (!m.library) {
    throw std::runtime_error(std::string("cannot load OSMesa (" TABLETOP_OSMESA_LIBRARY "): ") + dlerror() +
                             "; install libosmesa6");
  }
  find(m.library, "OSMesaCreateContextExt", m.createContextExt);
  find(m.library, "OSMesaMakeCurrent", m.makeCurrent);
  find(m.library, "OSMesaDestroyContext", m.destroyContext);
  find(m.library, "OSMesaGetProcAddress", m.getProcAddress);
  return m;
}

}  // namespace

struct OsMesaContext::Handle {
  OsMesa osmesa;
  OSMesaContext context = nullptr;
};

OsMesaContext::OsMesaContext(int width, int height)
    : width_(width), height_(height), handle_(std::make_unique<Handle>()) {
  constexpr int kMaxSide = 8192;  // OSMesa's limit on either side
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide) {
    throw std::runtime_error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is out of range 1.." + std::to_string(kMaxSide));
  }
  buffer_.resize(static_cast<std::size_t>(width) * height * 4);
  handle_->osmesa = openOsMesa();
  const OsMesa& m = handle_->osmesa;
  handle_->context = m.createContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!handle_->context) throw std::runtime_error("OSMesa cannot create an offscreen OpenGL context");
  if (!m.makeCurrent(handle_->context, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    m.destroyContext(handle_->context);
    handle_->context = nullptr;
    throw std::runtime_error("OSMesa cannot make its offscreen context current");
  }
  const auto getProcAddress = m.getProcAddress;  // the context is current: the functions are its
  gl_ = GlFunctions::load([getProcAddress](const char* name) { return reinterpret_cast<void*>(getProcAddress(name)); });
}

void OsMesaContext::makeCurrent() const {
  // OSMesa writes into buffer_, which this object owns and never resizes.
  auto* pixels = const_cast<unsigned char*>(buffer_.data());
  if (!handle_->osmesa.makeCurrent(handle_->context, pixels, GL_UNSIGNED_BYTE, width_, height_)) {
    throw std::runtime_error("OSMesa cannot make its offscreen context current");
  }
}

void OsMesaContext::release() const { handle_->osmesa.makeCurrent(nullptr, nullptr, 0, 0, 0); }

OsMesaContext::~OsMesaContext() {
  // The library stays loaded: Mesa keeps per-thread state that a dlclose
  // would leave dangling.
  if (handle_->context) handle_->osmesa.destroyContext(handle_->context);
}

}  // namespace tabletop
