#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tabletop {

/// The scenes shipped with tabletop, known by name: "hard/pyramid_55" (or
/// "hard/pyramid_55.json") is hard/pyramid_55.json under the data folder's
/// scenarios/. The one home of that rule, for the command line, the Python
/// module and sweep specs. A name may come from anyone, so it is checked
/// before it is joined to the folder (no ".." part, nothing absolute,
/// bounded) and it is never given to a shell. Each caller finds its own
/// folder (app/DataPaths.h for the programs) through dataFolder().

/// The longest name taken, in bytes.
constexpr std::size_t kMaxSceneNameBytes = 256;

/// One shipped scene, as `tabletop list` shows it.
struct ShippedScene {
  std::string name;         ///< as it is passed: "example2_two_cubes", "hard/tall_stack_10"
  std::string file;         ///< its path: the folder, then the name and .json
  std::string description;  ///< the file's own "description", "" if it has none
  bool loads = true;        ///< false when the loader refuses the file (run names why)
};

/// Where tabletop's own files are: the folder TABLETOP_DATA_DIR names if
/// set; else `installed` if it holds scenarios/ (an installed program's
/// PREFIX/share/tabletop); else `built`, the source tree it was built from.
std::string dataFolder(const std::string& installed, const std::string& built);

/// Why `name` cannot name a shipped scene, as "expected ..., got ..."; ""
/// when it can: at most kMaxSceneNameBytes of letters, digits, _ and - in
/// parts split by single slashes, no part "..", optionally ending ".json".
std::string sceneNameProblem(const std::string& name);

/// The file of the shipped scene `name` (one sceneNameProblem accepts) in
/// `folder`, whether or not it exists.
std::string shippedScenePath(const std::string& folder, const std::string& name);

/// What to read for a scene given by a user: `argument` itself when it is
/// something on disk (files win), "-" (standard input) or an absolute
/// path; else the shipped scene of that name in `folder`. Anything else is
/// a ScenarioError of one line naming `argument`, which says that no file
/// and no shipped scene has that name and that `listedBy` lists them.
std::string sceneFile(const std::string& argument, const std::string& folder, const std::string& listedBy);

/// Every scene in `folder` and its subfolders whose name can be passed,
/// with its description: those at the top first, then each subfolder's,
/// by name. A file the loader refuses is listed with loads false.
std::vector<ShippedScene> listShippedScenes(const std::string& folder);

}  // namespace tabletop
