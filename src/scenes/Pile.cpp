#include "scenes/Pile.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace tabletop {
namespace {

// Uniform in [lo, hi) from the generator's raw 64-bit words, the same on
// every standard library.
double uniform(std::mt19937_64& engine, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(engine() >> 11) * 0x1.0p-53);
}

// Body i of the pile: its kind in turn, so every mix is even; sizes,
// mass (log-uniform 0.1-2 kg) and material drawn.
EntitySpec pileBody(int i, std::mt19937_64& engine) {
  const auto size = [&] { return uniform(engine, Pile::kSmallest, Pile::kLargest); };
  EntitySpec e;
  switch (i % 4) {
    case 0: e.geometry = ShapeGeometry::cube(size()); break;
    case 1: e.geometry = ShapeGeometry::sphere(0.5 * size()); break;
    case 2: {
      const double w = size(), h = size(), d = size();
      e.geometry = ShapeGeometry::box(w, h, d);
      break;
    }
    default: {
      const double r = 0.5 * size(), h = size();
      e.geometry = ShapeGeometry::cylinder(r, r, h);
      break;
    }
  }
  e.mass = 0.1 * std::pow(20.0, uniform(engine, 0.0, 1.0));
  e.material.friction = uniform(engine, 0.2, 0.8);
  e.material.restitution = uniform(engine, 0.0, 0.5);
  e.yawDegrees = uniform(engine, 0.0, 360.0);
  return e;
}

}  // namespace

double Pile::pitch() { return kLargest * std::sqrt(3.0) + kGap; }

Scenario Pile::make(int n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  const int side = std::min(kLayerSide, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))));
  const double p = pitch();
  Scenario s;
  s.name = "pile_" + std::to_string(n);
  s.description = std::to_string(n) + " mixed bodies dropped at once onto the table";
  s.file = "(generated: " + s.name + ")";
  s.table.width = side * p + p;
  s.table.depth = side * p + p;
  s.table.legRadius = 0.05;
  s.settings.timestep = 1.0 / kRate;
  s.settings.duration = kSettle + kWindow;
  s.settings.endAtRest = false;
  const double bottom = s.table.height + kDropHeight + 0.5 * kLargest * std::sqrt(3.0);
  for (int i = 0; i < n; ++i) {
    const int layer = i / (side * side), cell = i % (side * side);
    EntitySpec e = pileBody(i, engine);
    e.name = "p" + std::to_string(i);
    e.position = {(cell % side - 0.5 * (side - 1)) * p, bottom + layer * p, (cell / side - 0.5 * (side - 1)) * p};
    const int shade = 60 + 40 * (i % 4);
    e.colour = Colour{shade, 230 - shade, 120};
    e.path = "/entities/" + std::to_string(i);
    s.entities.push_back(e);
  }
  return s;
}

}  // namespace tabletop
