#include "core/Event.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in the output.
constexpr EnumName<EventType> kNames[] = {
    {EventType::Push, "push"},
    {EventType::Rotate, "rotate"},
    {EventType::ContactBegin, "contact_begin"},
    {EventType::LeavesTable, "leaves_table"},
    {EventType::Lands, "lands"},
    {EventType::AtRest, "at_rest"}};

}  // namespace

const char* toString(EventType t) { return nameOf(t, kNames).data(); }

std::vector<std::string> eventEntities(const Event& e) {
  std::vector<std::string> names{e.entity};
  if (!e.other.empty()) names.push_back(e.other);
  return names;
}

}  // namespace tabletop
