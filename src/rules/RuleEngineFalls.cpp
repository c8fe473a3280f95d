#include "rules/RuleEngine.h"

#include <cmath>
#include <limits>
#include <vector>

// Report 3.4 in the rules: a body leaving the table (or its base) moves on
// until its footprint clears the edge, falls straight down, and lands on
// the first top it meets under its centre, which may be falling too.
namespace tabletop::rules {
namespace {

// The outward unit normal of the edge a status names.
Vec3 edgeNormal(EntityPositionStatus s) {
  switch (s) {
    case EntityPositionStatus::DropFromRightEdge: return {1, 0, 0};
    case EntityPositionStatus::DropFromLeftEdge: return {-1, 0, 0};
    case EntityPositionStatus::DropFromFrontEdge: return {0, 0, 1};
    case EntityPositionStatus::DropFromBackEdge: return {0, 0, -1};
    default: return {};
  }
}

}  // namespace

void RuleEngine::leaveTable(std::size_t i, EntityPositionStatus status) {
  std::vector<std::size_t> group{i};
  for (std::size_t r : riders(i)) group.push_back(r);
  for (std::size_t k : group) {
    bodies_[k].status = status;
    Event e = eventNow(EventType::LeavesTable, bodies_[k].name);
    e.edge = dropEdge(status);
    record(e);
  }
  if (release_) {
    std::vector<Vec3> velocities;
    for (std::size_t k : group) velocities.push_back(velocity(k));
    for (std::size_t k : group) motion_[k].phase = Phase::Released;
    for (std::size_t g = 0; g < group.size(); ++g) release_->release(group[g], velocities[g]);
    return;
  }
  startClearing(i, edgeNormal(status));
}

// Moves on along the body's own direction (or straight out, when it was
// carried there) until its footprint is past the edge whose outward normal
// is `outward`.
void RuleEngine::startClearing(std::size_t i, const Vec3& outward) {
  Motion& m = motion_[i];
  const RuleBody& b = bodies_[i];
  const double half = std::abs(outward.x) > 0.0 ? b.footX() : b.footZ();
  const bool moving = m.phase == Phase::Driven || m.phase == Phase::Clearing;
  if (!moving || m.direction.dot(outward) <= 0.0) m.direction = outward;
  m.phase = Phase::Clearing;
  m.remaining = half / m.direction.dot(outward);
}

void RuleEngine::startFall(std::size_t i) {
  Motion& m = motion_[i];
  m.phase = Phase::Falling;
  m.fallSpeed = 0.0;
  bodies_[i].support = kOnNothing;
  judgeStatus(i);
  for (std::size_t r : riders(i)) judgeStatus(r);
}

int RuleEngine::heldBy(std::size_t i) const {
  int s = bodies_[i].support;
  while (s >= 0) s = bodies_[static_cast<std::size_t>(s)].support;
  return s;
}

void RuleEngine::judgeStatus(std::size_t i) {
  const bool down = !descends(i) && heldBy(i) != kOnNothing;
  bodies_[i].status = comeDown(bodies_[i].status, down, heldBy(i) == kOnTable);
}

bool RuleEngine::descends(std::size_t i) const {
  for (int k = static_cast<int>(i); k >= 0; k = bodies_[static_cast<std::size_t>(k)].support) {
    if (motion_[static_cast<std::size_t>(k)].phase == Phase::Falling) return true;
  }
  return false;
}

// Report 3.4, 3.8: the first top a falling body meets whose footprint holds
// its centre: the table, the ground, or a body resting, moving or falling
// too. Asked again at every event and step, as what is below moves (a body
// under it lands, or is pushed away); a top above its bottom is not met.
RuleEngine::Next RuleEngine::landing(std::size_t i) const {
  const RuleBody& b = bodies_[i];
  const double g = settings_.gravity, v = motion_[i].fallSpeed;
  Next best;
  best.kind = Next::Kind::Lands;
  best.body = i;
  best.t = std::numeric_limits<double>::infinity();
  best.top = -std::numeric_limits<double>::infinity();
  const auto consider = [&best](double t, double top, int on) {
    if (t < best.t || (t == best.t && top > best.top)) {
      best.t = t;
      best.top = top;
      best.on = on;
    }
  };
  // A top that does not move up or down, at `top`: met after the closed
  // form of a fall from rest or from speed v.
  const auto still = [&](double top, int on) {
    const double drop = b.position.y - (top + b.below);
    consider(drop <= 0.0 ? 0.0 : (std::sqrt(v * v + 2.0 * g * drop) - v) / g, top, on);
  };
  still(0.0, kOnGround);
  const Vec3& c = b.position;
  if (overTableTop(c, b.bottom(), edges_, tableTop_, kLevelSlack)) {
    still(tableTop_, kOnTable);
  }
  std::vector<bool> carried(bodies_.size(), false);
  for (std::size_t r : riders(i)) carried[r] = true;
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const Phase p = motion_[k].phase;
    if (k == i || carried[k] || p == Phase::Clearing || p == Phase::Released) continue;
    const RuleBody& o = bodies_[k];
    const double dx = c.x - o.position.x, dz = c.z - o.position.z;
    const bool under = o.round() ? std::hypot(dx, dz) <= o.footX()
                                 : std::abs(dx) <= o.footX() && std::abs(dz) <= o.footZ();
    if (!under || o.top() > b.bottom() + kLevelSlack) continue;
    if (!descends(k)) {
      still(o.top(), static_cast<int>(k));
      continue;
    }
    // Falling too, under the same gravity: the gap closes at the
    // difference of the two speeds, if this one is the faster.
    const double closing = v + velocity(k).y;
    if (closing > 0.0) consider(std::max(0.0, b.bottom() - o.top()) / closing, o.top(), static_cast<int>(k));
  }
  return best;
}

// Lands on `on`: seated on its top, its riders moved with it.
void RuleEngine::land(std::size_t i, int on) {
  RuleBody& b = bodies_[i];
  Motion& m = motion_[i];
  const double top = on == kOnGround ? 0.0 : on == kOnTable ? tableTop_ : bodies_[static_cast<std::size_t>(on)].top();
  const double landingY = top + b.below;
  const double shift = landingY - b.position.y;
  b.position.y = landingY;
  for (std::size_t r : riders(i)) bodies_[r].position.y += shift;
  m.phase = Phase::Resting;
  m.fallSpeed = 0.0;
  b.support = on;
  // Down once on what stays up: on one still falling, when that one lands.
  if (!descends(i)) {
    judgeStatus(i);
    for (std::size_t r : riders(i)) judgeStatus(r);
  }
  Event e = eventNow(EventType::Lands, b.name);
  e.on = supportOf(on);
  record(e);
}

}  // namespace tabletop::rules
