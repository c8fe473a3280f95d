#pragma once

// Names for value-parameterised tests, made from their parameters
// (`sphere_0p05_table_e0p5_60Hz`). Without a name generator GoogleTest
// numbers the cases, and CTest names each by the printed value, which for
// a struct is a dump of its bytes, pointers and padding included: it
// changes from build to build, so a failing name could not be fed back to
// `ctest -R` and CTest's cost history was lost. GoogleTest accepts letters,
// digits and '_' only in a name, and aborts on two equal names in a suite.

#include <cctype>
#include <cstddef>
#include <cstdio>
#include <initializer_list>
#include <string>

namespace tabletop::test {

/// `text` as a part of a test name: a '.' between digits becomes 'p', a '-'
/// before a digit 'm', and a '+' before one goes (0.5 -> 0p5, -1 -> m1,
/// 1e-06 -> 1em06, 1e+06 -> 1e06); any other run of characters that are
/// not letters or digits becomes one '_', none at either end
/// ("[0.08, 0.03]" -> 0p08_0p03).
inline std::string namePart(const std::string& text) {
  const auto digitAt = [&text](std::size_t k) {
    return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])) != 0;
  };
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (std::isalnum(static_cast<unsigned char>(c)) != 0) {
      out += c;
    } else if (c == '.' && i > 0 && digitAt(i - 1) && digitAt(i + 1)) {
      out += 'p';
    } else if (c == '-' && digitAt(i + 1)) {
      out += 'm';
    } else if (c == '+' && digitAt(i + 1)) {
      continue;  // an exponent's sign: 1e+06 -> 1e06
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  if (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

/// A number as a name part, to six significant figures (%g): 0.5 -> 0p5,
/// -10 -> m10, 1000 -> 1000, 1e-6 -> 1em06.
inline std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return namePart(text);
}

/// Numbers as one name part, joined by '_': {0, 0, -10} -> 0_0_m10.
inline std::string numbers(std::initializer_list<double> values) {
  std::string out;
  for (const double v : values) out += (out.empty() ? "" : "_") + number(v);
  return out;
}

/// A test name from its parts, each made a name part, the empty ones left
/// out, joined by '_': testName({"sphere", "0.05", "e" + number(0.5)}) is
/// sphere_0p05_e0p5.
inline std::string testName(std::initializer_list<std::string> parts) {
  std::string out;
  for (const std::string& part : parts) {
    const std::string p = namePart(part);
    if (p.empty()) continue;
    out += (out.empty() ? "" : "_") + p;
  }
  return out;
}

}  // namespace tabletop::test
