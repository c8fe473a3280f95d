#include "scenario/JsonLocator.h"

#include <algorithm>
#include <unordered_set>

#include <nlohmann/json.hpp>

namespace tabletop {

std::string escapePointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

// A position in the text that keeps its line and column, and steps over
// what carries no value: white space, comments, a leading byte order mark.
class JsonLocator::Cursor {
 public:
  explicit Cursor(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = lineStart_ = 3;
  }

  bool done() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }
  std::size_t pos() const { return pos_; }
  void advance() { ++pos_; }
  // Steps over a line break at pos_: LF, CR LF, or a lone CR (as old Mac
  // files end lines), so each is one line whatever the file's convention.
  void lineBreak() {
    if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
    ++pos_;
    ++line_;
    lineStart_ = pos_;
  }

  std::string_view slice(std::size_t from, std::size_t to) const { return text_.substr(from, to - from); }
  Location location() const { return {line_, static_cast<int>(pos_ - lineStart_) + 1}; }

  void skipSpace() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n' || c == '\r') {
        lineBreak();
      } else if (c == ' ' || c == '\t') {
        ++pos_;
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
        // As nlohmann's parser: a line comment ends at either line break.
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
      } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
        pos_ += 2;
        while (pos_ + 1 < text_.size() && !(text_[pos_] == '*' && text_[pos_ + 1] == '/')) {
          if (text_[pos_] == '\n' || text_[pos_] == '\r') {
            lineBreak();
          } else {
            ++pos_;
          }
        }
        pos_ += 2;
      } else {
        return;
      }
    }
  }

  // From an opening quote to just past the closing one.
  void skipString() {
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += (text_[pos_] == '\\') ? 2 : 1;
    ++pos_;
  }

  // A number or a literal: up to the next delimiter.
  void skipBare() {
    while (pos_ < text_.size() && std::string_view(",:}]{[\" \t\r\n/").find(text_[pos_]) == std::string_view::npos) {
      ++pos_;
    }
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::size_t lineStart_ = 0;
};

namespace {

// A key as the parser reads it: escapes ("m\u0061ss") resolved.
std::string keyText(std::string_view raw) {
  if (raw.find('\\') == std::string_view::npos) return std::string(raw);
  try {
    return nlohmann::json::parse("\"" + std::string(raw) + "\"").get<std::string>();
  } catch (const nlohmann::json::exception&) {
    return std::string(raw);
  }
}

}  // namespace

JsonLocator::JsonLocator(std::string_view text) {
  Cursor at(text);
  at.skipSpace();
  if (!at.done()) value(at, "");
}

JsonLocator::Location JsonLocator::find(const std::string& pointer) const {
  std::string p = pointer;
  for (;;) {
    auto it = locations_.find(p);
    if (it != locations_.end()) return it->second;
    if (p.empty()) return {};
    p.erase(p.rfind('/'));
  }
}

void JsonLocator::value(Cursor& at, const std::string& pointer) {
  locations_.insert_or_assign(pointer, at.location());
  const char c = at.peek();
  if (c == '"') {
    at.skipString();
    return;
  }
  if (c != '{' && c != '[') {
    at.skipBare();
    return;
  }
  const bool object = c == '{';
  std::unordered_set<std::string> keys;
  at.advance();
  int index = 0;
  for (;;) {
    at.skipSpace();
    if (at.done()) return;
    if (at.peek() == (object ? '}' : ']')) {
      at.advance();
      return;
    }
    if (at.peek() == ',') {
      at.advance();
      continue;
    }
    std::string child = pointer + "/";
    bool repeated = false;
    if (object) {
      const std::size_t start = at.pos() + 1;
      at.skipString();
      const std::string key = keyText(at.slice(start, at.pos() - 1));
      child += escapePointerToken(key);
      at.skipSpace();
      if (!at.done()) at.advance();  // ':'
      at.skipSpace();
      repeated = !keys.insert(key).second;
      if (repeated) duplicates_.push_back({child, locations_.at(child), at.location()});
    } else {
      child += std::to_string(index++);
    }
    if (at.done()) return;
    const std::size_t before = at.pos();
    value(at, child);
    // The first of two values under one key keeps its place.
    if (repeated) locations_.insert_or_assign(child, duplicates_.back().first);
    // Every element moves on; a text the scan misreads ends the scan
    // rather than looping (positions are then only approximate).
    if (at.pos() == before) return;
  }
}

JsonLocator::Location JsonLocator::locate(std::string_view text, std::size_t offset) {
  Cursor at(text);
  offset = std::min(offset, text.size());
  while (at.pos() < offset) {
    if (at.peek() == '\n' || at.peek() == '\r') {
      at.lineBreak();
    } else {
      at.advance();
    }
  }
  return at.location();
}

std::optional<JsonLocator::Location> JsonLocator::tooDeep(std::string_view text, int maxDepth) {
  Cursor at(text);
  int depth = 0;
  for (at.skipSpace(); !at.done(); at.skipSpace()) {
    const char c = at.peek();
    if (c == '"') {
      at.skipString();
      continue;
    }
    if (c == '[' || c == '{') {
      if (++depth > maxDepth) return at.location();
    } else if (c == ']' || c == '}') {
      --depth;
    }
    at.advance();
  }
  return std::nullopt;
}

std::optional<JsonLocator::Location> JsonLocator::findToken(std::string_view text, std::string_view token) {
  Cursor at(text);
  for (at.skipSpace(); !at.done(); at.skipSpace()) {
    const char c = at.peek();
    if (c == '"') {
      at.skipString();
    } else if (std::string_view(",:}]{[").find(c) != std::string_view::npos) {
      at.advance();
    } else {
      const Location where = at.location();
      const std::size_t start = at.pos();
      at.skipBare();
      if (at.slice(start, at.pos()) == token) return where;
      if (at.pos() == start) at.advance();
    }
  }
  return std::nullopt;
}

}  // namespace tabletop
