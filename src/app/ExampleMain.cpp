// One of the report's examples as its own executable: `tabletop run` on the
// scenario built into it, with the same options.

#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/RunCommand.h"

namespace tabletop {
// Defined in the generated file that holds the scenario's text.
extern const char* const kExampleName;
extern const char* const kExampleFile;
extern const char* const kExampleText;
}  // namespace tabletop

int main(int argc, char** argv) {
  using namespace tabletop;
  CLI::App app{std::string("Runs the report's ") + kExampleName +
               " example (built-in scenario " + kExampleFile + ") in Bullet."};
  int status = kExitOk;
  RunOptions run;
  addRunOptions(app, run);
  app.callback([&] {
    run.scenarios.push_back({kExampleFile, std::string(kExampleText)});
    status = runScenarios(run, std::cout, std::cerr);
  });
  try {
    return parseAndRun(app, argc, argv, status);
  } catch (const std::exception& e) {
    std::cerr << kExampleName << ": internal error: " << e.what() << "\n";
    return kExitFailure;
  }
}
