#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "core/Text.h"

namespace tabletop {

/// A command-line number from `lo` to `hi`, finite: CLI11's own Range lets
/// "nan" through (every comparison with NaN is false) and "inf" through
/// where the range is open.
inline CLI::Validator finiteRange(double lo, double hi) {
  std::ostringstream range;
  range << lo << " to " << hi;
  return CLI::Validator(
      [lo, hi, bounds = range.str()](std::string& text) -> std::string {
        double v = 0.0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          return "expected a number, got '" + shownText(text) + "'";
        }
        if (used != text.size() || !std::isfinite(v)) return "expected a finite number, got '" + shownText(text) + "'";
        if (v < lo || v > hi) return "expected a number from " + bounds + ", got " + shownText(text);
        return "";
      },
      "NUMBER from " + range.str());
}

}  // namespace tabletop
