#include "physics/step/StepGroups.h"

#include <algorithm>

namespace tabletop {

// The boxes the world gave the broadphase, not its own: a dynamic tree
// pairs bodies whose fattened boxes overlap, and the groups, like the
// outcome, must not depend on the broadphase.
bool StepGroups::joins(const btBroadphaseProxy& a, const btBroadphaseProxy& b) {
  return TestAabbAgainstAabb2(a.m_aabbMin, a.m_aabbMax, b.m_aabbMin, b.m_aabbMax);
}

int StepGroups::root(int i) {
  while (parent_[static_cast<std::size_t>(i)] != i) {
    int& up = parent_[static_cast<std::size_t>(i)];
    up = parent_[static_cast<std::size_t>(up)];  // halve the path
    i = up;
  }
  return i;
}

void StepGroups::find(const btAlignedObjectArray<btRigidBody*>& bodies, btOverlappingPairCache& pairs) {
  int size = 0;
  for (int i = 0; i < bodies.size(); ++i) size = std::max(size, bodies[i]->getWorldArrayIndex() + 1);
  parent_.assign(static_cast<std::size_t>(size), -1);
  for (int i = 0; i < bodies.size(); ++i) {
    const int index = bodies[i]->getWorldArrayIndex();
    if (index >= 0) parent_[static_cast<std::size_t>(index)] = index;
  }
  const auto moving = [&](const btBroadphaseProxy* proxy) {
    const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    const int index = object->getWorldArrayIndex();
    return index >= 0 && index < size && parent_[static_cast<std::size_t>(index)] >= 0 ? index : -1;
  };
  btBroadphasePairArray& array = pairs.getOverlappingPairArray();
  for (int p = 0; p < array.size(); ++p) {
    const btBroadphaseProxy* p0 = array[p].m_pProxy0;
    const btBroadphaseProxy* p1 = array[p].m_pProxy1;
    const int a = moving(p0), b = moving(p1);
    if (a < 0 || b < 0) continue;
    if (!joins(*p0, *p1)) continue;
    const int ra = root(a), rb = root(b);
    if (ra != rb) parent_[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  }
}

void StepGroups::spread(const btAlignedObjectArray<btRigidBody*>& bodies, const BodySet& seeds, BodySet& out) {
  out.clear();
  hit_.assign(parent_.size(), 0);
  bool any = false;
  for (int i = 0; i < bodies.size(); ++i) {
    const int index = bodies[i]->getWorldArrayIndex();
    if (index < 0 || static_cast<std::size_t>(index) >= parent_.size() || !seeds.contains(bodies[i])) continue;
    hit_[static_cast<std::size_t>(root(index))] = 1;
    any = true;
  }
  if (!any) return;
  for (int i = 0; i < bodies.size(); ++i) {
    const int index = bodies[i]->getWorldArrayIndex();
    if (index >= 0 && static_cast<std::size_t>(index) < parent_.size() && hit_[static_cast<std::size_t>(root(index))]) {
      out.insert(bodies[i]);
    }
  }
}

}  // namespace tabletop
