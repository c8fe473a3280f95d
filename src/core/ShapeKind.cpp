#include "core/ShapeKind.h"

#include "core/EnumNames.h"

namespace tabletop {

std::string_view toString(ShapeKind k) {
  switch (k) {
    case ShapeKind::Cube: return "cube";
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::SolidBox: return "box";
    case ShapeKind::Cylinder: return "cylinder";
  }
  return "cube";
}

std::optional<ShapeKind> shapeKindFromString(std::string_view name) {
  constexpr ShapeKind all[] = {ShapeKind::Cube, ShapeKind::Sphere, ShapeKind::SolidBox, ShapeKind::Cylinder};
  return enumFromName(name, all);
}

}  // namespace tabletop
