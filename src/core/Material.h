#pragma once

namespace tabletop {

/// Surface properties of a body. Bullet combines two bodies' coefficients
/// by product (friction, restitution) and by x_a*f_b + x_b*f_a (rolling and
/// spinning friction); the table and ground default to the neutral values,
/// so an entity's own coefficients are the ones it feels on them.
struct Material {
  double friction = 0.5;          ///< Coulomb coefficient, dimensionless
  double rollingFriction = 0.0;   ///< rolling resistance lever arm, metres
  double spinningFriction = 0.0;  ///< resistance to spin about the contact normal, metres
  double restitution = 0.0;       ///< coefficient of restitution, 0..1
};

/// The table's and the ground's default: neutral under Bullet's combination.
inline constexpr Material kNeutralMaterial{1.0, 0.0, 0.0, 1.0};

}  // namespace tabletop
