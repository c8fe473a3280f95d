#include "core/Broadphase.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<Broadphase> kNames[] = {
    {Broadphase::Dbvt, "dbvt"},
    {Broadphase::SweepAndPrune, "sap"},
    {Broadphase::Simple, "simple"}};

}  // namespace

std::string_view toString(Broadphase b) { return nameOf(b, kNames); }

std::optional<Broadphase> broadphaseFromString(std::string_view name) { return valueNamed(name, kNames); }

}  // namespace tabletop
