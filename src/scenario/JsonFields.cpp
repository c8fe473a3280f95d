#include "scenario/JsonFields.h"

#include "core/Text.h"

namespace tabletop::fields {

// A name as a message quotes it in prose, and as it echoes a value.
std::string quotedName(const std::string& name) { return "'" + shownText(name, ScenarioLoader::kMaxQuotedBytes) + "'"; }
std::string quotedValue(const std::string& text) { return "\"" + shownText(text, ScenarioLoader::kMaxQuotedBytes) + "\""; }

// A value as a message shows it: short, on one line, whatever its size.
std::string shown(const json& j) {
  if (j.is_string()) return quotedValue(j.get_ref<const std::string&>());
  if (j.is_array() && j.size() > 8) return "an array of " + std::to_string(j.size()) + " values";
  if (j.is_object() && j.size() > 8) return "an object of " + std::to_string(j.size()) + " keys";
  std::string s = j.dump();
  const std::size_t most = ScenarioLoader::kMaxQuotedBytes;
  return s.size() > most ? s.substr(0, most - 3) + "..." : s;
}

}  // namespace tabletop::fields
