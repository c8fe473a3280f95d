#include "core/Text.h"

#include <cstdio>

namespace tabletop {
namespace {

// The length of the valid UTF-8 sequence at s[i], or 0 if there is none
// (overlong forms and surrogates are invalid, as RFC 3629 says).
std::size_t sequenceLength(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return n;
}

// The code point of the valid sequence of length n at s[i].
unsigned codePoint(std::string_view s, std::size_t i, std::size_t n) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned>(static_cast<unsigned char>(s[k])); };
  if (n == 1) return byte(i);
  unsigned cp = byte(i) & (0x7Fu >> n);
  for (std::size_t k = 1; k < n; ++k) cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  return cp;
}

bool isControl(unsigned cp) {
  return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || (cp >= 0x202A && cp <= 0x202E) ||
         (cp >= 0x2066 && cp <= 0x2069);
}

std::string hexByte(unsigned char c) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned>(c));
  return buffer;
}

}  // namespace

std::optional<std::string> unprintableProblem(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = sequenceLength(s, i);
    if (n == 0) return "invalid UTF-8 at byte " + std::to_string(i);
    const unsigned cp = codePoint(s, i, n);
    if (isControl(cp)) {
      char buffer[16];
      std::snprintf(buffer, sizeof buffer, "U+%04X", cp);
      return std::string("a control character (") + buffer + ") at byte " + std::to_string(i);
    }
    i += n;
  }
  return std::nullopt;
}

std::string shownText(std::string_view s, std::size_t maxBytes) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size() && i < maxBytes) {
    const std::size_t n = sequenceLength(s, i);
    if (n == 0 || isControl(codePoint(s, i, n))) {
      // A control character's bytes, or one byte of invalid UTF-8, escaped.
      for (std::size_t k = 0; k < (n == 0 ? 1 : n); ++k) out += hexByte(static_cast<unsigned char>(s[i + k]));
      i += n == 0 ? 1 : n;
    } else {
      out.append(s.substr(i, n));
      i += n;
    }
  }
  if (i < s.size()) out += "... (" + std::to_string(s.size() - i) + " more bytes)";
  return out;
}

std::string csvField(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

bool endsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

std::string fixed(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

std::string padded(const std::string& s, std::size_t width) {
  return s.size() >= width ? s + " " : s + std::string(width - s.size(), ' ');
}

}  // namespace tabletop
