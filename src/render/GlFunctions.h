#pragma once

#include <GL/gl.h>

#include <functional>
#include <string>

namespace tabletop {

// Every OpenGL function the renderer calls, as X(return type, name without
// "gl", parameter list).
#define TABLETOP_GL_FUNCTIONS(X)                                              \
  X(void, Viewport, (GLint, GLint, GLsizei, GLsizei))                         \
  X(void, ClearColor, (GLclampf, GLclampf, GLclampf, GLclampf))               \
  X(void, ClearStencil, (GLint))                                              \
  X(void, Clear, (GLbitfield))                                                \
  X(void, Enable, (GLenum))                                                   \
  X(void, Disable, (GLenum))                                                  \
  X(void, MatrixMode, (GLenum))                                               \
  X(void, LoadIdentity, ())                                                   \
  X(void, LoadMatrixd, (const GLdouble*))                                     \
  X(void, MultMatrixd, (const GLdouble*))                                     \
  X(void, PushMatrix, ())                                                     \
  X(void, PopMatrix, ())                                                      \
  X(void, Begin, (GLenum))                                                    \
  X(void, End, ())                                                            \
  X(void, Vertex3d, (GLdouble, GLdouble, GLdouble))                           \
  X(void, Normal3d, (GLdouble, GLdouble, GLdouble))                           \
  X(void, Color4ub, (GLubyte, GLubyte, GLubyte, GLubyte))                     \
  X(void, Lightfv, (GLenum, GLenum, const GLfloat*))                          \
  X(void, LightModelfv, (GLenum, const GLfloat*))                             \
  X(void, ColorMaterial, (GLenum, GLenum))                                    \
  X(void, Materialfv, (GLenum, GLenum, const GLfloat*))                       \
  X(void, ShadeModel, (GLenum))                                               \
  X(void, BlendFunc, (GLenum, GLenum))                                        \
  X(void, DepthFunc, (GLenum))                                                \
  X(void, DepthMask, (GLboolean))                                             \
  X(void, ColorMask, (GLboolean, GLboolean, GLboolean, GLboolean))            \
  X(void, StencilFunc, (GLenum, GLint, GLuint))                               \
  X(void, StencilOp, (GLenum, GLenum, GLenum))                                \
  X(void, PolygonOffset, (GLfloat, GLfloat))                                  \
  X(void, PointSize, (GLfloat))                                               \
  X(void, ReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*)) \
  X(void, PixelStorei, (GLenum, GLint))                                       \
  X(void, Finish, ())                                                         \
  X(GLenum, GetError, ())

/// The OpenGL entry points the renderer uses, looked up by name through the
/// context's own loader (OSMesaGetProcAddress, glutGetProcAddress).
///
/// The renderer never calls a GL symbol resolved by the linker: a process
/// that links both libGL (for the window) and libOSMesa (for headless
/// frames) has two definitions of every gl* symbol, and whichever the
/// linker meets first would silently draw into the wrong context (black
/// images). Pointers from the current context's loader always reach it.
struct GlFunctions {
#define TABLETOP_GL_MEMBER(ret, name, params) ret(*name) params = nullptr;
  TABLETOP_GL_FUNCTIONS(TABLETOP_GL_MEMBER)
#undef TABLETOP_GL_MEMBER

  /// Looks every function up with `loader`. Throws std::runtime_error
  /// naming the first one it cannot find.
  static GlFunctions load(const std::function<void*(const char*)>& loader);
};

}  // namespace tabletop
