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
/// no control character (C0, DEL, C1) and no bidirectional override
/// (U+202A-U+202E, U+2066-U+2069), which can make a terminal show other
/// text than the bytes hold.
std::optional<std::string> unprintableProblem(std::string_view s);

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
