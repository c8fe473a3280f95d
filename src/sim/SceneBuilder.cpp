#include "sim/SceneBuilder.h"

#include <map>

#include "physics/Cube.h"
#include "physics/Cylinder.h"
#include "physics/Seating.h"
#include "physics/SolidBox.h"
#include "physics/Sphere.h"
#include "scenario/ScenarioError.h"

namespace tabletop {
namespace {

// Bodies may touch at the start, not interpenetrate deeper than this.
constexpr double kOverlapTolerance = 1e-5;  // m

}  // namespace

std::unique_ptr<Shape> makeShape(const EntitySpec& e) {
  std::unique_ptr<Shape> shape;
  switch (e.shape) {
    case ShapeKind::Cube: shape = std::make_unique<Cube>(e.name, e.size.at(0)); break;
    case ShapeKind::Sphere: shape = std::make_unique<Sphere>(e.name, e.size.at(0)); break;
    case ShapeKind::SolidBox:
      shape = std::make_unique<SolidBox>(e.name, e.size.at(0), e.size.at(1), e.size.at(2));
      break;
    case ShapeKind::Cylinder:
      shape = std::make_unique<Cylinder>(e.name, e.size.at(0), e.size.at(1), e.size.at(2));
      break;
  }
  shape->setColour(e.colour);
  return shape;
}

std::unique_ptr<World> buildWorld(const Scenario& scenario, const Settings& settings) {
  auto world = std::make_unique<World>(settings, scenario.table);
  std::map<std::string, std::size_t> indexOf;
  for (const EntitySpec& e : scenario.entities) {
    indexOf[e.name] = indexOf.size();
    std::unique_ptr<Shape> shape = makeShape(e);
    btVector3 centre(e.position.x, e.position.y, e.position.z);
    // "on": the entity's lowest point rests on the top of what it names,
    // seated a hair into it (see Seating.h).
    if (e.on == "table") {
      centre.setY(seated(scenario.table.height + shape->below()));
    } else if (e.on == "ground") {
      centre.setY(seated(shape->below()));
    } else if (!e.on.empty()) {
      const Shape* base = world->find(e.on);
      centre.setY(seated(base->position().y() + base->above() + shape->below()));
    }
    world->addEntity(std::move(shape), e.mass, e.material, centre, e.yawDegrees);
  }

  std::vector<Problem> problems;
  // Blame the entity placed later: it was put where another already was.
  const auto rank = [&](const std::string& name) {
    auto it = indexOf.find(name);
    return it == indexOf.end() ? -1 : static_cast<long>(it->second);
  };
  for (const auto& [a, b] : world->overlaps(kOverlapTolerance)) {
    const bool aLater = rank(a) > rank(b);
    const std::string& entity = aLater ? a : b;
    const std::string& other = aLater ? b : a;
    problems.push_back({scenario.entities[indexOf[entity]].path + "/position",
                        "expected '" + entity + "' clear of other bodies at the start, but it overlaps " +
                            (rank(other) >= 0 ? "'" + other + "'" : "the " + other)});
  }
  if (!problems.empty()) throw ScenarioError(scenario.file, std::move(problems));
  return world;
}

}  // namespace tabletop
