#include "scenario/ScenarioLoader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "core/DirectionDef.h"
#include "core/EnumNames.h"
#include "core/Text.h"
#include "scenario/JsonFields.h"
#include "scenario/JsonLocator.h"
#include "scenario/JsonText.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioParts.h"

namespace tabletop {
namespace {

using namespace fields;
using namespace parts;

constexpr int kVersion = 1;

Scenario read(const json& root, std::vector<Problem>& problems) {
  Scenario s;
  Fields f(root, "", problems);
  if (!f.valid()) return s;

  if (const json* v = f.get("version", true)) {
    if (!v->is_number_integer() || v->get<long long>() != kVersion) {
      f.fail("/version", "expected " + std::to_string(kVersion) + ", got " + shown(*v));
    }
  }
  s.name = f.string("name", "", true, ScenarioLoader::kMaxNameBytes * 2);
  s.description = f.has("description") ? f.string("description", "") : "";
  if (const json* t = f.get("table", false)) s.table = readTable(*t, problems);
  if (const json* st = f.get("settings", false)) s.settings = readSettings(*st, problems);
  if (const json* g = f.get("ground", false)) {
    Fields gf(*g, "/ground", problems);
    s.ground = readMaterial(gf, "material", s.ground, problems);
    gf.finish();
  }

  NameIndex names;
  NameIndex normalised;  // each name in Unicode NFC: equal ones are the same name
  if (const json* list = f.get("entities", true)) {
    if (!list->is_array() || list->empty()) {
      f.fail("/entities", "expected a non-empty array of entities, got " + shown(*list));
    } else if (list->size() > ScenarioLoader::kMaxEntities) {
      f.fail("/entities", "expected at most " + std::to_string(ScenarioLoader::kMaxEntities) + " entities, got " +
                              std::to_string(list->size()));
    } else {
      s.entities.reserve(list->size());
      std::vector<bool> sized;  // per entity read, as readEntity says
      for (std::size_t i = 0; i < list->size(); ++i) {
        bool hasSize = false;
        EntitySpec e = readEntity((*list)[i], "/entities/" + std::to_string(i), names, problems, hasSize);
        checkOverTable(e, s.table, problems);
        const auto base = names.find(e.on.entityName());
        if (base != names.end() && sized[base->second]) checkOverBase(e, s.entities[base->second], problems);
        sized.push_back(hasSize);
        if (!e.name.empty()) {
          const auto same = normalised.emplace(nfc(e.name), s.entities.size());
          if (!same.second && !names.count(e.name)) {
            f.fail(e.path + "/name", "expected a unique name, but " + quotedName(e.name) + " is the same name as " +
                                         quotedName(s.entities[same.first->second].name) +
                                         " (/entities/" + std::to_string(same.first->second) +
                                         ") in Unicode normalization form C (NFC)");
          }
          names.emplace(e.name, s.entities.size());
        }
        s.entities.push_back(std::move(e));
      }
    }
  }

  if (const json* list = f.get("script", false)) {
    if (!list->is_array()) {
      f.fail("/script", "expected an array of actions, got " + shown(*list));
    } else if (list->size() > ScenarioLoader::kMaxActions) {
      f.fail("/script", "expected at most " + std::to_string(ScenarioLoader::kMaxActions) + " actions, got " +
                            std::to_string(list->size()));
    } else {
      double lastTime = 0.0;
      for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string path = "/script/" + std::to_string(i);
        s.script.push_back(readAction((*list)[i], path, names, problems));
        if (const auto& at = s.script.back().at) {
          if (*at < lastTime) {
            f.fail(path + "/t", "expected a time not before the previous action's (" +
                                    std::to_string(lastTime) + " s), got " + std::to_string(*at));
          }
          if (*at > s.settings.duration) {
            f.fail(path + "/t", "expected a time within the duration (" +
                                    std::to_string(s.settings.duration) + " s), got " + std::to_string(*at));
          }
          lastTime = std::max(lastTime, *at);
        }
      }
    }
  }
  f.finish();
  if (const std::string big = ScenarioLoader::runSizeProblem(s.settings, s.entities.size()); !big.empty()) {
    f.fail(f.has("settings") ? "/settings/duration" : "/entities", big);
  }
  return s;
}

}  // namespace

std::string ScenarioLoader::runSizeProblem(const Settings& settings, std::size_t entities) {
  const double steps = std::ceil(settings.duration / settings.timestep);
  if (!(steps <= kMaxSteps)) {
    return "expected at most " + number(kMaxSteps) + " steps (duration / timestep), got " + number(steps);
  }
  return workProblem(steps, settings, entities);
}

std::string ScenarioLoader::workProblem(double steps, const Settings& settings, std::size_t entities) {
  const double work = steps * settings.maxSubsteps * settings.iterations * static_cast<double>(entities);
  if (!(work <= kMaxWork)) {
    return "expected at most " + number(kMaxWork) + " solver work (steps x max_substeps x iterations x entities), got " +
           number(work) + ": shorten the duration, or lower max_substeps or iterations";
  }
  return "";
}

Scenario ScenarioLoader::loadText(const std::string& text, const std::string& source) {
  JsonText parsed = parseJsonText(text, source, kMaxFileBytes, kMaxDepth);
  const json& root = parsed.root;
  auto locator = std::move(parsed.locator);
  std::vector<Problem> problems = duplicateProblems(*locator);
  Scenario s = read(root, problems);
  s.file = source;
  s.locator = std::move(locator);
  s.text = std::make_shared<const std::string>(text);
  if (!problems.empty()) throw ScenarioError(s, std::move(problems));
  return s;
}

std::string ScenarioLoader::sourceName(const std::string& path) {
  return path == "-" ? "<stdin>" : path;
}

Scenario ScenarioLoader::loadFile(const std::string& path) {
  return loadText(readTextFile(path, kMaxFileBytes), sourceName(path));
}

}  // namespace tabletop
