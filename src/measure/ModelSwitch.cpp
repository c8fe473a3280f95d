#include "measure/ModelSwitch.h"

namespace tabletop {

std::vector<ModelSwitch> modelSwitches(const Settings& base) {
  std::vector<ModelSwitch> out{{"defaults", base}};
  Settings s = base;
  s.bullet.sleeping = !base.bullet.sleeping;
  out.push_back({std::string("sleeping=") + (s.bullet.sleeping ? "on" : "off"), s});
  s = base;
  s.bullet.legsWhenReachable = !base.bullet.legsWhenReachable;
  out.push_back({std::string("legs=") + (s.bullet.legsWhenReachable ? "when-reachable" : "always"), s});
  s = base;
  s.bullet.floorPairsNearFloor = !base.bullet.floorPairsNearFloor;
  out.push_back({std::string("floor-pairs=") + (s.bullet.floorPairsNearFloor ? "near-floor" : "all"), s});
  for (Broadphase b : kAllBroadphases) {
    if (b == base.bullet.broadphase) continue;
    s = base;
    s.bullet.broadphase = b;
    out.push_back({"broadphase=" + std::string(toString(b)), s});
  }
  return out;
}

}  // namespace tabletop
