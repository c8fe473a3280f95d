#pragma once

#include <optional>

#include "core/Vec3.h"
#include "rules/RuleBody.h"

namespace tabletop::rules {

/// Where a moving body first strikes another.
struct Hit {
  double fraction = 0.0;  ///< of the displacement travelled when they meet, 0..1
  Vec3 normal;            ///< unit, horizontal, from the mover towards the struck body
};

/// Finds when a body moving in a straight line meets another. The rule
/// engine asks it; the rules mode answers with the report's predicates
/// (ReportContactFinder), the compat mode with Bullet's collision detection.
class ContactFinder {
 public:
  virtual ~ContactFinder() = default;
  /// The first contact of `mover` with `other` while the mover is displaced
  /// by `displacement` (metres, relative to the other) from where it is now;
  /// nullopt if they do not meet, or if they touch but move apart.
  /// `moverIndex` and `otherIndex` are the bodies' scene indices.
  virtual std::optional<Hit> firstHit(std::size_t moverIndex, const RuleBody& mover, std::size_t otherIndex,
                                      const RuleBody& other, const Vec3& displacement) const = 0;
};

}  // namespace tabletop::rules
