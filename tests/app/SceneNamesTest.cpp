// Shipped scenes by name from any folder: `tabletop list` names every
// scene under scenarios/, and run, compare and render take those names
// where no file has them; a missing or '..' name is one located line.

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/CommandLine.h"

namespace {

using namespace tabletop::testing;

// `tabletop ARGS` run from `folder`.
Outcome runIn(const std::string& folder, const std::string& args) {
  return run("cd '" + folder + "' && " + kBin + "tabletop " + args);
}

// Every scene file under scenarios/, by the name it is passed as:
// "example2_two_cubes", "hard/pyramid_55".
std::set<std::string> shippedNames() {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kScenarios)) {
    if (e.is_regular_file() && e.path().extension() == ".json") {
      std::filesystem::path name = e.path().lexically_relative(kScenarios);
      names.insert(name.replace_extension().generic_string());
    }
  }
  return names;
}

TEST(SceneNames, RunTakesAShippedSceneByNameFromAnyFolder) {
  const TempFolder folder("scene_names_run");
  const Outcome byPath = run(kBin + "tabletop run " + kScenarios + "example2_two_cubes.json --json");
  ASSERT_EQ(byPath.status, 0) << byPath.err;
  const std::string hash = nlohmann::json::parse(byPath.out)["runs"][0]["state_hash"];
  for (const std::string name : {"example2_two_cubes", "example2_two_cubes.json"}) {
    const Outcome o = runIn(folder.path(), "run " + name + " --json");
    ASSERT_EQ(o.status, 0) << name << ": " << o.err;
    EXPECT_EQ(nlohmann::json::parse(o.out)["runs"][0]["state_hash"], hash) << name;
  }
  // A subfolder's scene, and several at once.
  const Outcome o = runIn(folder.path(), "run hard/tiny_cube analytic/free_flight.json --duration 0.2");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("tiny_cube  ("), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("free_flight  ("), std::string::npos) << o.out;
}

TEST(SceneNames, CompareAndRenderTakeNamesToo) {
  const TempFolder folder("scene_names_modes");
  Outcome o = runIn(folder.path(), "compare example2_two_cubes");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("rules, compat and bullet"), std::string::npos) << o.out;
  o = runIn(folder.path(), "render example1_single_cube --at 0 --size 64x48 --out-dir frames");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(folder.path() + "/frames/t_0.000.png"));
}

// Something on disk by that name is read, not the shipped scene.
TEST(SceneNames, AFileWinsOverAShippedName) {
  const TempFolder folder("scene_names_file");
  std::ofstream(folder.path() + "/example2_two_cubes") << R"({"version": 1, "name": "mine",
    "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})";
  const Outcome o = runIn(folder.path(), "run example2_two_cubes");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out.rfind("mine  (example2_two_cubes)", 0), 0u) << o.out;
}

TEST(SceneNames, NoFileAndNoSceneIsOneLocatedLine) {
  const TempFolder folder("scene_names_missing");
  for (const std::string command : {"run", "compare", "render --out-dir frames"}) {
    const Outcome o = runIn(folder.path(), command + " hard/no_such_scene");
    EXPECT_EQ(o.status, 2) << command;
    EXPECT_EQ(o.err,
              "hard/no_such_scene: cannot open the file for reading, and no shipped scene has that name "
              "(tabletop list names them)\n")
        << command;
  }
  // An absolute path is a file's, found or not.
  const Outcome o = runIn(folder.path(), "run /no/such/example2_two_cubes.json");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "/no/such/example2_two_cubes.json: cannot open the file for reading\n");
}

// A name never leaves the data folder, and is never given to a shell.
TEST(SceneNames, DotDotAndOtherHostileNamesAreRefused) {
  const TempFolder folder("scene_names_hostile");
  for (const std::string name : {"hard/../example2_two_cubes", "../scenarios/example2_two_cubes"}) {
    const Outcome o = runIn(folder.path(), "run " + name);
    EXPECT_EQ(o.status, 2) << name;
    EXPECT_EQ(o.err, name + ": cannot open the file for reading; as a shipped scene's name, expected no '..' part, "
                            "got '" + name + "'\n");
  }
  const std::string marker = folder.path() + "/ran";
  Outcome o = runArgs({"run", "$(touch " + marker + ")"});
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("as a shipped scene's name, expected letters, digits, _ and - in parts split by /"),
            std::string::npos)
      << o.err;
  EXPECT_FALSE(std::filesystem::exists(marker));
  o = runArgs({"run", std::string(300, 'a')});
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("expected at most 256 bytes, got 300"), std::string::npos) << o.err;
}

// The list is the folder: every .json under scenarios/, by its name, a
// line each, and the same names in --json with their files.
TEST(SceneNames, ListNamesEveryShippedScene) {
  const TempFolder folder("scene_names_list");
  const std::set<std::string> names = shippedNames();
  ASSERT_GT(names.size(), 20u);
  const Outcome text = runIn(folder.path(), "list");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(lineCount(text.out), static_cast<int>(names.size())) << text.out;
  std::set<std::string> listed;
  std::istringstream lines(text.out);
  for (std::string line; std::getline(lines, line);) listed.insert(line.substr(0, line.find(' ')));
  EXPECT_EQ(listed, names);
  EXPECT_NE(text.out.find("\nhard/pyramid_55 "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("Cube A pushed into cube B; A pushes B off the right edge.\n"), std::string::npos);

  const Outcome json = runIn(folder.path(), "list --json");
  ASSERT_EQ(json.status, 0) << json.err;
  const nlohmann::json document = nlohmann::json::parse(json.out);
  EXPECT_EQ(document["format_version"], 1);
  std::set<std::string> inJson;
  for (const nlohmann::json& scene : document["scenes"]) {
    inJson.insert(scene["name"].get<std::string>());
    EXPECT_TRUE(scene["loads"]) << scene;
    EXPECT_FALSE(scene["description"].get<std::string>().empty()) << scene;
    EXPECT_EQ(std::filesystem::canonical(scene["file"].get<std::string>()),
              std::filesystem::canonical(kScenarios + scene["name"].get<std::string>() + ".json"));
  }
  EXPECT_EQ(inJson, names);
}

}  // namespace
