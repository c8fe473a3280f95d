#pragma once

#include <cctype>
#include <cmath>
#include <optional>
#include <type_traits>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "core/Text.h"
#include "core/WorkerThreads.h"
#include "draw/CameraChoice.h"

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

/// --threads N, read from TABLETOP_THREADS when not given (neither: left
/// unset, and the command uses every core): a whole number from 1 to
/// kMaxThreads.
inline CLI::Option* addThreadsOption(CLI::App& command, std::optional<int>& threads) {
  const std::string bounds = "from 1 to " + std::to_string(kMaxThreads);
  CLI::Validator whole(
      [bounds](std::string& text) -> std::string {
        if (threadCount(text)) return "";
        return "expected a whole number " + bounds + " (--threads or TABLETOP_THREADS), got '" + shownText(text) + "'";
      },
      "N " + bounds);
  return command
      .add_option("--threads", threads,
                  "Threads a step solves independent islands on (default: TABLETOP_THREADS, else every core); "
                  "any count gives the same result to the bit")
      ->envname("TABLETOP_THREADS")
      ->check(whole);
}

/// --camera's value, as CameraChoice reads it (shown as CAMERA in help).
inline CLI::Validator cameraChoice() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto choice = CameraChoice::parse(text);
        const std::string* why = std::get_if<std::string>(&choice);
        return why ? *why : std::string();
      },
      "CAMERA");
}

/// A command-line choice among an enum's names, case-insensitive ("RULES"
/// is "rules"), shown in help as the names themselves ("rules|compat|bullet")
/// and refused as "expected rules, compat or bullet, got 'x'". `values`
/// lists them in help order.
template <class Enum, std::size_t N>
CLI::Option* enumOption(CLI::Option* option, const Enum (&values)[N]) {
  std::string shown, expected;
  for (std::size_t i = 0; i < N; ++i) {
    const std::string name(toString(values[i]));
    shown += (i ? "|" : "") + name;
    expected += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + name;
  }
  const auto lower = [](std::string t) {
    for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return t;
  };
  CLI::Validator named(
      [values, expected, lower](std::string& text) -> std::string {
        for (Enum v : values) {
          if (lower(std::string(toString(v))) == lower(text)) {
            // CLI11 reads an enum as its underlying number.
            text = std::to_string(static_cast<std::underlying_type_t<Enum>>(v));
            return "";
          }
        }
        return "expected " + expected + ", got '" + shownText(text) + "'";
      },
      "");
  return option->transform(named)->type_name(shown);
}

}  // namespace tabletop
