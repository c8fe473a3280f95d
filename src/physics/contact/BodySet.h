#pragma once

#include <algorithm>
#include <vector>

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>

namespace tabletop {

/// A set of the world's bodies, asked only whether a body is in it: the
/// bodies a part stops, holds or turns by their mean rate. Each is marked
/// by its index in the collision world's array, so a part that fills and
/// clears one allocates nothing once it has grown (a node-based set
/// allocated a node for every body, every part). A body not in a world
/// (index -1) is kept in a list of its own.
class BodySet {
 public:
  void insert(const btCollisionObject* body) {
    const int index = body->getWorldArrayIndex();
    if (index < 0) {
      if (std::find(outside_.begin(), outside_.end(), body) == outside_.end()) outside_.push_back(body);
      return;
    }
    mark(index);
  }
  bool contains(const btCollisionObject* body) const {
    const int index = body->getWorldArrayIndex();
    if (index < 0) return std::find(outside_.begin(), outside_.end(), body) != outside_.end();
    return static_cast<std::size_t>(index) < marked_.size() && marked_[static_cast<std::size_t>(index)] != 0;
  }
  /// Adds every body of `other`.
  void insertAll(const BodySet& other) {
    for (const int index : other.members_) mark(index);
    for (const btCollisionObject* body : other.outside_) insert(body);
  }
  bool empty() const { return members_.empty() && outside_.empty(); }
  std::size_t size() const { return members_.size() + outside_.size(); }
  void clear() {
    for (const int index : members_) marked_[static_cast<std::size_t>(index)] = 0;
    members_.clear();
    outside_.clear();
  }

 private:
  void mark(int index) {
    if (static_cast<std::size_t>(index) >= marked_.size()) marked_.resize(static_cast<std::size_t>(index) + 1, 0);
    if (marked_[static_cast<std::size_t>(index)] != 0) return;
    marked_[static_cast<std::size_t>(index)] = 1;
    members_.push_back(index);
  }
  std::vector<unsigned char> marked_;  // by world array index
  std::vector<int> members_;           // the indices marked
  std::vector<const btCollisionObject*> outside_;
};

}  // namespace tabletop
