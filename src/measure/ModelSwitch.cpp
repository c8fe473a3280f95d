#include "measure/ModelSwitch.h"

namespace tabletop {

std::vector<ModelSwitch> modelSwitches(const Settings& base) {
  std::vector<ModelSwitch> out{{"defaults", base}};
  Settings s = base;
  s.sleeping = !base.sleeping;
  out.push_back({std::string("sleeping=") + (s.sleeping ? "on" : "off"), s});
  s = base;
  s.legsWhenReachable = !base.legsWhenReachable;
  out.push_back({std::string("legs=") + (s.legsWhenReachable ? "when-reachable" : "always"), s});
  s = base;
  s.floorPairsNearFloor = !base.floorPairsNearFloor;
  out.push_back({std::string("floor-pairs=") + (s.floorPairsNearFloor ? "near-floor" : "all"), s});
  for (Broadphase b : kAllBroadphases) {
    if (b == base.broadphase) continue;
    s = base;
    s.broadphase = b;
    out.push_back({"broadphase=" + std::string(toString(b)), s});
  }
  return out;
}

}  // namespace tabletop
