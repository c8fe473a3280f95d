#include "core/Broadphase.h"

#include "core/EnumNames.h"

namespace tabletop {

std::string_view toString(Broadphase b) {
  switch (b) {
    case Broadphase::Dbvt: return "dbvt";
    case Broadphase::SweepAndPrune: return "sap";
    case Broadphase::Simple: return "simple";
  }
  return "dbvt";
}

std::optional<Broadphase> broadphaseFromString(std::string_view name) {
  return enumFromName(name, kAllBroadphases);
}

}  // namespace tabletop
