#include "core/Gyroscopic.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<Gyroscopic> kNames[] = {
    {Gyroscopic::None, "none"},
    {Gyroscopic::Explicit, "explicit"},
    {Gyroscopic::ImplicitWorld, "implicit_world"},
    {Gyroscopic::ImplicitBody, "implicit_body"}};

}  // namespace

std::string_view toString(Gyroscopic g) { return nameOf(g, kNames); }

std::optional<Gyroscopic> gyroscopicFromString(std::string_view name) { return valueNamed(name, kNames); }

}  // namespace tabletop
