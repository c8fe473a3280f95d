// initializeExactBoxFeatures: the box's polyhedron is Bullet's own hull of
// that box (built once, for a unit box, and scaled), vertex for vertex and
// face for face in Bullet's order, with exact corners and planes, over
// sizes from a millimetre to metres and sides up to 10^4 apart.

#include "physics/shapes/SolidBox.h"

#include <cmath>
#include <vector>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexPolyhedron.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

// Every order of the three sides, and sides equal in pairs and all three.
const btVector3 kHalves[] = {{0.05, 0.05, 0.05}, {0.001, 0.5, 2.0},  {3.0, 0.01, 0.2},   {0.7, 0.2, 0.0004},
                             {0.04, 0.015, 0.03}, {10.0, 10.0, 0.001}, {0.2, 0.9, 0.05}, {0.01, 0.3, 0.02},
                             {0.02, 0.03, 0.5},   {0.5, 0.1, 0.5},    {0.1, 0.5, 0.5},   {0.5, 0.5, 0.1}};

TEST(SolidBoxFeatures, AreBulletsHullOfThatBoxWithExactCornersAndPlanes) {
  for (const btVector3& half : kHalves) {
    for (const double margin : {0.0, 0.001, 0.04}) {
      btBoxShape box(half);
      box.setMargin(margin);
      initializeExactBoxFeatures(box);
      const btConvexPolyhedron& made = *box.getConvexPolyhedron();
      // Bullet's hull of the same box, built for it.
      btBoxShape own(box.getHalfExtentsWithMargin());
      own.setMargin(margin);
      own.initializePolyhedralFeatures();
      const btConvexPolyhedron& hull = *own.getConvexPolyhedron();
      const btVector3 h = box.getHalfExtentsWithMargin();
      ASSERT_EQ(made.m_vertices.size(), hull.m_vertices.size());
      for (int v = 0; v < made.m_vertices.size(); ++v) {
        for (int a = 0; a < 3; ++a) {
          EXPECT_EQ(made.m_vertices[v][a], std::copysign(h[a], hull.m_vertices[v][a]))
              << "half " << half.x() << " " << half.y() << " " << half.z() << ", vertex " << v << ", axis " << a;
        }
      }
      ASSERT_EQ(made.m_faces.size(), hull.m_faces.size());
      for (int f = 0; f < made.m_faces.size(); ++f) {
        const btFace &a = made.m_faces[f], &b = hull.m_faces[f];
        ASSERT_EQ(a.m_indices.size(), b.m_indices.size());
        for (int i = 0; i < a.m_indices.size(); ++i) EXPECT_EQ(a.m_indices[i], b.m_indices[i]) << "face " << f;
        const int axis = btVector3(b.m_plane[0], b.m_plane[1], b.m_plane[2]).absolute().maxAxis();
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(a.m_plane[k], k == axis ? (b.m_plane[axis] > 0 ? 1.0 : -1.0) : 0.0) << "face " << f;
        }
        EXPECT_EQ(a.m_plane[3], -h[axis]) << "face " << f;
      }
      // Three unique edge directions, the centre at the origin, and the
      // box inside it a millionth smaller.
      EXPECT_EQ(made.m_uniqueEdges.size(), 3);
      EXPECT_NEAR(made.m_localCenter.length(), 0.0, 1e-12 * h.length());
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(made.m_extents[a], h[a], 2e-6 * h[a]);
    }
  }
}

}  // namespace
}  // namespace tabletop
