// Shipped scenes by name: which names are taken, what a name resolves to
// (files win, nothing outside the folder), the one-line refusals, the
// list, and where the data folder is.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "scenario/ScenarioError.h"
#include "scenario/ShippedScenes.h"
#include "support/TempFiles.h"

namespace tabletop {
namespace {

using testing::TempFolder;

const std::string kScene = R"({"version": 1, "name": "NAME", "description": "ABOUT",
  "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})";

// A scene file at `folder`/`name` with its name and description.
void writeScene(const std::string& folder, const std::string& name, const std::string& about) {
  const std::filesystem::path file = std::filesystem::path(folder) / name;
  std::filesystem::create_directories(file.parent_path());
  std::string text = kScene;
  text.replace(text.find("NAME"), 4, file.stem().string());
  text.replace(text.find("ABOUT"), 5, about);
  std::ofstream(file) << text;
}

// The one line sceneFile refuses `argument` with.
std::string refusal(const std::string& argument, const std::string& folder) {
  try {
    sceneFile(argument, folder, "LIST");
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.lines().size(), 1u);
    return e.lines().front();
  }
  return "(taken)";
}

TEST(ShippedScenes, NamesAreLettersDigitsUnderscoresAndDashesInParts) {
  for (const std::string name : {"example2_two_cubes", "hard/pyramid_55", "hard/pyramid_55.json", "a-b/c_D/9"}) {
    EXPECT_EQ(sceneNameProblem(name), "") << name;
  }
  for (const std::string name : {"", ".json", "/etc/passwd", "a//b", "hard/", "./a", "a b", "a;rm -rf x", "a$(x)",
                                 "a\\b", "a.b", "hard\n"}) {
    EXPECT_NE(sceneNameProblem(name).find("expected letters, digits, _ and - in parts split by /"),
              std::string::npos)
        << name;
  }
  for (const std::string name : {"..", "../x", "hard/../example1", "a/..", "../../etc/passwd.json"}) {
    EXPECT_NE(sceneNameProblem(name).find("expected no '..' part"), std::string::npos) << name;
  }
  EXPECT_EQ(sceneNameProblem(std::string(kMaxSceneNameBytes, 'a')), "");
  EXPECT_EQ(sceneNameProblem(std::string(kMaxSceneNameBytes + 1, 'a')),
            "expected at most 256 bytes, got " + std::to_string(kMaxSceneNameBytes + 1));
  EXPECT_EQ(shippedScenePath("F", "hard/x.json"), "F/hard/x.json");
  EXPECT_EQ(shippedScenePath("F", "hard/x"), "F/hard/x.json");
}

TEST(ShippedScenes, AFileWinsThenANameThenAOneLineRefusal) {
  const TempFolder folder("shipped_names");
  const std::string& dir = folder.path();
  writeScene(dir, "a.json", "first");
  writeScene(dir, "sub/b.json", "second");
  // Something on disk, standard input, and any absolute path are files.
  EXPECT_EQ(sceneFile(dir + "/a.json", dir, "LIST"), dir + "/a.json");
  EXPECT_EQ(sceneFile("-", dir, "LIST"), "-");
  EXPECT_EQ(sceneFile("/no/such/file.json", dir, "LIST"), "/no/such/file.json");
  EXPECT_EQ(sceneFile(".", dir, "LIST"), ".") << "a folder is something on disk; the loader refuses it";
  // Else a shipped scene's name, with or without .json.
  EXPECT_EQ(sceneFile("a", dir, "LIST"), dir + "/a.json");
  EXPECT_EQ(sceneFile("sub/b.json", dir, "LIST"), dir + "/sub/b.json");
  // Else one line naming the argument, and what lists the names.
  EXPECT_EQ(refusal("nosuch", dir),
            "nosuch: cannot open the file for reading, and no shipped scene has that name (LIST names them)");
  EXPECT_EQ(refusal("sub/../a", dir),
            "sub/../a: cannot open the file for reading; as a shipped scene's name, expected no '..' part, got "
            "'sub/../a'");
  EXPECT_NE(refusal("a b", dir).find("a b: cannot open the file for reading; as a shipped scene's name, expected "
                                     "letters"),
            std::string::npos);
}

TEST(ShippedScenes, TheListHasEverySceneTopFirstWithItsDescription) {
  const TempFolder folder("shipped_list");
  const std::string& dir = folder.path();
  writeScene(dir, "z.json", "at the top");
  writeScene(dir, "hard/b.json", "in a subfolder");
  writeScene(dir, "analytic/a.json", "");
  std::ofstream(dir + "/broken.json") << "{";
  std::ofstream(dir + "/not a name.json") << kScene;  // no one could pass it back
  std::ofstream(dir + "/notes.txt") << "not a scene";
  const std::vector<ShippedScene> scenes = listShippedScenes(dir);
  ASSERT_EQ(scenes.size(), 4u);
  EXPECT_EQ(scenes[0].name, "broken");
  EXPECT_FALSE(scenes[0].loads);
  EXPECT_EQ(scenes[1].name, "z");
  EXPECT_EQ(scenes[1].description, "at the top");
  EXPECT_EQ(scenes[1].file, dir + "/z.json");
  EXPECT_TRUE(scenes[1].loads);
  EXPECT_EQ(scenes[2].name, "analytic/a");
  EXPECT_EQ(scenes[2].description, "");
  EXPECT_EQ(scenes[3].name, "hard/b");
  EXPECT_EQ(scenes[3].description, "in a subfolder");
  EXPECT_TRUE(listShippedScenes(dir + "/absent").empty());
}

// TABLETOP_DATA_DIR wins; else an installed folder holding scenarios/;
// else the source tree.
TEST(ShippedScenes, TheDataFolderIsTheEnvironmentsThenTheInstalledThenTheBuilt) {
  const char* before = std::getenv("TABLETOP_DATA_DIR");
  const std::optional<std::string> saved = before ? std::optional<std::string>(before) : std::nullopt;
  const TempFolder installed("shipped_installed");
  ::unsetenv("TABLETOP_DATA_DIR");
  EXPECT_EQ(dataFolder(installed.path(), "BUILT"), "BUILT") << "no scenarios/ in it";
  std::filesystem::create_directories(installed.path() + "/scenarios");
  EXPECT_EQ(dataFolder(installed.path(), "BUILT"), installed.path());
  EXPECT_EQ(dataFolder("", "BUILT"), "BUILT");
  ::setenv("TABLETOP_DATA_DIR", "CHOSEN", 1);
  EXPECT_EQ(dataFolder(installed.path(), "BUILT"), "CHOSEN");
  if (saved) {
    ::setenv("TABLETOP_DATA_DIR", saved->c_str(), 1);
  } else {
    ::unsetenv("TABLETOP_DATA_DIR");
  }
}

}  // namespace
}  // namespace tabletop
