#include "core/Integrator.h"

#include "core/EnumNames.h"

namespace tabletop {

std::string_view toString(Integrator i) {
  switch (i) {
    case Integrator::Euler: return "euler";
    case Integrator::Trapezoid: return "trapezoid";
  }
  return "trapezoid";
}

std::optional<Integrator> integratorFromString(std::string_view name) {
  return enumFromName(name, kAllIntegrators);
}

}  // namespace tabletop
