#include "app/ListCommand.h"

#include <algorithm>
#include <iostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/DataPaths.h"
#include "app/RunCommand.h"
#include "core/Text.h"
#include "scenario/ShippedScenes.h"

namespace tabletop {

void addListOptions(CLI::App& command, ListOptions& options) {
  command.add_flag("--json", options.json, "Print the scenes as JSON: each one's name, description and file");
}

int listScenes(const ListOptions& options, std::ostream& out, std::ostream& err) {
  const std::string folder = shippedScenarios();
  const std::vector<ShippedScene> scenes = listShippedScenes(folder);
  if (scenes.empty()) {
    err << "tabletop list: no scenes in '" << shownText(folder, 256)
        << "' (tabletop --version names the data folder; TABLETOP_DATA_DIR sets it)\n";
    return kExitFailure;
  }
  if (options.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const ShippedScene& s : scenes) {
      list.push_back({{"name", s.name}, {"description", s.description}, {"file", s.file}, {"loads", s.loads}});
    }
    const nlohmann::json document{{"format_version", 1}, {"scenes", list}};
    out << document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return kExitOk;
  }
  // The names in one column, as wide as the longest.
  std::size_t width = 0;
  for (const ShippedScene& s : scenes) width = std::max(width, s.name.size());
  for (const ShippedScene& s : scenes) {
    const std::string about = s.loads ? shownText(s.description, 200) : "(refused: tabletop run " + s.name + " says why)";
    out << (about.empty() ? s.name : padded(s.name, width + 2) + about) << "\n";
  }
  return kExitOk;
}

}  // namespace tabletop
