#pragma once

#include "physics/shapes/SolidBox.h"

namespace tabletop {

/// The report's Cube: a SolidBox whose three sides equal `side` (report 3.2).
class Cube : public SolidBox {
 public:
  Cube(std::string name, double side) : SolidBox(std::move(name), side, side, side) {}

  double side() const { return width(); }
  ShapeKind kind() const override { return ShapeKind::Cube; }
};

}  // namespace tabletop
