#include "scenario/ScenarioError.h"

#include "core/Text.h"
#include "scenario/JsonLocator.h"
#include "scenario/Scenario.h"

namespace tabletop {
namespace {

std::string format(const std::string& file, const Problem& p) {
  std::string s = shownText(file, 256);
  if (p.line > 0) s += ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  s += ": ";
  if (!p.path.empty()) s += "at " + shownText(p.path, 128) + ": ";
  return s + shownText(p.message, 1024);
}

std::vector<Problem> located(const Scenario& scenario, std::vector<Problem> problems) {
  if (!scenario.locator) return problems;
  for (Problem& p : problems) {
    if (p.line > 0) continue;
    const auto where = scenario.locator->find(p.path);
    p.line = where.line;
    p.column = where.column;
  }
  return problems;
}

std::string firstLine(const std::string& file, const std::vector<Problem>& problems) {
  return problems.empty() ? file + ": invalid scenario" : format(file, problems.front());
}

}  // namespace

ScenarioError::ScenarioError(std::string file, std::vector<Problem> problems)
    : std::runtime_error(firstLine(file, problems)),
      file_(std::move(file)),
      problems_(std::move(problems)) {}

ScenarioError::ScenarioError(const Scenario& scenario, std::vector<Problem> problems)
    : ScenarioError(scenario.file, located(scenario, std::move(problems))) {}

std::vector<std::string> ScenarioError::lines() const {
  std::vector<std::string> out;
  for (const Problem& p : problems_) out.push_back(format(file_, p));
  return out;
}

}  // namespace tabletop
