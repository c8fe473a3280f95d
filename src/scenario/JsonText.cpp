#include "scenario/JsonText.h"

#include <algorithm>
#include <fstream>

#include <sys/stat.h>

namespace tabletop {
namespace {

using nlohmann::json;

// The 1-based line and column of a byte offset in `text` (a byte order
// mark, which the parser skips, is not counted).
void locate(Problem& p, const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::size_t lineStart = offset == 0 ? 0 : text.rfind('\n', offset - 1) + 1;
  if (lineStart == 0 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) lineStart = std::min<std::size_t>(3, offset);
  p.line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
  p.column = static_cast<int>(offset - lineStart) + 1;
}

// What follows nlohmann's "[json.exception.parse_error.101] parse error at
// line 3, column 5: " (or its other exceptions' "[json.exception...] ").
std::string reason(const std::string& what) {
  const std::size_t colon = what.find(": ", what.find("parse error"));
  if (what.find("parse error") != std::string::npos && colon != std::string::npos) {
    return what.substr(colon + 2);
  }
  const std::size_t close = what.find("] ");
  return close == std::string::npos ? what : what.substr(close + 2);
}

Problem parseProblem(const json::parse_error& e, const std::string& text) {
  Problem p{"", "not valid JSON: " + reason(e.what())};
  locate(p, text, e.byte == 0 ? 0 : e.byte - 1);
  return p;
}

// Other parser failures (a number too large for a double) give no
// position; the offending token, which the message quotes, is found among
// the text's tokens instead (not in a comment or a string).
Problem valueProblem(const json::exception& e, const std::string& text) {
  Problem p{"", "not valid JSON: " + reason(e.what())};
  const std::size_t open = p.message.find('\'');
  const std::size_t close = p.message.find('\'', open + 1);
  if (open != std::string::npos && close != std::string::npos) {
    const auto where = JsonLocator::findToken(text, p.message.substr(open + 1, close - open - 1));
    if (where) {
      p.line = where->line;
      p.column = where->column;
    }
  }
  return p;
}
}  // namespace

JsonText parseJsonText(const std::string& text, const std::string& source, std::size_t maxBytes, int maxDepth) {
  if (text.size() > maxBytes) {
    throw ScenarioError(source, {{"", "expected at most " + std::to_string(maxBytes) + " bytes, got " +
                                          std::to_string(text.size())}});
  }
  // nlohmann's parser stops at a NUL byte as at the end of the text, and
  // would accept what comes before it.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
    Problem p{"", "not valid JSON: expected text, got a NUL byte"};
    locate(p, text, nul);
    throw ScenarioError(source, {p});
  }
  // Deep nesting is refused before anything recurses into it (showing a
  // value, the locator).
  if (const auto deep = JsonLocator::tooDeep(text, maxDepth)) {
    Problem p{"", "expected arrays and objects nested at most " + std::to_string(maxDepth) + " deep"};
    p.line = deep->line;
    p.column = deep->column;
    throw ScenarioError(source, {p});
  }
  JsonText parsed;
  try {
    parsed.root = json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw ScenarioError(source, {parseProblem(e, text)});
  } catch (const json::exception& e) {
    throw ScenarioError(source, {valueProblem(e, text)});
  }
  parsed.locator = std::make_shared<const JsonLocator>(text);
  return parsed;
}

std::vector<Problem> duplicateProblems(const JsonLocator& locator) {
  std::vector<Problem> problems;
  for (const JsonLocator::Duplicate& d : locator.duplicates()) {
    problems.push_back({d.pointer,
                        "expected each key once in an object, but it was given already at line " +
                            std::to_string(d.first.line) + ", column " + std::to_string(d.first.column),
                        d.later.line, d.later.column});
  }
  return problems;
}

std::string readTextFile(const std::string& path, std::size_t maxBytes) {
  // Only a regular file of bounded size is read: not a directory, a device
  // (/dev/zero never ends) or a pipe.
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw ScenarioError(path, {{"", "cannot open the file for reading"}});
  if (!S_ISREG(info.st_mode)) throw ScenarioError(path, {{"", "expected a regular file"}});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path, {{"", "cannot open the file for reading"}});
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= maxBytes && (in.read(chunk, sizeof chunk) || in.gcount() > 0)) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw ScenarioError(path, {{"", "cannot read the file"}});
  return text;
}

}  // namespace tabletop
