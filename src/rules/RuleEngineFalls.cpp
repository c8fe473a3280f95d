#include "rules/RuleEngine.h"

#include <cmath>

// Report 3.4 in the rules: a body leaving the table (or its base) moves on
// until its footprint clears the edge, falls straight down, and lands on
// the highest surface under its centre.
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
  RuleBody& b = bodies_[i];
  Motion& m = motion_[i];
  std::vector<bool> carried(bodies_.size(), false);
  for (std::size_t r : riders(i)) carried[r] = true;
  // The highest surface below the centre: the table, a body, or the ground.
  double surface = 0.0;
  int on = kOnGround;
  const Vec3& c = b.position;
  if (dropStatus(c, edges_) == EntityPositionStatus::OnTable && b.bottom() >= tableTop_ - kLevelSlack) {
    surface = tableTop_;
    on = kOnTable;
  }
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    if (k == i || carried[k] || !onSurface(k)) continue;
    const RuleBody& o = bodies_[k];
    const double dx = c.x - o.position.x, dz = c.z - o.position.z;
    const bool under = o.round() ? std::hypot(dx, dz) <= o.footX()
                                 : std::abs(dx) <= o.footX() && std::abs(dz) <= o.footZ();
    if (under && o.top() <= b.bottom() + kLevelSlack && o.top() > surface) {
      surface = o.top();
      on = static_cast<int>(k);
    }
  }
  m.phase = Phase::Falling;
  m.fallSpeed = 0.0;
  m.landingY = surface + b.below;
  m.landingOn = on;
  b.support = kOnNothing;
}

void RuleEngine::land(std::size_t i) {
  RuleBody& b = bodies_[i];
  Motion& m = motion_[i];
  const double shift = m.landingY - b.position.y;
  b.position.y = m.landingY;
  for (std::size_t r : riders(i)) bodies_[r].position.y += shift;
  m.phase = Phase::Resting;
  m.fallSpeed = 0.0;
  b.support = m.landingOn;
  if (m.landingOn == kOnGround || isDropping(b.status)) b.status = EntityPositionStatus::FinishDropSimulation;
  for (std::size_t r : riders(i)) {
    if (isDropping(bodies_[r].status)) bodies_[r].status = EntityPositionStatus::FinishDropSimulation;
  }
  Event e = eventNow(EventType::Lands, b.name);
  e.on = supportOf(m.landingOn);
  record(e);
}

}  // namespace tabletop::rules
