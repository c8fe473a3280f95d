#include "physics/CompatWorld.h"

#include <algorithm>

#include "physics/GjkContactFinder.h"

namespace tabletop {

CompatWorld::CompatWorld(std::unique_ptr<World> world, std::vector<rules::RuleBody> bodies)
    : world_(std::move(world)), settled_(bodies.size(), false) {
  for (std::size_t i = 0; i < bodies.size(); ++i) world_->makeKinematic(i);
  engine_ = std::make_unique<rules::RuleEngine>("compat", world_->settings(), world_->table().spec(),
                                                std::move(bodies),
                                                std::make_unique<GjkContactFinder>(*world_),
                                                static_cast<rules::ReleaseHandler*>(this));
  place();
}

void CompatWorld::place() {
  const auto& bodies = engine_->bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (engine_->released(i)) continue;
    const Vec3& c = bodies[i].position;
    world_->placeKinematic(i, btVector3(c.x, c.y, c.z), bodies[i].yawDegrees);
  }
}

void CompatWorld::release(std::size_t body, const Vec3& velocity) {
  const Vec3& c = engine_->bodies()[body].position;
  world_->placeKinematic(body, btVector3(c.x, c.y, c.z), engine_->bodies()[body].yawDegrees);
  world_->makeDynamic(body, btVector3(velocity.x, velocity.y, velocity.z));
}

void CompatWorld::push(const Arrow& arrow, const PushMagnitude& magnitude) {
  engine_->push(arrow, magnitude);
  mergeEvents();
}

void CompatWorld::rotate(const std::string& entity, double degrees) {
  engine_->rotate(entity, degrees);
  place();
  mergeEvents();
}

void CompatWorld::step() {
  engine_->step();
  place();
  world_->step();
  observeReleased();
  mergeEvents();
}

// A released body's drop ends when Bullet has it at rest.
void CompatWorld::observeReleased() {
  const auto& shapes = world_->entities();
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (!engine_->released(i) || settled_[i] || !world_->atRest(i)) continue;
    settled_[i] = true;
    Event lands;
    lands.t = engine_->time();
    lands.type = EventType::Lands;
    lands.entity = shapes[i]->name();
    lands.on = shapes[i]->support();
    ownEvents_.push_back(lands);
    Event rest = lands;
    rest.type = EventType::AtRest;
    rest.on.clear();
    ownEvents_.push_back(rest);
  }
}

void CompatWorld::mergeEvents() {
  events_ = engine_->events();
  events_.insert(events_.end(), ownEvents_.begin(), ownEvents_.end());
  std::stable_sort(events_.begin(), events_.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
}

bool CompatWorld::allAtRest() const {
  if (!engine_->allAtRest()) return false;
  for (std::size_t i = 0; i < settled_.size(); ++i) {
    if (engine_->released(i) && !settled_[i]) return false;
  }
  return true;
}

std::vector<EntityState> CompatWorld::snapshot() const {
  std::vector<EntityState> states = engine_->snapshot();
  const std::vector<EntityState> physical = world_->snapshot();
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (engine_->released(i)) {
      // The rules said which edge; Bullet says when the drop is over.
      const EntityPositionStatus edge = states[i].status;
      states[i] = physical[i];
      states[i].status = settled_[i] && states[i].position.y < world_->table().topHeight()
                             ? EntityPositionStatus::FinishDropSimulation
                             : edge;
    } else {
      states[i].angularVelocity = {};
    }
  }
  return states;
}

}  // namespace tabletop
