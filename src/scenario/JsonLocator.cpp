#include "scenario/JsonLocator.h"

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

JsonLocator::JsonLocator(std::string_view text) : text_(text) {
  skipSpace();
  if (pos_ < text_.size()) value("");
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

void JsonLocator::mark(const std::string& pointer) {
  locations_[pointer] = {line_, static_cast<int>(pos_ - lineStart_) + 1};
}

void JsonLocator::skipSpace() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++pos_;
      ++line_;
      lineStart_ = pos_;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      ++pos_;
    } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
      // As nlohmann's parser: a line comment ends at either line break.
      while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
    } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
      pos_ += 2;
      while (pos_ + 1 < text_.size() && !(text_[pos_] == '*' && text_[pos_ + 1] == '/')) {
        if (text_[pos_] == '\n') {
          ++line_;
          lineStart_ = pos_ + 1;
        }
        ++pos_;
      }
      pos_ += 2;
    } else {
      return;
    }
  }
}

void JsonLocator::skipString() {
  ++pos_;  // opening quote
  while (pos_ < text_.size() && text_[pos_] != '"') pos_ += (text_[pos_] == '\\') ? 2 : 1;
  ++pos_;  // closing quote
}

void JsonLocator::value(const std::string& pointer) {
  mark(pointer);
  const char c = text_[pos_];
  if (c == '{' || c == '[') {
    const bool object = c == '{';
    ++pos_;
    int index = 0;
    for (;;) {
      skipSpace();
      if (pos_ >= text_.size()) return;
      if (text_[pos_] == (object ? '}' : ']')) {
        ++pos_;
        return;
      }
      if (text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      std::string child = pointer + "/";
      if (object) {
        const std::size_t start = pos_ + 1;
        skipString();
        child += escapePointerToken(std::string(text_.substr(start, pos_ - 1 - start)));
        skipSpace();
        ++pos_;  // ':'
        skipSpace();
      } else {
        child += std::to_string(index++);
      }
      if (pos_ >= text_.size()) return;
      const std::size_t before = pos_;
      value(child);
      // Every element moves on; a text the scan misreads ends the scan
      // rather than looping (positions are then only approximate).
      if (pos_ == before) return;
    }
  }
  if (c == '"') {
    skipString();
    return;
  }
  while (pos_ < text_.size() && std::string_view(",}] \t\r\n/").find(text_[pos_]) == std::string_view::npos) {
    ++pos_;
  }
}

}  // namespace tabletop
