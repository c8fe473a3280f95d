#include "sim/SceneBuilder.h"

#include <map>

#include "compat/CompatWorld.h"
#include "physics/shapes/Cube.h"
#include "physics/shapes/Cylinder.h"
#include "physics/shapes/Seating.h"
#include "physics/shapes/SolidBox.h"
#include "physics/shapes/Sphere.h"
#include "rules/ReportContactFinder.h"
#include "rules/RuleEngine.h"
#include "scenario/ScenarioError.h"

namespace tabletop {
namespace {

// Bodies may touch at the start, not interpenetrate deeper than this.
constexpr double kOverlapTolerance = 1e-5;  // m

}  // namespace

std::unique_ptr<Shape> makeShape(const EntitySpec& e) {
  std::unique_ptr<Shape> shape;
  const ShapeGeometry g = e.geometry;
  switch (g.kind()) {
    case ShapeKind::Cube: shape = std::make_unique<Cube>(e.name, g.side()); break;
    case ShapeKind::Sphere: shape = std::make_unique<Sphere>(e.name, g.radius()); break;
    case ShapeKind::SolidBox: shape = std::make_unique<SolidBox>(e.name, g.width(), g.boxHeight(), g.depth()); break;
    case ShapeKind::Cylinder: shape = std::make_unique<Cylinder>(e.name, g.radius(), g.topRadius(), g.height()); break;
  }
  shape->setColour(e.colour);
  return shape;
}

std::unique_ptr<World> buildWorld(const Scenario& scenario, const Settings& settings) {
  auto world = std::make_unique<World>(settings, scenario.table, scenario.ground);
  std::map<Support, std::size_t> indexOf;  // each entity's place in the file
  for (const EntitySpec& e : scenario.entities) {
    indexOf[Support::entity(e.name)] = indexOf.size();
    std::unique_ptr<Shape> shape = makeShape(e);
    btVector3 centre(e.position.x, e.position.y, e.position.z);
    const double below = e.orientation ? e.geometry.below(*e.orientation) : shape->below();
    // "on": the entity's lowest point rests on the top of what it names,
    // seated a hair into it (see Seating.h).
    switch (e.on.kind()) {
      case Support::Kind::Table: centre.setY(seated(scenario.table.height + below)); break;
      case Support::Kind::Ground: centre.setY(seated(below)); break;
      case Support::Kind::Entity: {
        const Shape* base = world->find(e.on.entityName());
        centre.setY(seated(base->position().y() + base->above() + below));
        break;
      }
      case Support::Kind::None: break;
    }
    const auto& q = e.orientation;
    btRigidBody* body =
        (q ? world->addEntity(std::move(shape), e.mass, e.material, centre, btQuaternion(q->x, q->y, q->z, q->w))
           : world->addEntity(std::move(shape), e.mass, e.material, centre, e.yawDegrees))
            .body();
    body->setLinearVelocity(btVector3(e.velocity.x, e.velocity.y, e.velocity.z));
    body->setAngularVelocity(btVector3(e.spin.x, e.spin.y, e.spin.z));
  }

  std::vector<Problem> problems;
  // Blame the entity placed later: it was put where another already was.
  const auto rank = [&](const Support& s) {
    auto it = indexOf.find(s);
    return it == indexOf.end() ? -1 : static_cast<long>(it->second);
  };
  for (const auto& [a, b] : world->overlaps(kOverlapTolerance)) {
    const bool aLater = rank(a) > rank(b);
    const Support& entity = aLater ? a : b;
    const Support& other = aLater ? b : a;
    problems.push_back({scenario.entities[indexOf[entity]].path + "/position",
                        "expected '" + entity.name() + "' clear of other bodies at the start, but it overlaps " +
                            (other.isEntity() ? "'" + other.name() + "'" : "the " + other.name())});
  }
  if (!problems.empty()) throw ScenarioError(scenario, std::move(problems));
  // On the contacts just found: a snapshot before the first step shows
  // what holds each entity up and its status.
  world->look();
  return world;
}

std::vector<rules::RuleBody> buildRuleBodies(const Scenario& scenario) {
  std::vector<rules::RuleBody> bodies;
  std::map<std::string, int> indexOf;
  for (const EntitySpec& e : scenario.entities) {
    // The rules need only the geometry: no Bullet shape is made.
    const ShapeGeometry g = e.geometry;
    rules::RuleBody b;
    b.name = e.name;
    b.shape = e.geometry.kind();
    b.halfExtents = g.halfExtents();
    b.below = g.below();
    b.above = g.above();
    b.position = e.position;
    b.yawDegrees = e.yawDegrees;
    b.support = rules::kOnNothing;
    switch (e.on.kind()) {
      case Support::Kind::Table:
        b.position.y = scenario.table.height + b.below;
        b.support = rules::kOnTable;
        break;
      case Support::Kind::Ground:
        b.position.y = b.below;
        b.support = rules::kOnGround;
        break;
      case Support::Kind::Entity: {
        const int base = indexOf.at(e.on.entityName());
        b.position.y = bodies[static_cast<std::size_t>(base)].top() + b.below;
        b.support = base;
        break;
      }
      case Support::Kind::None: break;
    }
    indexOf[e.name] = static_cast<int>(bodies.size());
    bodies.push_back(b);
  }
  return bodies;
}

std::unique_ptr<Simulation> buildSimulation(const Scenario& scenario, const Settings& settings,
                                            SimulationMode mode) {
  if (mode != SimulationMode::Bullet) {
    // The report's rules start every entity at rest, upright.
    std::vector<Problem> moving;
    for (const EntitySpec& e : scenario.entities) {
      if (e.orientation) {
        moving.push_back({e.path + "/orientation", "expected an upright entity, turned about Y alone, in mode " +
                                                       std::string(toString(mode)) +
                                                       ": the report's rules move entities upright (report 3.4)"});
      }
      for (const auto& [key, v] : {std::pair{"velocity", e.velocity}, std::pair{"spin", e.spin}}) {
        if (v.x != 0.0 || v.y != 0.0 || v.z != 0.0) {
          moving.push_back({e.path + "/" + key, "expected no starting " + std::string(key) + " in mode " +
                                                     std::string(toString(mode)) +
                                                     ": the report's rules start every entity at rest"});
        }
      }
    }
    if (!moving.empty()) throw ScenarioError(scenario, std::move(moving));
  }
  std::unique_ptr<World> world = buildWorld(scenario, settings);
  switch (mode) {
    case SimulationMode::Bullet: return world;
    case SimulationMode::Compat: return std::make_unique<CompatWorld>(std::move(world), buildRuleBodies(scenario));
    case SimulationMode::Rules:
      return std::make_unique<rules::RuleEngine>("rules", settings, scenario.table, buildRuleBodies(scenario),
                                                 std::make_unique<rules::ReportContactFinder>());
  }
  return world;
}

}  // namespace tabletop
