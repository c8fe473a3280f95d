#include "compat/CompatWorld.h"

#include <algorithm>
#include <cmath>

#include "compat/GjkContactFinder.h"

namespace tabletop {
namespace {

// A released body has landed once its vertical speed stays below this...
constexpr double kLandedSpeed = 5e-3;  // m/s
// ...for this long.
constexpr double kLandedWindow = 0.1;  // s

}  // namespace

CompatWorld::CompatWorld(std::unique_ptr<World> world, std::vector<rules::RuleBody> bodies)
    : world_(std::move(world)), settled_(bodies.size(), false), landedSince_(bodies.size(), -1.0) {
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

// The rules move what is on the table and Bullet what has left it: both
// step at the new rate, under the new gravity.
void CompatWorld::setTimestep(double seconds) {
  engine_->setTimestep(seconds);
  world_->setTimestep(seconds);
}

void CompatWorld::setGravity(double g) {
  engine_->setGravity(g);
  world_->setGravity(g);
}

void CompatWorld::step() {
  engine_->step();
  place();
  world_->step();
  observeReleased();
  mergeEvents();
}

// A released body's drop ends once it has landed: held up by the ground,
// or by a released body whose drop has ended (one fell onto another, report
// 3.4), and not moving up or down for kLandedWindow. A ball may roll on
// along the floor under physics; the rules have no floor to roll on, and
// the script does not wait for it.
void CompatWorld::observeReleased() {
  const auto& shapes = world_->entities();
  const double now = engine_->time();
  const auto heldUp = [&](const Support& support) {
    if (support == Support::ground()) return true;
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      if (settled_[k] && support == Support::entity(shapes[k]->name())) return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (!engine_->released(i) || settled_[i]) continue;
    const Shape& shape = *shapes[i];
    const bool landed = heldUp(shape.support()) && std::abs(shape.body()->getLinearVelocity().y()) < kLandedSpeed;
    if (!landed) {
      landedSince_[i] = -1.0;
      continue;
    }
    if (landedSince_[i] < 0.0) landedSince_[i] = now;
    if (now - landedSince_[i] < kLandedWindow - 1e-12) continue;
    settled_[i] = true;
    Event lands;
    lands.t = landedSince_[i];
    lands.type = EventType::Lands;
    lands.entity = shape.name();
    lands.on = shape.support();
    ownEvents_.push_back(lands);
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
      // The rules said which edge; Bullet says when the drop is over (the
      // status rule, EntityPositionStatus.h, with down = settled).
      const EntityPositionStatus edge = states[i].status;
      states[i] = physical[i];
      states[i].status = comeDown(edge, settled_[i], false);
    } else {
      states[i].angularVelocity = {};
    }
  }
  return states;
}

WorkCount CompatWorld::work() const {
  WorkCount w = world_->work();
  w += engine_->work();
  return w;
}

}  // namespace tabletop
