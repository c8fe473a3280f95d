#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tabletop {

/// Text that came from someone else (names, file names, values) on its way
/// to a terminal, a CSV file or another program. Scenario strings are valid
/// UTF-8 (the JSON parser checks it); these helpers work on bytes so they
/// also hold for command-line text that was never checked.

/// Why `s` is not a printable name, or nothing: it must be valid UTF-8 with
/// no character of the Unicode categories Cc (C0, DEL, C1), Cf (zero-width,
/// direction and joining marks such as U+200B-U+200F, U+202A-U+202E,
/// U+2066-U+2069, U+061C, U+FEFF), Zl, Zp (U+2028, U+2029), Cs or Cn
/// (unassigned), which can make a terminal show other text than the bytes
/// hold, or nothing at all.
std::optional<std::string> unprintableProblem(std::string_view s);

/// `s` in Unicode normalization form C: two names that are equal so are
/// the same name. Invalid UTF-8 is returned as it is.
std::string nfc(std::string_view s);

/// `s` made safe to print on one line: control bytes and bytes of invalid
/// UTF-8 as \xNN, cut after `maxBytes` bytes with "..." (and how many
/// bytes were cut).
std::string shownText(std::string_view s, std::size_t maxBytes = 64);

/// `s` as one CSV field (RFC 4180): quoted, with quotes doubled, when it
/// holds a comma, a quote or a line break; as it is otherwise.
std::string csvField(std::string_view s);

/// `v` with `digits` decimals ("%.*f").
std::string fixed(double v, int digits);

/// `s` padded with spaces to `width` columns, and at least one space after.
std::string padded(const std::string& s, std::size_t width);

/// Whether `s` ends with `suffix`.
bool endsWith(std::string_view s, std::string_view suffix);

}  // namespace tabletop
