#include "core/Gyroscopic.h"

#include "core/EnumNames.h"

namespace tabletop {

std::string_view toString(Gyroscopic g) {
  switch (g) {
    case Gyroscopic::None: return "none";
    case Gyroscopic::Explicit: return "explicit";
    case Gyroscopic::ImplicitWorld: return "implicit_world";
    case Gyroscopic::ImplicitBody: return "implicit_body";
  }
  return "implicit_body";
}

std::optional<Gyroscopic> gyroscopicFromString(std::string_view name) {
  return enumFromName(name, kAllGyroscopics);
}

}  // namespace tabletop
