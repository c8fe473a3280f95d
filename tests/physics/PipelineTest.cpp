// The pipeline's collision configuration: its pool of collision algorithms
// holds tabletop's own (SolidOnFaceAlgorithm, SolidOnPlaneAlgorithm). Bullet sizes the
// pool's elements for its algorithms alone; an algorithm larger than that
// was written past its element into the next one's memory (SolidOnFaceAlgorithm
// grown by 176 bytes scrambled every pair of a scene with cylinders).

#include "physics/Pipeline.h"

#include <LinearMath/btPoolAllocator.h>

#include <gtest/gtest.h>

#include "physics/collision/SolidOnFaceAlgorithm.h"
#include "physics/collision/SolidOnPlaneAlgorithm.h"

namespace tabletop {
namespace {

TEST(Pipeline, TheAlgorithmPoolHoldsTabletopsOwnAlgorithms) {
  const Pipeline pipeline(Settings{}, TableSpec{});
  const int element = pipeline.configuration->getCollisionAlgorithmPool()->getElementSize();
  EXPECT_GE(element, static_cast<int>(sizeof(SolidOnFaceAlgorithm)));
  EXPECT_GE(element, static_cast<int>(sizeof(SolidOnPlaneAlgorithm)));
}

}  // namespace
}  // namespace tabletop
