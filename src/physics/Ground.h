#pragma once

#include <memory>

#include <btBulletDynamicsCommon.h>

#include "core/Material.h"

namespace tabletop {

/// The floor the table stands on: the static plane y = 0.
class Ground {
 public:
  explicit Ground(const Material& material = kNeutralMaterial);
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
