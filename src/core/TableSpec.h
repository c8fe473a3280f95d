#pragma once

#include "core/Colour.h"
#include "core/Material.h"
#include "core/Vec3.h"

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

  /// Centre of leg `i` (0..3), in world space. Legs stand one leg diameter
  /// in from each corner and reach from the ground to the underside of the
  /// top.
  Vec3 legCentre(int i) const {
    const double inset = 2.0 * legRadius;
    const double x = (i % 2 == 0 ? -1.0 : 1.0) * (0.5 * width - inset);
    const double z = (i < 2 ? -1.0 : 1.0) * (0.5 * depth - inset);
    return {centreX + x, 0.5 * (height - thickness), centreZ + z};
  }
};

}  // namespace tabletop
