#pragma once

#include <memory>

#include <btBulletDynamicsCommon.h>

#include "core/Material.h"

namespace tabletop {

/// The floor the table stands on: the static plane y = 0. `bounded` gives
/// it the bounding box of the half-space y <= 0 (Settings::
/// floorPairsNearFloor) instead of Bullet's infinite one.
class Ground {
 public:
  explicit Ground(const Material& material = kNeutralMaterial, bool bounded = false);
  ~Ground();
  Ground(const Ground&) = delete;
  Ground& operator=(const Ground&) = delete;

  btRigidBody& body() { return *body_; }
  const Material& material() const { return material_; }

 private:
  Material material_;
  std::unique_ptr<btStaticPlaneShape> plane_;
  std::unique_ptr<btRigidBody> body_;
};

}  // namespace tabletop
