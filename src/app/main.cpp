// tabletop: runs the report's scenes in Bullet from the command line.

#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/CompareCommand.h"
#include "app/RenderCommand.h"
#include "app/RunCommand.h"
#include "app/ViewCommand.h"

int main(int argc, char** argv) {
  using namespace tabletop;
  CLI::App app{
      "tabletop: the table-top scenes of S. Zou's report \"The Design of a 3D-Object Simulator\n"
      "Using Open-GL\" (Concordia, 2001) simulated with Bullet rigid-body physics."};
  app.require_subcommand(1);
  int status = kExitOk;

  RunOptions run;
  std::vector<std::string> files;
  CLI::App* runCommand = app.add_subcommand(
      "run", "Run scenario files headless and print each entity's final state and the events");
  runCommand->add_option("SCENARIO", files, "Scenario files (JSON)")->required();
  addRunOptions(*runCommand, run);
  runCommand->callback([&] {
    for (const std::string& f : files) run.scenarios.push_back({f, std::nullopt});
    status = runScenarios(run, std::cout, std::cerr);
  });

  CompareOptions compare;
  std::string compareFile;
  CLI::App* compareCommand = app.add_subcommand(
      "compare", "Run a scenario in the rules, compat and bullet modes and say where and why they differ");
  compareCommand->add_option("SCENARIO", compareFile, "Scenario file (JSON)")->required();
  addRunOptions(*compareCommand, compare.run, false);
  compareCommand->add_option("--plot", compare.plot, "Write a top view of the trajectories (FILE.png or FILE.svg)");
  compareCommand->callback([&] {
    compare.run.scenarios.push_back({compareFile, std::nullopt});
    status = compareScenario(compare, std::cout, std::cerr);
  });

  RenderOptions render;
  std::string renderFile;
  CLI::App* renderCommand = app.add_subcommand(
      "render", "Render a scenario without a display (OSMesa) to PNG frames, and with --video to MP4 or GIF");
  renderCommand->add_option("SCENARIO", renderFile, "Scenario file (JSON)")->required();
  addRunOptions(*renderCommand, render.run);
  renderCommand->remove_option(renderCommand->get_option("--json"));
  addRenderOptions(*renderCommand, render);
  renderCommand->callback([&] {
    render.run.scenarios.push_back({renderFile, std::nullopt});
    status = renderScenario(render, std::cout, std::cerr);
  });

  ViewOptions view;
  std::string viewFile;
  CLI::App* viewCommand = app.add_subcommand(
      "view", "Open the report's window on a scenario: watch it, push entities with the keyboard (H: help)");
  viewCommand->add_option("SCENARIO", viewFile, "Scenario file (JSON)")->required();
  addRunOptions(*viewCommand, view.run);
  viewCommand->remove_option(viewCommand->get_option("--json"));
  addViewOptions(*viewCommand, view);
  viewCommand->callback([&] {
    view.run.scenarios.push_back({viewFile, std::nullopt});
    status = viewScenario(view, std::cerr);
  });

  try {
    return parseAndRun(app, argc, argv, status);
  } catch (const std::exception& e) {
    std::cerr << "tabletop: internal error: " << e.what() << "\n";
    return kExitFailure;
  }
}
