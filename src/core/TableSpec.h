#pragma once

#include "core/Colour.h"
#include "core/Material.h"

namespace tabletop {

/// Dimensions of the report's Table (a SolidBox top on four Cylinder legs),
/// in metres. The top's upper face is at `height` above the ground (y = 0);
/// the table is centred on (centreX, centreZ).
struct TableSpec {
  double width = 1.2;       ///< along X
  double depth = 0.8;       ///< along Z
  double height = 0.75;     ///< top surface above the ground
  double thickness = 0.04;  ///< of the top
  double legRadius = 0.03;
  double centreX = 0.0;
  double centreZ = 0.0;
  Material material = kNeutralMaterial;
  Colour colour{150, 100, 60};
};

}  // namespace tabletop
