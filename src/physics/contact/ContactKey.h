#pragma once

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace tabletop {

/// A contact, named by its two bodies (a manifold may be made anew for the
/// same pair), and the contacts whose friction held at its limit through a
/// part, in order (a sorted vector: it is made afresh every part): they
/// slid through it. Contacts are ordered by their bodies' places in the
/// world, not their addresses: where the order breaks a tie (the face a
/// body slipped on), an order by address made a pile of 1000 bodies end
/// differently after other worlds had been built and freed in the process.
struct ContactKey {
  const btCollisionObject* first = nullptr;
  const btCollisionObject* second = nullptr;
  friend bool operator==(const ContactKey& a, const ContactKey& b) {
    return a.first == b.first && a.second == b.second;
  }
  friend bool operator!=(const ContactKey& a, const ContactKey& b) { return !(a == b); }
  friend bool operator<(const ContactKey& a, const ContactKey& b) {
    const auto place = [](const ContactKey& k) {
      return std::make_pair(k.first->getWorldArrayIndex(), k.second->getWorldArrayIndex());
    };
    if (place(a) != place(b)) return place(a) < place(b);
    // Bodies outside a world (-1) are told apart by address.
    return std::less<const btCollisionObject*>()(a.first, b.first) ||
           (a.first == b.first && std::less<const btCollisionObject*>()(a.second, b.second));
  }
};
inline ContactKey contactOf(const btPersistentManifold& manifold) { return {manifold.getBody0(), manifold.getBody1()}; }
using SlidingContacts = std::vector<ContactKey>;
inline bool slid(const SlidingContacts& sliding, const ContactKey& key) {
  return std::binary_search(sliding.begin(), sliding.end(), key);
}

}  // namespace tabletop
