#include "render/GlRenderer.h"

#include <algorithm>
#include <cmath>

#include "core/Angle.h"

namespace tabletop {
namespace {

// Tessellation: fine enough that silhouettes look round at 1080p.
constexpr int kSlices = 32;
constexpr int kStacks = 16;
// Spheres alternate light and dark gores this many slices wide.
constexpr int kGoreSlices = 4;
constexpr double kDarkGore = 0.72;

// Stencil values marking the surfaces that receive shadows.
constexpr int kFloorStencil = 1;
constexpr int kTableTopStencil = 2;

// How dark a shadow is: the fraction of light it takes away.
constexpr unsigned char kShadowAlpha = 105;

// The background, a pale sky.
constexpr float kSky[3] = {0.80f, 0.86f, 0.93f};

// Projects onto the plane y = h from the point light `lamp` (the classic
// planar shadow matrix: (plane . light) I - light plane^T).
Mat4 shadowMatrix(double h, const Vec3& lamp) {
  const double plane[4] = {0, 1, 0, -h};
  const double light[4] = {lamp.x, lamp.y, lamp.z, 1};
  const double dot = lamp.y - h;
  Mat4 m;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) m.at(i, j) = (i == j ? dot : 0.0) - light[i] * plane[j];
  }
  return m;
}

Colour shaded(const Colour& c, double s) {
  return {static_cast<int>(c.r * s), static_cast<int>(c.g * s), static_cast<int>(c.b * s)};
}

}  // namespace

void GlRenderer::setColour(const Colour& c, double shade) const {
  const Colour s = shaded(c, shade);
  const auto clamp = [](int v) { return static_cast<GLubyte>(std::clamp(v, 0, 255)); };
  gl_.Color4ub(clamp(s.r), clamp(s.g), clamp(s.b), 255);
}

void GlRenderer::draw(const DrawList& list, const Camera& camera, int width, int height) const {
  gl_.Viewport(0, 0, width, height);
  gl_.ClearColor(kSky[0], kSky[1], kSky[2], 1.0f);
  gl_.ClearStencil(0);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  gl_.MatrixMode(GL_PROJECTION);
  gl_.LoadMatrixd(camera.projection(double(width) / std::max(height, 1)).m.data());
  gl_.MatrixMode(GL_MODELVIEW);
  gl_.LoadMatrixd(camera.view().m.data());

  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.Disable(GL_CULL_FACE);
  gl_.Enable(GL_NORMALIZE);
  gl_.ShadeModel(GL_SMOOTH);
  setUpLight(list);

  // The floor marks its pixels for the floor's shadows.
  gl_.Enable(GL_STENCIL_TEST);
  gl_.StencilFunc(GL_ALWAYS, kFloorStencil, 0xff);
  gl_.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  drawFloor(list);
  gl_.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);

  for (const DrawShape& part : list.table) drawShape(part, true);
  // The table top's upper face, drawn again into the stencil only: its
  // pixels (and not the top's sides) receive the shadows on the table.
  if (!list.table.empty()) {
    const DrawShape& top = list.table.front();
    gl_.DepthFunc(GL_LEQUAL);
    gl_.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl_.StencilFunc(GL_ALWAYS, kTableTopStencil, 0xff);
    gl_.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl_.PushMatrix();
    gl_.MultMatrixd(Mat4::pose(top.position, top.orientation).m.data());
    gl_.Begin(GL_QUADS);
    gl_.Normal3d(0, 1, 0);
    gl_.Vertex3d(-top.size.x, top.size.y, -top.size.z);
    gl_.Vertex3d(-top.size.x, top.size.y, top.size.z);
    gl_.Vertex3d(top.size.x, top.size.y, top.size.z);
    gl_.Vertex3d(top.size.x, top.size.y, -top.size.z);
    gl_.End();
    gl_.PopMatrix();
    gl_.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.DepthFunc(GL_LESS);
  }

  for (const DrawShape& e : list.entities) drawShape(e, true);
  if (list.arrow) drawArrow(*list.arrow, true);
  drawShadows(list);
  gl_.Disable(GL_STENCIL_TEST);

  if (!list.contacts.empty()) {
    // Contact points show through everything, as in the physics debuggers.
    gl_.Disable(GL_LIGHTING);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.PointSize(static_cast<GLfloat>(list.contactPixels));
    setColour(list.contactColour);
    gl_.Begin(GL_POINTS);
    for (const Vec3& p : list.contacts) gl_.Vertex3d(p.x, p.y, p.z);
    gl_.End();
    gl_.Enable(GL_DEPTH_TEST);
  }
  gl_.Finish();
}

void GlRenderer::setUpLight(const DrawList& list) const {
  const GLfloat position[4] = {float(list.lamp.x), float(list.lamp.y), float(list.lamp.z), 1.0f};
  const GLfloat ambient[4] = {0.30f, 0.30f, 0.30f, 1.0f};
  const GLfloat diffuse[4] = {0.75f, 0.75f, 0.72f, 1.0f};
  const GLfloat none[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  const GLfloat sceneAmbient[4] = {0.12f, 0.12f, 0.12f, 1.0f};
  gl_.Enable(GL_LIGHTING);
  gl_.Enable(GL_LIGHT0);
  gl_.Lightfv(GL_LIGHT0, GL_POSITION, position);  // in world space: the view matrix is loaded
  gl_.Lightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  gl_.Lightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  gl_.Lightfv(GL_LIGHT0, GL_SPECULAR, none);
  gl_.LightModelfv(GL_LIGHT_MODEL_AMBIENT, sceneAmbient);
  gl_.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, none);
  gl_.Enable(GL_COLOR_MATERIAL);
  gl_.ColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
}

void GlRenderer::drawFloor(const DrawList& list) const {
  const ShadowReceiver& f = list.floor;
  const double tile = list.floorTile;
  const int nx = std::max(1, static_cast<int>(std::ceil((f.xMax - f.xMin) / tile)));
  const int nz = std::max(1, static_cast<int>(std::ceil((f.zMax - f.zMin) / tile)));
  gl_.Begin(GL_QUADS);
  gl_.Normal3d(0, 1, 0);
  for (int i = 0; i < nx; ++i) {
    for (int k = 0; k < nz; ++k) {
      setColour(list.floorColours[(i + k) % 2]);
      const double x0 = f.xMin + i * tile, x1 = std::min(f.xMax, x0 + tile);
      const double z0 = f.zMin + k * tile, z1 = std::min(f.zMax, z0 + tile);
      gl_.Vertex3d(x0, f.height, z0);
      gl_.Vertex3d(x0, f.height, z1);
      gl_.Vertex3d(x1, f.height, z1);
      gl_.Vertex3d(x1, f.height, z0);
    }
  }
  gl_.End();
}

void GlRenderer::drawShape(const DrawShape& s, bool coloured) const {
  gl_.PushMatrix();
  gl_.MultMatrixd(Mat4::pose(s.position, s.orientation).m.data());
  if (coloured && s.primitive != Primitive::Sphere) setColour(s.colour);
  switch (s.primitive) {
    case Primitive::Box: drawBox(s.size); break;
    case Primitive::Sphere: drawSphere(s.size.x, s.colour, coloured); break;
    case Primitive::Cylinder:
      gl_.MultMatrixd(Mat4::translation({0, -s.baseOffset, 0}).m.data());
      drawFrustum(s.size.x, s.size.y, s.size.z);
      break;
  }
  gl_.PopMatrix();
}

void GlRenderer::drawBox(const Vec3& h) const {
  // Each face: its outward normal and its corners, counter-clockwise.
  struct Face {
    Vec3 normal, corner[4];
  };
  const Face faces[6] = {
      {{1, 0, 0}, {{h.x, -h.y, -h.z}, {h.x, h.y, -h.z}, {h.x, h.y, h.z}, {h.x, -h.y, h.z}}},
      {{-1, 0, 0}, {{-h.x, -h.y, -h.z}, {-h.x, -h.y, h.z}, {-h.x, h.y, h.z}, {-h.x, h.y, -h.z}}},
      {{0, 1, 0}, {{-h.x, h.y, -h.z}, {-h.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, -h.z}}},
      {{0, -1, 0}, {{-h.x, -h.y, -h.z}, {h.x, -h.y, -h.z}, {h.x, -h.y, h.z}, {-h.x, -h.y, h.z}}},
      {{0, 0, 1}, {{-h.x, -h.y, h.z}, {h.x, -h.y, h.z}, {h.x, h.y, h.z}, {-h.x, h.y, h.z}}},
      {{0, 0, -1}, {{-h.x, -h.y, -h.z}, {-h.x, h.y, -h.z}, {h.x, h.y, -h.z}, {h.x, -h.y, -h.z}}},
  };
  gl_.Begin(GL_QUADS);
  for (const Face& f : faces) {
    gl_.Normal3d(f.normal.x, f.normal.y, f.normal.z);
    for (const Vec3& c : f.corner) gl_.Vertex3d(c.x, c.y, c.z);
  }
  gl_.End();
}

void GlRenderer::drawSphere(double radius, const Colour& colour, bool coloured) const {
  gl_.Begin(GL_QUADS);
  for (int slice = 0; slice < kSlices; ++slice) {
    if (coloured) setColour(colour, (slice / kGoreSlices) % 2 ? kDarkGore : 1.0);
    const double a0 = 2.0 * kPi * slice / kSlices, a1 = 2.0 * kPi * (slice + 1) / kSlices;
    for (int stack = 0; stack < kStacks; ++stack) {
      const double p0 = kPi * stack / kStacks - 0.5 * kPi, p1 = kPi * (stack + 1) / kStacks - 0.5 * kPi;
      const double corners[4][2] = {{a0, p0}, {a1, p0}, {a1, p1}, {a0, p1}};
      for (const auto& c : corners) {
        const Vec3 n{std::cos(c[1]) * std::cos(c[0]), std::sin(c[1]), -std::cos(c[1]) * std::sin(c[0])};
        gl_.Normal3d(n.x, n.y, n.z);
        gl_.Vertex3d(radius * n.x, radius * n.y, radius * n.z);
      }
    }
  }
  gl_.End();
}

void GlRenderer::drawFrustum(double r0, double r1, double h) const {
  // The side's normal leans by the slope of the profile.
  const double slope = (r0 - r1) / h;
  const double ny = slope / std::sqrt(1.0 + slope * slope), nr = 1.0 / std::sqrt(1.0 + slope * slope);
  gl_.Begin(GL_QUADS);
  for (int slice = 0; slice < kSlices; ++slice) {
    const double a0 = 2.0 * kPi * slice / kSlices, a1 = 2.0 * kPi * (slice + 1) / kSlices;
    const double c0 = std::cos(a0), s0 = std::sin(a0), c1 = std::cos(a1), s1 = std::sin(a1);
    gl_.Normal3d(nr * c0, ny, -nr * s0);
    gl_.Vertex3d(r0 * c0, 0, -r0 * s0);
    gl_.Normal3d(nr * c1, ny, -nr * s1);
    gl_.Vertex3d(r0 * c1, 0, -r0 * s1);
    gl_.Vertex3d(r1 * c1, h, -r1 * s1);
    gl_.Normal3d(nr * c0, ny, -nr * s0);
    gl_.Vertex3d(r1 * c0, h, -r1 * s0);
  }
  gl_.End();
  for (int cap = 0; cap < 2; ++cap) {
    const double r = cap ? r1 : r0, y = cap ? h : 0.0;
    if (r <= 0.0) continue;
    gl_.Begin(GL_TRIANGLE_FAN);
    gl_.Normal3d(0, cap ? 1 : -1, 0);
    gl_.Vertex3d(0, y, 0);
    for (int slice = 0; slice <= kSlices; ++slice) {
      const double a = 2.0 * kPi * slice / kSlices;
      gl_.Vertex3d(r * std::cos(a), y, -r * std::sin(a));
    }
    gl_.End();
  }
}

void GlRenderer::drawArrow(const DrawArrow& a, bool coloured) const {
  const Vec3 along = a.head - a.tail;
  const double length = along.length();
  if (length <= 0.0) return;
  const double headLength = std::min(0.35 * length, 6.0 * a.radius);
  gl_.PushMatrix();
  gl_.MultMatrixd(Mat4::alongAxis(a.tail, along * (1.0 / length)).m.data());
  if (coloured) setColour(a.colour);
  drawFrustum(a.radius, a.radius, length - headLength);
  gl_.MultMatrixd(Mat4::translation({0, length - headLength, 0}).m.data());
  drawFrustum(2.5 * a.radius, 0.0, headLength);
  gl_.PopMatrix();
}

void GlRenderer::drawShadows(const DrawList& list) const {
  gl_.Disable(GL_LIGHTING);
  gl_.Enable(GL_BLEND);
  gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl_.DepthMask(GL_FALSE);
  gl_.Enable(GL_POLYGON_OFFSET_FILL);
  gl_.PolygonOffset(-1.0f, -2.0f);
  gl_.Color4ub(0, 0, 0, kShadowAlpha);
  // Each pixel is darkened once: its stencil moves on from the value drawn.
  gl_.StencilOp(GL_KEEP, GL_KEEP, GL_INCR);

  // On the table top: what is above it. The table top's pass comes first,
  // as the floor's pass leaves the value the table top's pass looks for.
  gl_.StencilFunc(GL_EQUAL, kTableTopStencil, 0xff);
  gl_.PushMatrix();
  gl_.MultMatrixd(shadowMatrix(list.tableTop.height, list.lamp).m.data());
  for (const DrawShape& e : list.entities) {
    if (e.position.y > list.tableTop.height) drawShape(e, false);
  }
  if (list.arrow && list.arrow->head.y > list.tableTop.height) drawArrow(*list.arrow, false);
  gl_.PopMatrix();

  // On the floor: the table and every entity.
  gl_.StencilFunc(GL_EQUAL, kFloorStencil, 0xff);
  gl_.PushMatrix();
  gl_.MultMatrixd(shadowMatrix(list.floor.height, list.lamp).m.data());
  for (const DrawShape& part : list.table) drawShape(part, false);
  for (const DrawShape& e : list.entities) drawShape(e, false);
  gl_.PopMatrix();

  gl_.Disable(GL_POLYGON_OFFSET_FILL);
  gl_.DepthMask(GL_TRUE);
  gl_.Disable(GL_BLEND);
  gl_.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gl_.Enable(GL_LIGHTING);
}

// Read as RGBA, the framebuffer's own layout (Mesa converts to RGB pixel
// by pixel, slower than the copy here), rows flipped on the way: OpenGL's
// first row is the bottom one.
Image GlRenderer::readPixels(int width, int height) const {
  Image image(width, height);
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  for (int row = 0; row < height; ++row) {
    const std::uint8_t* from = &rgba[static_cast<std::size_t>(height - 1 - row) * width * 4];
    std::uint8_t* to = &image.rgb[static_cast<std::size_t>(row) * width * 3];
    for (int c = 0; c < width; ++c) {
      to[3 * c] = from[4 * c];
      to[3 * c + 1] = from[4 * c + 1];
      to[3 * c + 2] = from[4 * c + 2];
    }
  }
  return image;
}

}  // namespace tabletop
