#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace tabletop {

/// Where each value of a JSON text starts, by JSON pointer. nlohmann::json
/// reports positions only for syntax errors; this scan (which skips // and
/// /* */ comments and a UTF-8 byte order mark like the loader) lets every
/// semantic error name its line and column too, and finds what the parser
/// accepts silently: a key given twice in one object. It keeps no view of
/// the text once built, so a Scenario can keep it to locate problems found
/// later (at run time). Its cost is linear in the text for a bounded
/// nesting depth: check tooDeep() first.
class JsonLocator {
 public:
  struct Location {
    int line = 0;
    int column = 0;
  };
  /// A key given again in the same object.
  struct Duplicate {
    std::string pointer;  ///< the later value's pointer
    Location first;       ///< where the first one's value starts
    Location later;       ///< where the later one's value starts
  };

  explicit JsonLocator(std::string_view text);

  /// The start of the value at `pointer`, or of its nearest located parent.
  Location find(const std::string& pointer) const;
  /// Every key given twice in one object, in the order of the text.
  const std::vector<Duplicate>& duplicates() const { return duplicates_; }

  /// The line and column of byte `offset` in `text`. A line ends at LF,
  /// CR LF or a lone CR; a leading byte order mark is not counted.
  static Location locate(std::string_view text, std::size_t offset);
  /// The first '[' or '{' nested deeper than `maxDepth`, if any.
  static std::optional<Location> tooDeep(std::string_view text, int maxDepth);
  /// The first bare token (a number or a literal, outside strings and
  /// comments) that reads `token`, if any.
  static std::optional<Location> findToken(std::string_view text, std::string_view token);

 private:
  class Cursor;
  void value(Cursor& at, const std::string& pointer);

  std::unordered_map<std::string, Location> locations_;
  std::vector<Duplicate> duplicates_;
};

/// Escapes one key for a JSON pointer ("~" as "~0", "/" as "~1").
std::string escapePointerToken(const std::string& key);

}  // namespace tabletop
