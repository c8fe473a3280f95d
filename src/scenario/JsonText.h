#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/JsonLocator.h"
#include "scenario/ScenarioError.h"

namespace tabletop {

/// A JSON text (with comments) parsed and located: what every file tabletop
/// reads from a user goes through before its fields are checked.
struct JsonText {
  nlohmann::json root;
  std::shared_ptr<const JsonLocator> locator;
};

/// Parses `text` (named `source` in errors): refused with one located
/// ScenarioError when it is longer than `maxBytes`, holds a NUL byte, nests
/// deeper than `maxDepth` or is not JSON.
JsonText parseJsonText(const std::string& text, const std::string& source, std::size_t maxBytes, int maxDepth);

/// A problem per key given twice in one object (the parser keeps the last
/// silently), for the caller to report with the others it finds.
std::vector<Problem> duplicateProblems(const JsonLocator& locator);

/// The content of the regular file or pipe at `path` ("-": standard input,
/// named "<stdin>" in errors), refused
/// (a ScenarioError) when longer than `maxBytes` or when it cannot be read.
std::string readTextFile(const std::string& path, std::size_t maxBytes);

}  // namespace tabletop
