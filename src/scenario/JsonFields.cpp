#include "scenario/JsonFields.h"

#include <sstream>

#include "core/Text.h"

namespace tabletop::fields {

std::string number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

std::string rangeText(const Range& r) {
  if (r.lo == -kInf && r.hi == kInf) return "a finite number";
  if (r.hi == kInf) return r.loOpen ? "a positive number" : "a non-negative number";
  if (r.loOpen && r.lo == 0.0) return "a positive number up to " + number(r.hi);
  return "a number from " + number(r.lo) + " to " + number(r.hi);
}

bool inRange(double v, const Range& r) {
  return std::isfinite(v) && (r.loOpen ? v > r.lo : v >= r.lo) && v <= r.hi;
}

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
