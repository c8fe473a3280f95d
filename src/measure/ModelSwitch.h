#pragma once

#include <string>
#include <vector>

#include "core/Settings.h"

namespace tabletop {

/// One way of modelling less (or differently) than the defaults, as the
/// bench measures it: a name ("sleeping=on") and the settings it changes.
/// The switches are the Settings fields that decide what the collision
/// world holds (Settings.h); each is named here as the change from the
/// settings it is applied to, so the list follows the defaults.
struct ModelSwitch {
  std::string name;
  Settings settings;
};

/// The defaults first ("defaults"), then each switch flipped alone from
/// `base`: sleeping, the legs, the floor's pairs, and each other
/// broadphase.
std::vector<ModelSwitch> modelSwitches(const Settings& base);

}  // namespace tabletop
