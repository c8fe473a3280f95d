#pragma once

#include <iosfwd>

namespace CLI {
class App;
}

namespace tabletop {

/// What `tabletop list` was asked to do.
struct ListOptions {
  bool json = false;  ///< --json: one document instead of a line per scene
};

/// Declares list's options on `command`.
void addListOptions(CLI::App& command, ListOptions& options);

/// Prints the shipped scenes (listShippedScenes, scenario/ShippedScenes.h),
/// a line each: the name run, view, render and compare take from any
/// folder, and the scene's description. With --json, one document:
/// {"format_version": 1, "scenes": [{"name", "description", "file",
/// "loads"}]}. No scene in the data folder is kExitFailure, said in one
/// line on `err`.
int listScenes(const ListOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tabletop
