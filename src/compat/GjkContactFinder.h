#pragma once

#include "rules/ContactFinder.h"

namespace tabletop {

class World;

/// Contacts by Bullet's own narrow phase, for the compat mode: the exact
/// distance between two entities' collision shapes (GJK, EPA when they
/// overlap, margins included) and conservative advancement along the
/// straight displacement. The distance between two convex bodies is convex
/// in a translation, so each Newton step t += distance / closing speed
/// stays on the near side of the first contact; it stops within
/// kContactTolerance.
class GjkContactFinder : public rules::ContactFinder {
 public:
  /// Contact is reached within this distance, metres.
  static constexpr double kContactTolerance = 1e-6;

  explicit GjkContactFinder(const World& world) : world_(world) {}

  std::optional<rules::Hit> firstHit(std::size_t moverIndex, const rules::RuleBody& mover, std::size_t otherIndex,
                                     const rules::RuleBody& other, const Vec3& displacement) const override;

 private:
  const World& world_;
};

}  // namespace tabletop
