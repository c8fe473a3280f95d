#include "render/GlFunctions.h"

#include <stdexcept>

namespace tabletop {

GlFunctions GlFunctions::load(const std::function<void*(const char*)>& loader) {
  GlFunctions f;
#define TABLETOP_GL_LOAD(ret, name, params)                                         \
  f.name = reinterpret_cast<ret(*) params>(loader("gl" #name));                     \
  if (!f.name) throw std::runtime_error("OpenGL function gl" #name " is not available");
  TABLETOP_GL_FUNCTIONS(TABLETOP_GL_LOAD)
#undef TABLETOP_GL_LOAD
  return f;
}

}  // namespace tabletop
