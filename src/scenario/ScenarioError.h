#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace tabletop {

struct Scenario;

/// One thing wrong with a scenario, located in its file.
struct Problem {
  std::string path;     ///< JSON pointer ("/entities/2/size"), "" for the whole file
  std::string message;  ///< what was expected, and what was found
  int line = 0;         ///< 1-based, 0 when unknown
  int column = 0;       ///< 1-based, 0 when unknown
};

/// A scenario that cannot be run. Each problem formats as one line:
/// `FILE:LINE:COL: at PATH: MESSAGE`, with control characters escaped and
/// its length bounded, whoever wrote the file and its name.
class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(std::string file, std::vector<Problem> problems);
  /// Problems with a scenario, each located in its file by its pointer
  /// (those already located keep their place).
  ScenarioError(const Scenario& scenario, std::vector<Problem> problems);

  const std::string& file() const { return file_; }
  const std::vector<Problem>& problems() const { return problems_; }
  /// Every problem, one per line.
  std::vector<std::string> lines() const;

 private:
  std::string file_;
  std::vector<Problem> problems_;
};

}  // namespace tabletop
