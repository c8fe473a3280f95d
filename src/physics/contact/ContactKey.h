#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace tabletop {

/// A contact, named by its two bodies (a manifold may be made anew for the
/// same pair), and the contacts whose friction held at its limit through a
/// part, in order (a sorted vector: it is made afresh every part): they
/// slid through it.
using ContactKey = std::pair<const btCollisionObject*, const btCollisionObject*>;
inline ContactKey contactOf(const btPersistentManifold& manifold) { return {manifold.getBody0(), manifold.getBody1()}; }
using SlidingContacts = std::vector<ContactKey>;
inline bool slid(const SlidingContacts& sliding, const ContactKey& key) {
  return std::binary_search(sliding.begin(), sliding.end(), key);
}

}  // namespace tabletop
