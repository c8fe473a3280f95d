#include "scenario/ScenarioError.h"

namespace tabletop {
namespace {

std::string format(const std::string& file, const Problem& p) {
  std::string s = file;
  if (p.line > 0) s += ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  s += ": ";
  if (!p.path.empty()) s += "at " + p.path + ": ";
  return s + p.message;
}

std::string firstLine(const std::string& file, const std::vector<Problem>& problems) {
  return problems.empty() ? file + ": invalid scenario" : format(file, problems.front());
}

}  // namespace

ScenarioError::ScenarioError(std::string file, std::vector<Problem> problems)
    : std::runtime_error(firstLine(file, problems)),
      file_(std::move(file)),
      problems_(std::move(problems)) {}

std::vector<std::string> ScenarioError::lines() const {
  std::vector<std::string> out;
  for (const Problem& p : problems_) out.push_back(format(file_, p));
  return out;
}

}  // namespace tabletop
