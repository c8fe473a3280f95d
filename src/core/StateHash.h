#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/EntityState.h"

namespace tabletop {

/// FNV-1a over the exact bits of every entity's position, orientation and
/// velocities, in entity order: equal hashes mean bit-identical states.
std::uint64_t stateHash(const std::vector<EntityState>& entities);

/// The hash as 16 lower-case hex digits.
std::string formatHash(std::uint64_t hash);

}  // namespace tabletop
