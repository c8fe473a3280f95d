#include "core/ShapeKind.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<ShapeKind> kNames[] = {
    {ShapeKind::Cube, "cube"},
    {ShapeKind::Sphere, "sphere"},
    {ShapeKind::SolidBox, "box"},
    {ShapeKind::Cylinder, "cylinder"}};

}  // namespace

std::string_view toString(ShapeKind k) { return nameOf(k, kNames); }

std::optional<ShapeKind> shapeKindFromString(std::string_view name) { return valueNamed(name, kNames); }

}  // namespace tabletop
