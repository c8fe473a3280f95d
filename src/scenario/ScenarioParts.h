#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/JsonFields.h"
#include "scenario/Scenario.h"
#include "scenario/ScenarioError.h"

/// The readers of a scenario file's parts, each checking its fields and
/// adding a located Problem for each it refuses (ScenarioLoader puts them
/// together). The bounds of every quantity are in ScenarioParts.cpp.
namespace tabletop::parts {

// The entities read so far, by name, so that each lookup costs O(1) and a
// file of n entities loads in O(n).
using NameIndex = std::unordered_map<std::string, std::size_t>;

Material readMaterial(fields::Fields& parent, const std::string& key, Material m, std::vector<Problem>& problems);
TableSpec readTable(const nlohmann::json& j, std::vector<Problem>& problems);
Settings readSettings(const nlohmann::json& j, std::vector<Problem>& problems);

/// One entity at `path`; `earlier` holds those before it. `sized`: whether
/// its shape and size were read (else its geometry is the default, and
/// nothing is checked against it).
EntitySpec readEntity(const nlohmann::json& j, const std::string& path, const NameIndex& earlier,
                      std::vector<Problem>& problems, bool& sized);
Action readAction(const nlohmann::json& j, const std::string& path, const NameIndex& entities,
                  std::vector<Problem>& problems);

/// An entity set on the table starts with its centre over the top.
void checkOverTable(const EntitySpec& e, const TableSpec& t, std::vector<Problem>& problems);
/// An entity set on another starts with its centre over the other's top.
void checkOverBase(const EntitySpec& e, const EntitySpec& base, std::vector<Problem>& problems);

}  // namespace tabletop::parts
