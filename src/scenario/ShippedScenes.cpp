#include "scenario/ShippedScenes.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/Text.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"

namespace tabletop {
namespace {

constexpr std::string_view kSuffix = ".json";

bool isNameCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

// `name` without its .json, if it has one.
std::string_view stem(const std::string& name) {
  std::string_view s(name);
  if (endsWith(s, kSuffix)) s.remove_suffix(kSuffix.size());
  return s;
}

bool exists(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0;
}

}  // namespace

std::string dataFolder(const std::string& installed, const std::string& built) {
  if (const char* dir = std::getenv("TABLETOP_DATA_DIR"); dir && *dir) return dir;
  std::error_code ec;
  if (!installed.empty() && std::filesystem::is_directory(std::filesystem::path(installed) / "scenarios", ec)) {
    return installed;
  }
  return built;
}

std::string sceneNameProblem(const std::string& name) {
  if (name.size() > kMaxSceneNameBytes) {
    return "expected at most " + std::to_string(kMaxSceneNameBytes) + " bytes, got " + std::to_string(name.size());
  }
  // Part by part, so that ".." is named as what it is.
  const std::string_view s = stem(name);
  const std::string expected = "expected letters, digits, _ and - in parts split by /, got '" + shownText(name, 40) + "'";
  std::size_t start = 0;
  while (true) {
    const std::size_t end = std::min(s.find('/', start), s.size());
    const std::string_view part = s.substr(start, end - start);
    if (part == "..") return "expected no '..' part, got '" + shownText(name, 40) + "'";
    if (part.empty() || !std::all_of(part.begin(), part.end(), isNameCharacter)) return expected;
    if (end == s.size()) return "";
    start = end + 1;
  }
}

std::string shippedScenePath(const std::string& folder, const std::string& name) {
  return folder + "/" + std::string(stem(name)) + std::string(kSuffix);
}

std::string sceneFile(const std::string& argument, const std::string& folder, const std::string& listedBy) {
  // Files win: a scene's name is looked up only when nothing by that name
  // is here. An absolute path is a file's, found or not.
  if (argument.empty() || argument == "-" || argument.front() == '/' || exists(argument)) return argument;
  const std::string cannot = "cannot open the file for reading";
  if (const std::string problem = sceneNameProblem(argument); !problem.empty()) {
    throw ScenarioError(argument, {{"", cannot + "; as a shipped scene's name, " + problem}});
  }
  const std::string path = shippedScenePath(folder, argument);
  if (!exists(path)) {
    throw ScenarioError(argument,
                        {{"", cannot + ", and no shipped scene has that name (" + listedBy + " names them)"}});
  }
  return path;
}

std::vector<ShippedScene> listShippedScenes(const std::string& folder) {
  std::vector<ShippedScene> scenes;
  namespace fs = std::filesystem;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec) || it->path().extension().string() != kSuffix) continue;
    ShippedScene scene;
    scene.name = it->path().lexically_relative(folder).generic_string();
    if (!sceneNameProblem(scene.name).empty()) continue;  // a name no one could pass back
    scene.name = std::string(stem(scene.name));
    scene.file = shippedScenePath(folder, scene.name);
    try {
      scene.description = ScenarioLoader::loadFile(scene.file).description;
    } catch (const ScenarioError&) {
      scene.loads = false;
    }
    scenes.push_back(std::move(scene));
  }
  // Those at the top first, then each subfolder's.
  const auto depth = [](const ShippedScene& s) { return std::count(s.name.begin(), s.name.end(), '/'); };
  std::sort(scenes.begin(), scenes.end(), [&depth](const ShippedScene& a, const ShippedScene& b) {
    return depth(a) != depth(b) ? depth(a) < depth(b) : a.name < b.name;
  });
  return scenes;
}

}  // namespace tabletop
