#include "core/Event.h"

namespace tabletop {

const char* toString(EventType t) {
  switch (t) {
    case EventType::Push: return "push";
    case EventType::Rotate: return "rotate";
    case EventType::ContactBegin: return "contact_begin";
    case EventType::LeavesTable: return "leaves_table";
    case EventType::Lands: return "lands";
    case EventType::AtRest: return "at_rest";
  }
  return "push";
}

std::vector<std::string> eventEntities(const Event& e) {
  std::vector<std::string> names{e.entity};
  if (!e.other.empty()) names.push_back(e.other);
  return names;
}

}  // namespace tabletop
