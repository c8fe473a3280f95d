#include "core/Integrator.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<Integrator> kNames[] = {
    {Integrator::Euler, "euler"},
    {Integrator::Trapezoid, "trapezoid"}};

}  // namespace

std::string_view toString(Integrator i) { return nameOf(i, kNames); }

std::optional<Integrator> integratorFromString(std::string_view name) { return valueNamed(name, kNames); }

}  // namespace tabletop
