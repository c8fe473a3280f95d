#pragma once

#include <map>
#include <string>
#include <string_view>

namespace tabletop {

/// Where each value of a JSON text starts, by JSON pointer. nlohmann::json
/// reports positions only for syntax errors; this scan (which skips // and
/// /* */ comments like the loader) lets every semantic error name its line
/// and column too. Only used on texts that parsed.
class JsonLocator {
 public:
  struct Location {
    int line = 0;
    int column = 0;
  };

  explicit JsonLocator(std::string_view text);

  /// The start of the value at `pointer`, or of its nearest located parent.
  Location find(const std::string& pointer) const;

 private:
  void value(const std::string& pointer);
  void skipSpace();
  void skipString();
  void mark(const std::string& pointer);

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::size_t lineStart_ = 0;
  std::map<std::string, Location> locations_;
};

/// Escapes one key for a JSON pointer ("~" as "~0", "/" as "~1").
std::string escapePointerToken(const std::string& key);

}  // namespace tabletop
