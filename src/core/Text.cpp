#include "core/Text.h"

#include <cstdio>
#include <cstdlib>
#include <memory>

#include <utf8proc.h>

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

// What kind of unprintable character `cp` is, by its Unicode general
// category, or null when it is printable: controls (Cc), format marks (Cf:
// zero-width, direction and joining marks, U+FEFF), line and paragraph
// separators (Zl, Zp), surrogates (Cs) and unassigned code points (Cn). A
// terminal may show them as other text than the bytes hold, or as nothing.
const char* unprintableKind(unsigned cp) {
  switch (utf8proc_category(static_cast<utf8proc_int32_t>(cp))) {
    case UTF8PROC_CATEGORY_CC: return "a control character";
    case UTF8PROC_CATEGORY_CF: return "a format character (invisible, or a direction mark)";
    case UTF8PROC_CATEGORY_ZL: return "a line separator";
    case UTF8PROC_CATEGORY_ZP: return "a paragraph separator";
    case UTF8PROC_CATEGORY_CS:
    case UTF8PROC_CATEGORY_CN: return "an unassigned code point";
    default: return nullptr;
  }
}

bool isControl(unsigned cp) { return unprintableKind(cp) != nullptr; }

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
    if (const char* kind = unprintableKind(cp)) {
      char buffer[16];
      std::snprintf(buffer, sizeof buffer, "U+%04X", cp);
      return std::string(kind) + " (" + buffer + ") at byte " + std::to_string(i);
    }
    i += n;
  }
  return std::nullopt;
}

std::string nfc(std::string_view s) {
  // utf8proc allocates the result with malloc; invalid UTF-8 stays as it is.
  utf8proc_uint8_t* out = nullptr;
  const auto n = utf8proc_map(reinterpret_cast<const utf8proc_uint8_t*>(s.data()),
                              static_cast<utf8proc_ssize_t>(s.size()), &out,
                              static_cast<utf8proc_option_t>(UTF8PROC_STABLE | UTF8PROC_COMPOSE));
  if (n < 0) return std::string(s);
  const std::unique_ptr<utf8proc_uint8_t, decltype(&std::free)> owned(out, &std::free);
  return std::string(reinterpret_cast<const char*>(out), static_cast<std::size_t>(n));
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
