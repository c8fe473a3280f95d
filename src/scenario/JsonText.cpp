#include "scenario/JsonText.h"

#include <algorithm>
#include <cerrno>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/Text.h"
#include "scenario/ScenarioLoader.h"

namespace tabletop {
namespace {

using nlohmann::json;

// The 1-based line and column of a byte offset in `text`.
void locate(Problem& p, const std::string& text, std::size_t offset) {
  const JsonLocator::Location at = JsonLocator::locate(text, offset);
  p.line = at.line;
  p.column = at.column;
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

// `message` with each value it quotes ('...') cut to kMaxQuotedBytes, as
// the loader's own messages show values: a 1 MB number stays one short line.
std::string cutQuotes(const std::string& message) {
  std::string out;
  std::size_t from = 0;
  for (;;) {
    const std::size_t open = message.find('\'', from);
    const std::size_t close = open == std::string::npos ? open : message.find('\'', open + 1);
    if (close == std::string::npos) return out + message.substr(from);
    out += message.substr(from, open + 1 - from);
    out += shownText(std::string_view(message).substr(open + 1, close - open - 1), ScenarioLoader::kMaxQuotedBytes);
    out += '\'';
    from = close + 1;
  }
}

Problem parseProblem(const json::parse_error& e, const std::string& text) {
  Problem p{"", "not valid JSON: " + cutQuotes(reason(e.what()))};
  locate(p, text, e.byte == 0 ? 0 : e.byte - 1);
  return p;
}

// Other parser failures (a number too large for a double) give no
// position; the offending token, which the message quotes, is found among
// the text's tokens instead (not in a comment or a string).
Problem valueProblem(const json::exception& e, const std::string& text) {
  const std::string why = reason(e.what());
  Problem p{"", "not valid JSON: " + cutQuotes(why)};
  const std::size_t open = why.find('\'');
  const std::size_t close = why.find('\'', open + 1);
  if (open != std::string::npos && close != std::string::npos) {
    const auto where = JsonLocator::findToken(text, why.substr(open + 1, close - open - 1));
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
  // A regular file, a pipe (`tabletop run <(generate)`) or standard input
  // ("-"), each read to at most maxBytes: not a directory or a device
  // (/dev/zero never ends).
  const std::string source = path == "-" ? "<stdin>" : path;
  int fd = STDIN_FILENO;
  if (path != "-") {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) throw ScenarioError(source, {{"", "cannot open the file for reading"}});
    if (!S_ISREG(info.st_mode) && !S_ISFIFO(info.st_mode)) {
      throw ScenarioError(source, {{"", "expected a regular file or a pipe"}});
    }
    // Not blocking in open(): a named pipe that no one writes to reads as
    // empty instead of waiting for a writer forever.
    fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) throw ScenarioError(source, {{"", "cannot open the file for reading"}});
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  }
  std::string text;
  char chunk[1 << 16];
  bool failed = false;
  while (text.size() <= maxBytes) {
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) failed = true;
    if (n <= 0) break;
    text.append(chunk, static_cast<std::size_t>(n));
  }
  if (fd != STDIN_FILENO) ::close(fd);
  if (failed) throw ScenarioError(source, {{"", "cannot read the file"}});
  if (text.size() > maxBytes) {
    throw ScenarioError(source, {{"", "expected at most " + std::to_string(maxBytes) + " bytes, got more"}});
  }
  return text;
}

}  // namespace tabletop
