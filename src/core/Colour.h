#pragma once

namespace tabletop {

/// An RGB colour with components 0..255, as in the report's Shapes class.
struct Colour {
  int r = 200;
  int g = 200;
  int b = 200;
};

}  // namespace tabletop
