#pragma once

#include <optional>
#include <string_view>

namespace tabletop {

/// How Bullet finds the pairs of bodies whose bounding boxes overlap, the
/// only pairs it tests for contact:
///  - Dbvt: two dynamic AABB trees (btDbvtBroadphase), Bullet's default;
///  - SweepAndPrune: sorted interval lists on three axes (bt32BitAxisSweep3),
///    cheap to update when few bodies move far;
///  - Simple: every pair's boxes compared (btSimpleBroadphase), O(n^2),
///    with the least overhead for a handful of bodies.
enum class Broadphase { Dbvt, SweepAndPrune, Simple };

/// The scenario and command-line name ("dbvt", "sap", "simple").
std::string_view toString(Broadphase b);

/// Parses a name; nullopt if it is not one.
std::optional<Broadphase> broadphaseFromString(std::string_view name);

inline constexpr Broadphase kAllBroadphases[] = {Broadphase::Dbvt, Broadphase::SweepAndPrune, Broadphase::Simple};

}  // namespace tabletop
