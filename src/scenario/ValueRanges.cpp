#include "scenario/ValueRanges.h"

#include <cmath>
#include <sstream>

namespace tabletop::ranges {

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

std::string expectedText(double v, const Range& r) {
  const bool positive = r.lo > 0.0 || (r.lo == 0.0 && r.loOpen);
  return positive && v <= 0.0 ? "a positive number" : rangeText(r);
}

}  // namespace tabletop::ranges
