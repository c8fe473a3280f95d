#pragma once

// The checked reading of a sweep spec's values: each problem recorded
// against its JSON pointer, values shown short in messages. Private to the
// sweep library (SweepSpecLoader.cpp).

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/Text.h"
#include "scenario/JsonLocator.h"
#include "scenario/ScenarioError.h"
#include "sweep/SweepSpec.h"

namespace tabletop::sweep {

using nlohmann::json;

// A value as a message shows it: short and on one line.
inline std::string shown(const json& j) {
  if (j.is_string()) return "\"" + shownText(j.get_ref<const std::string&>(), 40) + "\"";
  if (j.is_array() && j.size() > 8) return "an array of " + std::to_string(j.size()) + " values";
  if (j.is_object() && j.size() > 8) return "an object of " + std::to_string(j.size()) + " keys";
  const std::string s = j.dump();
  return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

// Collects problems against pointers into the spec.
struct SpecChecker {
  std::vector<Problem> problems;
  void fail(const std::string& at, const std::string& message) { problems.push_back({at, message}); }

  // The keys of object `j` at `at` not among `known` are reported.
  void onlyKeys(const json& j, const std::string& at, const std::set<std::string>& known) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!known.count(it.key()))
        fail(at + "/" + escapePointerToken(it.key()), "unknown key '" + shownText(it.key(), 40) + "'");
    }
  }
  bool isNumber(const json& j, const std::string& at) {
    if (j.is_number() && std::isfinite(j.get<double>())) return true;
    fail(at, "expected a finite number, got " + shown(j));
    return false;
  }
  // A whole number from lo to hi, or `fallback` after a problem.
  std::size_t count(const json& j, const std::string& at, std::size_t lo, std::size_t hi, std::size_t fallback) {
    if (j.is_number_integer() && j.get<long long>() >= static_cast<long long>(lo) &&
        j.get<long long>() <= static_cast<long long>(hi)) {
      return j.get<std::size_t>();
    }
    fail(at, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + shown(j));
    return fallback;
  }
  std::string name(const json& j, const std::string& at) {
    if (!j.is_string()) {
      fail(at, "expected a string, got " + shown(j));
      return "";
    }
    const std::string& s = j.get_ref<const std::string&>();
    if (s.empty() || s.size() > SweepSpec::kMaxNameBytes || unprintableProblem(s)) {
      fail(at,
           "expected a printable name of 1 to " + std::to_string(SweepSpec::kMaxNameBytes) + " bytes, got " + shown(j));
    }
    return s;
  }
  // A pointer that names a place in `scene`: an existing value, or a new
  // key of an existing object.
  std::string pointer(const json& j, const std::string& at, const json& scene) {
    if (!j.is_string()) {
      fail(at, "expected a JSON pointer (a string), got " + shown(j));
      return "";
    }
    const std::string& s = j.get_ref<const std::string&>();
    try {
      const json::json_pointer p(s);
      if (p.empty()) {
        fail(at, "expected a pointer into the scene, got the whole scene \"\"");
      } else if (!scene.contains(p) && !(scene.contains(p.parent_pointer()) && scene[p.parent_pointer()].is_object())) {
        fail(at, "expected a place in the scene (a value, or a new key of an object), got " + shown(j));
      }
    } catch (const json::exception&) {
      fail(at, "expected a JSON pointer (\"/entities/0/mass\"), got " + shown(j));
    }
    return s;
  }
};


}  // namespace tabletop::sweep
