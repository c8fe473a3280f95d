#include "scenes/RandomScene.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace tabletop {
namespace {

// Uniform numbers from the generator's raw 64-bit words, the same on every
// standard library.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * unit;
  }
  /// Log-uniform in [lo, hi): every factor of ten equally likely.
  double logUniform(double lo, double hi) { return lo * std::pow(hi / lo, uniform(0.0, 1.0)); }
  /// An integer in [lo, hi].
  int integer(int lo, int hi) { return lo + static_cast<int>(engine_() % static_cast<std::uint64_t>(hi - lo + 1)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

 private:
  std::mt19937_64 engine_;
};

// Half the largest horizontal extent of a body of this shape and size:
// the radius of a circle around its centre that holds its footprint at
// any yaw, m.
double footprintRadius(const ShapeGeometry& g) {
  const std::vector<double> size = g.sizes();
  switch (g.kind()) {
    case ShapeKind::Cube: return size[0] * std::sqrt(0.5);
    case ShapeKind::Sphere: return size[0];
    case ShapeKind::SolidBox: return 0.5 * std::hypot(size[0], size[2]);
    case ShapeKind::Cylinder: return std::max(size[0], size[1]);
  }
  return 0.0;
}

EntitySpec randomBody(Draw& draw) {
  EntitySpec e;
  const auto kind = static_cast<ShapeKind>(draw.integer(0, 3));
  // The sizes are drawn in order (a braced list evaluates left to right;
  // a function's arguments need not).
  std::vector<double> sizes;
  switch (kind) {
    case ShapeKind::Cube: sizes = {draw.uniform(0.02, 0.2)}; break;
    case ShapeKind::Sphere: sizes = {draw.uniform(0.01, 0.1)}; break;
    case ShapeKind::SolidBox: sizes = {draw.uniform(0.02, 0.2), draw.uniform(0.02, 0.2), draw.uniform(0.02, 0.2)}; break;
    case ShapeKind::Cylinder:
      sizes = {draw.uniform(0.01, 0.1), draw.uniform(0.01, 0.1), draw.uniform(0.02, 0.2)};
      break;
  }
  e.geometry = ShapeGeometry::fromSizes(kind, sizes).value();
  e.mass = draw.logUniform(0.05, 5.0);
  e.material.friction = draw.uniform(0.0, 1.0);
  e.material.restitution = draw.uniform(0.0, 0.9);
  e.yawDegrees = draw.uniform(0.0, 360.0);
  e.colour = Colour{draw.integer(40, 230), draw.integer(40, 230), draw.integer(40, 230)};
  return e;
}

bool flatTopped(ShapeKind shape) { return shape != ShapeKind::Sphere; }

// Where the bodies drawn so far stand: each one's footprint circle and the
// body standing on the table at the bottom of its column.
struct Layout {
  std::vector<double> radius;  // m
  std::vector<int> column;     // index of the body on the table below it (itself if on the table)
  std::vector<bool> covered;   // something stands on it

  // Whether a footprint of radius r at (x, z) keeps 5 mm clear of every
  // body not in column `own` (-1: of every body).
  bool clear(const std::vector<EntitySpec>& bodies, double x, double z, double r, int own) const {
    for (std::size_t j = 0; j < bodies.size(); ++j) {
      if (column[j] == own) continue;
      if (std::hypot(bodies[j].position.x - x, bodies[j].position.z - z) <= radius[j] + r + 0.005) return false;
    }
    return true;
  }
};

}  // namespace

Scenario RandomScene::make(std::uint64_t seed) {
  Draw draw(seed);
  Scenario s;
  s.name = "random_" + std::to_string(seed);
  s.description = "A random scene and push sequence (hard case 9), seed " + std::to_string(seed);
  s.file = "(generated: " + s.name + ")";
  s.settings.duration = kDuration;
  s.settings.endAtRest = false;

  const int n = draw.integer(kMinBodies, kMaxBodies);
  Layout layout;
  for (int i = 0; i < n; ++i) {
    EntitySpec e = randomBody(draw);
    const double r = footprintRadius(e.geometry);
    // On an earlier flat-topped body with nothing on it yet, centred on it within a centimetre,
    // if its footprint there is clear of the other columns...
    if (draw.chance(0.3)) {
      const int base = draw.integer(0, static_cast<int>(s.entities.size())) - 1;  // -1: none
      if (base >= 0 && flatTopped(s.entities[base].geometry.kind()) && !layout.covered[base]) {
        const Vec3& p = s.entities[base].position;
        const double x = p.x + draw.uniform(-0.01, 0.01), z = p.z + draw.uniform(-0.01, 0.01);
        if (layout.clear(s.entities, x, z, r, layout.column[base])) {
          e.position = {x, 0.0, z};
          e.on = Support::entity(s.entities[base].name);
          layout.radius.push_back(r);
          layout.column.push_back(layout.column[base]);
          layout.covered[base] = true;
        }
      }
    }
    // ... else on the table, clear of every other body (a few tries; a
    // body with no room is left out).
    for (int attempt = 0; attempt < 20 && e.on.isNone(); ++attempt) {
      const double x = draw.uniform(-0.5 * s.table.width + r, 0.5 * s.table.width - r);
      const double z = draw.uniform(-0.5 * s.table.depth + r, 0.5 * s.table.depth - r);
      if (layout.clear(s.entities, x, z, r, -1)) {
        e.position = {x, 0.0, z};
        e.on = Support::table();
        layout.radius.push_back(r);
        layout.column.push_back(static_cast<int>(s.entities.size()));
      }
    }
    if (e.on.isNone()) continue;
    layout.covered.push_back(false);
    e.name = "b" + std::to_string(s.entities.size());
    e.path = "/entities/" + std::to_string(s.entities.size());
    s.entities.push_back(e);
  }

  const int pushes = draw.integer(1, 4);
  std::vector<double> times;
  for (int k = 0; k < pushes; ++k) times.push_back(draw.uniform(0.0, 0.6));
  std::sort(times.begin(), times.end());
  for (double t : times) {
    const EntitySpec& target = s.entities[static_cast<std::size_t>(draw.integer(0, static_cast<int>(s.entities.size()) - 1))];
    Action push;
    push.type = Action::Type::Push;
    push.at = t;
    push.arrow.entity = target.name;
    if (!target.geometry.round()) {
      push.arrow.face = static_cast<DirectionDef>(draw.integer(0, 3));
    } else {
      push.arrow.angleDegrees = draw.uniform(0.0, 360.0);
    }
    push.magnitude = {PushMagnitude::Kind::Impulse, target.mass * draw.uniform(0.1, 5.0)};
    push.path = "/script/" + std::to_string(s.script.size());
    s.script.push_back(push);
  }
  return s;
}

}  // namespace tabletop
