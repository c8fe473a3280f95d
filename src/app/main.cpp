// tabletop: runs the report's scenes in Bullet from the command line.

#include <csignal>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/BenchCommand.h"
#include "app/CompareCommand.h"
#include "app/DataPaths.h"
#include "app/ListCommand.h"
#include "app/OptionChecks.h"
#include "app/PlainHelp.h"
#include "app/RenderCommand.h"
#include "app/RunCommand.h"
#include "app/SweepCommand.h"
#include "app/ViewCommand.h"

namespace {

// A subcommand on one scenario file with run's options (--json, the
// setting overrides, and --mode when `withMode`).
CLI::App* addScenarioCommand(CLI::App& app, const std::string& name, const std::string& help,
                             tabletop::RunOptions& run, bool withMode = true) {
  CLI::App* command = app.add_subcommand(name, help);
  command
      ->add_option_function<std::string>(
          "SCENARIO", [&run](const std::string& file) { run.scenarios.push_back({file, std::nullopt}); },
          "Scenario file (JSON), a pipe, - for standard input, or a shipped scene's name (tabletop list)")
      ->required();
  tabletop::addRunOptions(*command, run, withMode);
  return command;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tabletop;
  // A file size limit (ulimit -f) makes a write past it fail, as a full
  // disk does, instead of killing tabletop with a temporary left behind:
  // every output then fails whole, with its reason (and gnuplot and ffmpeg
  // inherit the same).
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "tabletop: the table-top scenes of S. Zou's report \"The Design of a 3D-Object Simulator\n"
      "Using Open-GL\" (Concordia, 2001) simulated with Bullet rigid-body physics."};
  app.formatter(std::make_shared<PlainHelp>());
  app.require_subcommand(1);
  app.set_version_flag("--version", versionLine(), "Print the version, the Bullet build (float or double) and where the shipped files are, then exit");
  int status = kExitOk;

  ListOptions list;
  CLI::App* listCommand = app.add_subcommand(
      "list", "List the shipped scenes: the names run, compare, render and view take from any folder");
  addListOptions(*listCommand, list);
  listCommand->callback([&] { status = listScenes(list, std::cout, std::cerr); });

  RunOptions run;
  std::vector<std::string> files;
  CLI::App* runCommand = app.add_subcommand(
      "run", "Run scenario files headless and print each entity's final state and the events");
  runCommand
      ->add_option("SCENARIO", files,
                   "Scenario files (JSON), pipes, - for standard input, or shipped scenes' names (tabletop list)")
      ->required();
  addRunOptions(*runCommand, run);
  runCommand->add_option("--out", run.outFile,
                         "Write the output to FILE instead of standard output (whole or not at all)");
  runCommand->add_option("--trace", run.traceFile,
                         "Write every entity's position, orientation and velocities after every step to "
                         "FILE (CSV, SI units; one scenario)");
  runCommand->add_option("--trace-max-mb", run.traceMaxMegabytes,
                         "The largest --trace file to write, in MB; a run that would write more writes none "
                         "(default 1024)")
      ->check(finiteRange(0.001, 1e6));
  runCommand->callback([&] {
    for (const std::string& f : files) run.scenarios.push_back({f, std::nullopt});
    status = runScenarios(run, std::cout, std::cerr);
  });

  CompareOptions compare;
  CLI::App* compareCommand = addScenarioCommand(
      app, "compare", "Run a scenario in the rules, compat and bullet modes and say where and why they differ",
      compare.run, false);
  compareCommand->add_option("--plot", compare.plot, "Write a top view of the trajectories (FILE.png or FILE.svg)");
  compareCommand->callback([&] { status = compareScenario(compare, std::cout, std::cerr); });

  RenderOptions render;
  CLI::App* renderCommand = addScenarioCommand(
      app, "render", "Render a scenario without a display (OSMesa) to PNG frames, and with --video to MP4 or GIF",
      render.run);
  renderCommand->remove_option(renderCommand->get_option("--json"));
  addRenderOptions(*renderCommand, render);
  renderCommand->callback([&] { status = renderScenario(render, std::cout, std::cerr); });

  ViewOptions view;
  CLI::App* viewCommand = addScenarioCommand(
      app, "view", "Open the report's window on a scenario: watch it, push entities with the keyboard (H: help)",
      view.run);
  viewCommand->remove_option(viewCommand->get_option("--json"));
  addViewOptions(*viewCommand, view);
  viewCommand->callback([&] { status = viewScenario(view, std::cerr); });

  BenchOptions bench;
  CLI::App* benchCommand = app.add_subcommand(
      "bench", "Measure speed against error: sweep timesteps and solver iterations over scenes, print the fronts");
  addBenchOptions(*benchCommand, bench);
  benchCommand->callback([&] { status = runBench(bench, std::cout, std::cerr); });

  SweepOptions sweep;
  CLI::App* sweepCommand = app.add_subcommand(
      "sweep", "Run a scene many times with parameters varied, in several modes, on every core: one table row per run");
  addSweepOptions(*sweepCommand, sweep);
  sweepCommand->callback([&] { status = runSweep(sweep, std::cout, std::cerr); });

  try {
    return parseAndRun(app, argc, argv, status);
  } catch (const std::exception& e) {
    std::cerr << "tabletop: internal error: " << e.what() << "\n";
    return kExitFailure;
  }
}
