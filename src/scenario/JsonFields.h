#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/EnumNames.h"
#include "core/Vec3.h"
#include "core/Text.h"
#include "scenario/JsonLocator.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "scenario/ValueRanges.h"

/// The checked reading of JSON objects that the scenario loader is made
/// of: ranges of numbers, values shown short in messages, and a reader of
/// one object that records each problem against its JSON pointer. Private
/// to the scenario library.
namespace tabletop::fields {

using nlohmann::json;

// The ranges of numbers and how messages word them (ValueRanges.h, shared
// with the Python module's checks of its arguments).
using ranges::inRange;
using ranges::kInf;
using ranges::number;
using ranges::Range;
using ranges::rangeText;

/// A name as a message quotes it in prose ('A'), cut and escaped.
std::string quotedName(const std::string& name);
/// A text as a message echoes a value ("A"), cut and escaped.
std::string quotedValue(const std::string& text);
/// A value as a message shows it: short, on one line, whatever its size.
std::string shown(const json& j);

// Reads one JSON object field by field, recording problems against JSON
// pointers; finish() reports the keys nobody asked for.
class Fields {
 public:
  Fields(const json& j, std::string path, std::vector<Problem>& problems)
      : j_(j), path_(std::move(path)), problems_(problems) {
    if (!j_.is_object()) fail(path_, "expected an object, got " + shown(j_));
  }

  bool valid() const { return j_.is_object(); }
  /// Where this object's problems go, for a reader of a part of it.
  std::vector<Problem>& problems() { return problems_; }
  std::string at(const std::string& key) const { return path_ + "/" + escapePointerToken(key); }
  void fail(const std::string& path, const std::string& message) { problems_.push_back({path, message}); }

  // The raw value of `key`, or null when absent (reported if required).
  const json* get(const std::string& key, bool required) {
    seen_.insert(key);
    if (!valid()) return nullptr;
    auto it = j_.find(key);
    if (it == j_.end()) {
      if (required) fail(path_, "missing required key '" + key + "'");
      return nullptr;
    }
    return &*it;
  }

  bool has(const std::string& key) const { return valid() && j_.contains(key); }

  double number(const std::string& key, const Range& range, double fallback, bool required = false) {
    const json* v = get(key, required);
    if (!v) return fallback;
    return checkNumber(*v, at(key), range, fallback);
  }

  double checkNumber(const json& v, const std::string& path, const Range& range, double fallback) {
    if (!v.is_number() || !inRange(v.get<double>(), range)) {
      fail(path, "expected " + (v.is_number() ? ranges::expectedText(v.get<double>(), range) : rangeText(range)) +
                     ", got " + shown(v));
      return fallback;
    }
    return v.get<double>();
  }

  // A non-empty string of printable characters, at most `maxBytes` long.
  std::string string(const std::string& key, const std::string& fallback, bool required = false,
                     std::size_t maxBytes = ScenarioLoader::kMaxTextBytes) {
    const json* v = get(key, required);
    if (!v) return fallback;
    if (!v->is_string() || v->get_ref<const std::string&>().empty()) {
      fail(at(key), "expected a non-empty string, got " + shown(*v));
      return fallback;
    }
    const std::string& text = v->get_ref<const std::string&>();
    if (text.size() > maxBytes) {
      fail(at(key), "expected at most " + std::to_string(maxBytes) + " bytes, got " + std::to_string(text.size()) +
                        " (" + shown(*v) + ")");
      return fallback;
    }
    if (const auto why = unprintableProblem(text)) {
      fail(at(key), "expected printable text, got " + *why + " in " + shown(*v));
      return fallback;
    }
    return text;
  }

  bool boolean(const std::string& key, bool fallback) {
    const json* v = get(key, false);
    if (!v) return fallback;
    if (!v->is_boolean()) {
      fail(at(key), "expected true or false, got " + shown(*v));
      return fallback;
    }
    return v->get<bool>();
  }

  // The key's array of three numbers, each within `range`; none when it is
  // absent or wrong (a problem then).
  std::optional<Vec3> vec3(const std::string& key, const Range& range) {
    const json* v = get(key, false);
    if (!v) return std::nullopt;
    const std::vector<double> c = numbers(*v, at(key), 3, 3, range);
    if (c.size() != 3) return std::nullopt;
    return Vec3{c[0], c[1], c[2]};
  }

  // A fixed-length array of numbers; empty on error.
  std::vector<double> numbers(const json& v, const std::string& path, std::size_t minCount,
                              std::size_t maxCount, const Range& range) {
    const std::string what = minCount == maxCount
                                 ? "an array of " + std::to_string(minCount) + " numbers"
                                 : "an array of " + std::to_string(minCount) + " to " +
                                       std::to_string(maxCount) + " numbers";
    if (!v.is_array() || v.size() < minCount || v.size() > maxCount) {
      fail(path, "expected " + what + ", got " + shown(v));
      return {};
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::size_t before = problems_.size();
      const double x = checkNumber(v[i], path + "/" + std::to_string(i), range, 0.0);
      if (problems_.size() != before) return {};
      out.push_back(x);
    }
    return out;
  }

  void finish() {
    if (!valid()) return;
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      if (!seen_.count(it.key())) fail(at(it.key()), "unknown key " + quotedName(it.key()));
    }
  }

 private:
  const json& j_;
  std::string path_;
  std::vector<Problem>& problems_;
  std::set<std::string> seen_;
};

// A key whose value is one of an enum's names: "expected "a", "b" or
// "c", got "x"" otherwise.
template <class Enum, std::size_t N>
void choice(Fields& f, const std::string& key, const Enum (&values)[N], Enum& into) {
  if (!f.has(key)) return;
  const std::string name = f.string(key, "");
  if (const auto v = enumFromName(name, values)) {
    into = *v;
  } else if (!name.empty()) {
    std::string expected;
    for (std::size_t i = 0; i < N; ++i) {
      expected += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + ("\"" + std::string(toString(values[i])) + "\"");
    }
    f.fail(f.at(key), "expected " + expected + ", got " + shown(*f.get(key, false)));
  }
}

// An optional integer setting within `range`, into `value`.
inline void integer(Fields& f, const char* key, const ranges::IntRange& range, int& value) {
  const json* it = f.get(key, false);
  if (!it) return;
  if (!it->is_number_integer() || it->get<long long>() < range.lo || it->get<long long>() > range.hi) {
    f.fail(f.at(key), "expected an integer from " + std::to_string(range.lo) + " to " + std::to_string(range.hi) +
                          ", got " + shown(*it));
  } else {
    value = it->get<int>();
  }
}

}  // namespace tabletop::fields
