#pragma once

#include "rules/ContactFinder.h"

namespace tabletop::rules {

/// Contacts by the report's predicates, solved for the moment they first
/// hold along a straight displacement:
/// - two boxes (cubes): 3.6.1 as intended, generalised to any direction:
///   the footprints overlap strictly along each axis the motion crosses,
///   and inclusively along an axis it does not (touching sideways counts);
/// - two spheres: 3.6.2, the distance of the centres reaches R1 + R2;
/// - a sphere and a box (not in the report): the sphere's cross-section
///   at the box's nearest height against the box's footprint.
/// Cylinders count as circles of their larger radius.
class ReportContactFinder : public ContactFinder {
 public:
  std::optional<Hit> firstHit(std::size_t moverIndex, const RuleBody& mover, std::size_t otherIndex,
                              const RuleBody& other, const Vec3& displacement) const override;
};

}  // namespace tabletop::rules
