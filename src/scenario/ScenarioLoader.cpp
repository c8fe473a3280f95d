#include "scenario/ScenarioLoader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <unordered_map>

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "core/DirectionDef.h"
#include "core/EnumNames.h"
#include "core/Text.h"
#include "scenario/JsonFields.h"
#include "scenario/JsonLocator.h"
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
        if (!e.name.empty()) names.emplace(e.name, s.entities.size());
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

// The 1-based line and column of a byte offset in `text` (a byte order
// mark, which the parser skips, is not counted).
void locate(Problem& p, const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::size_t lineStart = offset == 0 ? 0 : text.rfind('\n', offset - 1) + 1;
  if (lineStart == 0 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) lineStart = std::min<std::size_t>(3, offset);
  p.line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
  p.column = static_cast<int>(offset - lineStart) + 1;
}

// What follows nlohmann's "[json.exception.parse_error.101] parse error at
// line 3, column 5: " (or its other exceptions' "[json.exception...] ").
std::string reason(const std::string& what) {
  const std::size_t colon = what.find(": ", what.find("parse error"));
  if (what.find("parse error") != std::string::npos && colon != std::string::npos) {
    return what.substr(colon + 2);
  }
  const std::size_t close = what.find("] ");
  return close == std::string::npos ? what : what.substr(close + 2);
}

Problem parseProblem(const json::parse_error& e, const std::string& text) {
  Problem p{"", "not valid JSON: " + reason(e.what())};
  locate(p, text, e.byte == 0 ? 0 : e.byte - 1);
  return p;
}

// Other parser failures (a number too large for a double) give no
// position; the offending token, which the message quotes, is found among
// the text's tokens instead (not in a comment or a string).
Problem valueProblem(const json::exception& e, const std::string& text) {
  Problem p{"", "not valid JSON: " + reason(e.what())};
  const std::size_t open = p.message.find('\'');
  const std::size_t close = p.message.find('\'', open + 1);
  if (open != std::string::npos && close != std::string::npos) {
    const auto where = JsonLocator::findToken(text, p.message.substr(open + 1, close - open - 1));
    if (where) {
      p.line = where->line;
      p.column = where->column;
    }
  }
  return p;
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
  if (text.size() > kMaxFileBytes) {
    throw ScenarioError(source, {{"", "expected at most " + std::to_string(kMaxFileBytes) + " bytes, got " +
                                          std::to_string(text.size())}});
  }
  // nlohmann's parser stops at a NUL byte as at the end of the text, and
  // would accept what comes before it.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
    Problem p{"", "not valid JSON: expected text, got a NUL byte"};
    locate(p, text, nul);
    throw ScenarioError(source, {p});
  }
  // Deep nesting is refused before anything recurses into it (showing a
  // value, the locator).
  if (const auto deep = JsonLocator::tooDeep(text, kMaxDepth)) {
    Problem p{"", "expected arrays and objects nested at most " + std::to_string(kMaxDepth) + " deep"};
    p.line = deep->line;
    p.column = deep->column;
    throw ScenarioError(source, {p});
  }
  json root;
  try {
    root = json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw ScenarioError(source, {parseProblem(e, text)});
  } catch (const json::exception& e) {
    throw ScenarioError(source, {valueProblem(e, text)});
  }
  auto locator = std::make_shared<const JsonLocator>(text);
  std::vector<Problem> problems;
  // The parser keeps the last of two values under one key, silently.
  for (const JsonLocator::Duplicate& d : locator->duplicates()) {
    problems.push_back({d.pointer,
                        "expected each key once in an object, but it was given already at line " +
                            std::to_string(d.first.line) + ", column " + std::to_string(d.first.column),
                        d.later.line, d.later.column});
  }
  Scenario s = read(root, problems);
  s.file = source;
  s.locator = std::move(locator);
  if (!problems.empty()) throw ScenarioError(s, std::move(problems));
  return s;
}

Scenario ScenarioLoader::loadFile(const std::string& path) {
  // Only a regular file of bounded size is read: not a directory, a device
  // (/dev/zero never ends) or a pipe.
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw ScenarioError(path, {{"", "cannot open the file for reading"}});
  if (!S_ISREG(info.st_mode)) throw ScenarioError(path, {{"", "expected a regular file"}});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(path, {{"", "cannot open the file for reading"}});
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= kMaxFileBytes && (in.read(chunk, sizeof chunk) || in.gcount() > 0)) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw ScenarioError(path, {{"", "cannot read the file"}});
  return loadText(text, path);
}

}  // namespace tabletop
