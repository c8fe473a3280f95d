#include "scenes/CubeField.h"

#include <cmath>
#include <string>

namespace tabletop {

Scenario CubeField::make(int n) {
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + columns - 1) / columns;
  Scenario s;
  s.name = "cube_field_" + std::to_string(n);
  s.description = std::to_string(n) + " cubes on a large table, every other column pushed into the next";
  s.file = "(generated: " + s.name + ")";
  s.table.width = columns * kPitch + 2.0 * kPitch;
  s.table.depth = rows * kPitch + 2.0 * kPitch;
  s.table.legRadius = 0.05;
  s.settings.duration = kDuration;
  s.settings.endAtRest = false;
  for (int i = 0; i < n; ++i) {
    const int column = i % columns;
    const int row = i / columns;
    EntitySpec e;
    e.name = "c" + std::to_string(i);
    e.geometry = ShapeGeometry::cube(kSide);
    e.position = {(column - 0.5 * (columns - 1)) * kPitch, 0.0, (row - 0.5 * (rows - 1)) * kPitch};
    e.on = Support::table();
    e.colour = column % 2 ? Colour{40, 90, 220} : Colour{220, 40, 40};
    e.mass = 0.5;
    e.material = Material{0.4, 0.0, 0.0, 0.5};  // friction 0.4, restitution 0.5
    e.path = "/entities/" + std::to_string(i);
    s.entities.push_back(e);
    if (column % 2 == 0) {
      Action push;
      push.type = Action::Type::Push;
      push.at = 0.0;
      push.arrow.entity = e.name;
      push.arrow.face = DirectionDef::Left;
      push.magnitude = {PushMagnitude::Kind::Step, kStep};
      push.path = "/script/" + std::to_string(s.script.size());
      s.script.push_back(push);
    }
  }
  return s;
}

}  // namespace tabletop
