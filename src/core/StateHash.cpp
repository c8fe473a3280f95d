#include "core/StateHash.h"

#include <cstdio>
#include <cstring>

namespace tabletop {
namespace {

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

void mix(std::uint64_t& h, double value) {
  // -0.0 and +0.0 compare equal but differ in bits; fold them together.
  if (value == 0.0) value = 0.0;
  unsigned char bytes[sizeof(double)];
  std::memcpy(bytes, &value, sizeof(double));
  for (unsigned char b : bytes) {
    h ^= b;
    h *= kFnvPrime;
  }
}

void mix(std::uint64_t& h, const Vec3& v) {
  mix(h, v.x);
  mix(h, v.y);
  mix(h, v.z);
}

}  // namespace

std::uint64_t stateHash(const std::vector<EntityState>& entities) {
  std::uint64_t h = kFnvOffset;
  for (const EntityState& e : entities) {
    mix(h, e.position);
    for (double q : e.orientation) mix(h, q);
    mix(h, e.linearVelocity);
    mix(h, e.angularVelocity);
  }
  return h;
}

std::string formatHash(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace tabletop
