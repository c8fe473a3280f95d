#include "rules/RuleEngine.h"

#include <cmath>
#include <stdexcept>

#include "core/DirectionDef.h"

namespace tabletop::rules {
namespace {

// Events at one instant that keep causing each other mean a bug, not a scene.
constexpr int kMaxEventsPerStep = 100000;
// A drive that ends this close to an edge ends on it: report 3.4 drops an
// entity only when its centre is strictly past the edge, so the tie goes
// to the drive's end, whatever the rounding of the path to it.
constexpr double kEdgeTie = 1e-9;  // m

}  // namespace

RuleEngine::RuleEngine(std::string mode, const Settings& settings, const TableSpec& table,
                       std::vector<RuleBody> bodies, std::unique_ptr<ContactFinder> finder,
                       ReleaseHandler* release)
    : mode_(std::move(mode)),
      settings_(settings),
      tableTop_(table.height),
      edges_{table.centreX - 0.5 * table.width, table.centreX + 0.5 * table.width,
             table.centreZ - 0.5 * table.depth, table.centreZ + 0.5 * table.depth},
      bodies_(std::move(bodies)),
      motion_(bodies_.size()),
      finder_(std::move(finder)),
      release_(release) {
  // Where each entity starts: on the table or never on it; one placed in
  // mid-air (on nothing) falls from the start.
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    RuleBody& b = bodies_[i];
    const int held = heldBy(i);
    const Support::Kind kind = held == kOnTable ? Support::Kind::Table
                               : held == kOnGround ? Support::Kind::Ground : Support::Kind::None;
    b.status = startStatus(kind, overTableTop(b.position, b.bottom(), edges_, tableTop_, kLevelSlack));
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].support == kOnNothing) {
      startFall(i);
      motion_[i].moving = true;
    }
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) judgeStatus(i);
}

std::size_t RuleEngine::index(const std::string& name) const {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].name == name) return i;
  }
  throw std::invalid_argument("no entity named '" + name + "'");
}

bool RuleEngine::onSurface(std::size_t i) const {
  return motion_[i].phase == Phase::Resting || motion_[i].phase == Phase::Driven;
}

Vec3 RuleEngine::ownVelocity(std::size_t i) const {
  const Motion& m = motion_[i];
  switch (m.phase) {
    case Phase::Driven:
    case Phase::Clearing: return m.direction * kDriveSpeed;
    case Phase::Falling: return {0.0, -m.fallSpeed, 0.0};
    default: return {};
  }
}

Vec3 RuleEngine::velocity(std::size_t i) const {
  if (motion_[i].phase == Phase::Released) return {};
  const int s = bodies_[i].support;
  return s >= 0 ? ownVelocity(i) + velocity(static_cast<std::size_t>(s)) : ownVelocity(i);
}

Support RuleEngine::supportOf(int support) const {
  if (support == kOnTable) return Support::table();
  if (support == kOnGround) return Support::ground();
  if (support == kOnNothing) return {};
  return Support::entity(bodies_.at(static_cast<std::size_t>(support)).name);
}

std::vector<std::size_t> RuleEngine::riders(std::size_t i) const {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    if (bodies_[k].support == static_cast<int>(i) && motion_[k].phase != Phase::Released) {
      out.push_back(k);
      for (std::size_t r : riders(k)) out.push_back(r);
    }
  }
  return out;
}

// The body whose own push moves `i`: itself, or what carries it.
std::size_t RuleEngine::driver(std::size_t i) const {
  const Phase p = motion_[i].phase;
  if (p == Phase::Driven || p == Phase::Clearing) return i;
  const int s = bodies_[i].support;
  return s >= 0 ? driver(static_cast<std::size_t>(s)) : i;
}

RuleEngine::Next RuleEngine::nextEvent(double horizon) const {
  Next best;
  best.t = horizon;
  const auto consider = [&best](Next candidate) {
    if (candidate.t < best.t) best = candidate;
  };
  const auto make = [](Next::Kind kind, double t, std::size_t body) {
    Next e;
    e.kind = kind;
    e.t = t;
    e.body = body;
    return e;
  };
  const std::size_t n = bodies_.size();
  std::size_t falling = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Motion& m = motion_[i];
    const RuleBody& b = bodies_[i];
    if (m.phase == Phase::Driven || m.phase == Phase::Clearing) {
      consider(make(Next::Kind::DriveEnds, m.remaining / kDriveSpeed, i));
    }
    if (m.phase == Phase::Falling) {
      consider(landing(i));
      ++falling;
    }
    if (m.phase != Phase::Driven && m.phase != Phase::Clearing) continue;
    const Vec3 v = ownVelocity(i);
    // Report 3.4: the centre reaching an edge while moving out, whether
    // pushed on the table or sliding off a base beyond it.
    const bool overTable = (m.phase == Phase::Driven && b.support == kOnTable) ||
                           (m.phase == Phase::Clearing && b.status == EntityPositionStatus::OnTable);
    if (overTable) {
      const auto edge = [&](double coord, double speed, double limit, EntityPositionStatus s) {
        if (speed == 0.0) return;
        const double t = (limit - coord) / speed;
        if (t >= 0.0 && t * kDriveSpeed < m.remaining - kEdgeTie) {
          Next e = make(Next::Kind::TableEdge, t, i);
          e.edge = s;
          consider(e);
        }
      };
      if (v.x > 0.0) edge(b.position.x, v.x, edges_.xRight, EntityPositionStatus::DropFromRightEdge);
      if (v.x < 0.0) edge(b.position.x, v.x, edges_.xLeft, EntityPositionStatus::DropFromLeftEdge);
      if (v.z > 0.0) edge(b.position.z, v.z, edges_.zFront, EntityPositionStatus::DropFromFrontEdge);
      if (v.z < 0.0) edge(b.position.z, v.z, edges_.zBack, EntityPositionStatus::DropFromBackEdge);
    } else if (m.phase == Phase::Driven && b.support >= 0) {
      // Report 3.7: a pushed upper entity slides until its centre passes
      // the lower one's edge.
      const RuleBody& base = bodies_[static_cast<std::size_t>(b.support)];
      const double rx = b.position.x - base.position.x, rz = b.position.z - base.position.z;
      double t = horizon;
      if (v.x > 0.0) t = std::min(t, (base.footX() - rx) / v.x);
      if (v.x < 0.0) t = std::min(t, (-base.footX() - rx) / v.x);
      if (v.z > 0.0) t = std::min(t, (base.footZ() - rz) / v.z);
      if (v.z < 0.0) t = std::min(t, (-base.footZ() - rz) / v.z);
      consider(make(Next::Kind::BaseEdge, std::max(t, 0.0), i));
    }
  }
  Next out = nextStrike(best);
  out.checks += static_cast<double>(falling * n);  // each landing looks at every body
  return out;
}

void RuleEngine::advance(double dt) {
  if (dt <= 0.0) return;
  const std::size_t n = bodies_.size();
  // Own displacements first (they change the motion), then add what each
  // body's support moved.
  std::vector<Vec3>& own = own_;
  own.assign(n, Vec3{});
  for (std::size_t i = 0; i < n; ++i) {
    Motion& m = motion_[i];
    switch (m.phase) {
      case Phase::Driven:
      case Phase::Clearing: {
        const double d = std::min(m.remaining, kDriveSpeed * dt);
        own[i] = m.direction * d;
        m.remaining -= d;
        break;
      }
      case Phase::Falling: {
        own[i] = {0.0, -(m.fallSpeed * dt + 0.5 * settings_.gravity * dt * dt), 0.0};
        m.fallSpeed += settings_.gravity * dt;
        break;
      }
      default: break;
    }
  }
  // What each body's supports moved, added down the chain: a support is
  // never its own rider, so the chains end.
  for (std::size_t i = 0; i < n; ++i) {
    if (motion_[i].phase == Phase::Released) continue;
    Vec3 moved = own[i];
    for (int s = bodies_[i].support; s >= 0; s = bodies_[static_cast<std::size_t>(s)].support) {
      moved = moved + own[static_cast<std::size_t>(s)];
    }
    bodies_[i].position = bodies_[i].position + moved;
  }
}

void RuleEngine::handle(const Next& next) {
  const std::size_t i = next.body;
  switch (next.kind) {
    case Next::Kind::None: break;
    case Next::Kind::DriveEnds:
      motion_[i].remaining = 0.0;
      if (motion_[i].phase == Phase::Clearing) {
        startFall(i);
      } else {
        motion_[i].phase = Phase::Resting;
      }
      break;
    case Next::Kind::Strike: {
      Event e = eventNow(EventType::ContactBegin, bodies_[i].name);
      e.other = bodies_[next.other].name;
      record(e);
      strike(i, next.other, next.normal);
      break;
    }
    case Next::Kind::TableEdge: leaveTable(i, next.edge); break;
    case Next::Kind::BaseEdge: {
      // Past a table edge, an entity on the table drops from it; one that
      // never was on the table only falls off its base.
      const EntityPositionStatus past = dropStatus(bodies_[i].position, edges_);
      if (bodies_[i].status == EntityPositionStatus::OnTable && past != EntityPositionStatus::OnTable) {
        leaveTable(i, past);
        break;
      }
      // Which of the base's edges: the direction of the rider's offset.
      const RuleBody& base = bodies_[static_cast<std::size_t>(bodies_[i].support)];
      const double rx = (bodies_[i].position.x - base.position.x) / base.footX();
      const double rz = (bodies_[i].position.z - base.position.z) / base.footZ();
      const Vec3 outward = std::abs(rx) >= std::abs(rz) ? Vec3{rx > 0 ? 1.0 : -1.0, 0, 0}
                                                          : Vec3{0, 0, rz > 0 ? 1.0 : -1.0};
      startClearing(i, outward);
      break;
    }
    case Next::Kind::Lands: land(i, next.on); break;
  }
}

void RuleEngine::strike(std::size_t striker, std::size_t struck, const Vec3& n) {
  const std::size_t d = driver(striker);
  const Motion& push = motion_[d];
  Motion& target = motion_[struck];
  const bool spheres = bodies_[striker].shape == ShapeKind::Sphere &&
                       bodies_[struck].shape == ShapeKind::Sphere && d == striker;
  if (!spheres) {
    // Straight-line transfer: the push goes on through the struck body's
    // centre, same direction, same remaining distance.
    target.phase = Phase::Driven;
    target.direction = push.direction;
    target.remaining = push.remaining;
    return;
  }
  // Two spheres: see the class comment.
  Motion& own = motion_[striker];
  const double cosine = std::max(0.0, own.direction.dot(n));
  const double remaining = own.remaining;
  const double step1 = remaining * cosine * cosine;
  const Vec3 rest = own.direction - n * cosine;
  const double restLength = rest.length();
  target.phase = Phase::Driven;
  target.direction = n;
  target.remaining = step1;
  own.remaining = restLength > 0.0 ? std::min(remaining * (1.0 - cosine * cosine), step1) : 0.0;
  if (restLength > 0.0) own.direction = rest * (1.0 / restLength);
}

bool RuleEngine::moving(std::size_t i) const {
  const Phase p = motion_[i].phase;
  if (p == Phase::Released) return false;
  if (p == Phase::Driven || p == Phase::Clearing || p == Phase::Falling) return true;
  const int s = bodies_[i].support;
  return s >= 0 && moving(static_cast<std::size_t>(s));
}

void RuleEngine::noteRest() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (motion_[i].phase == Phase::Released) continue;
    const bool moving = this->moving(i);
    if (motion_[i].moving && !moving) record(eventNow(EventType::AtRest, bodies_[i].name));
    motion_[i].moving = moving;
  }
}

Event RuleEngine::eventNow(EventType type, const std::string& entity) const {
  Event e;
  e.t = now_;
  e.type = type;
  e.entity = entity;
  return e;
}

void RuleEngine::record(Event e) { events_.push_back(std::move(e)); }

void RuleEngine::push(const Arrow& arrow, const PushMagnitude& magnitude) {
  const std::size_t i = index(arrow.entity);
  RuleBody& b = bodies_[i];
  Motion& m = motion_[i];
  if (arrow.at) {
    throw std::invalid_argument("the report's pushes act through the centre (report 3.5): a push 'at' a point "
                                "needs mode bullet");
  }
  if (magnitude.kind != PushMagnitude::Kind::Step) {
    throw std::invalid_argument("the report's rules move entities by steps: give the push a 'step' in metres");
  }
  const bool pushable = b.status == EntityPositionStatus::OnTable || b.status == EntityPositionStatus::OnGround;
  if (m.phase == Phase::Released || m.phase == Phase::Clearing || m.phase == Phase::Falling ||
      b.support == kOnGround || !pushable) {
    const std::string where = b.support == kOnGround ? "on the ground (" + std::string(toString(b.status)) + ")"
                                                     : std::string(toString(b.status));
    throw std::invalid_argument("'" + b.name + "' is " + where + ": the report's rules push only entities on the table");
  }
  if (m.phase == Phase::Driven) {
    throw std::invalid_argument("'" + b.name + "' is still moving from an earlier push; wait for rest first");
  }
  const double angle = arrow.worldAngleDegrees(b.round() ? 0.0 : b.yawDegrees);
  m.phase = Phase::Driven;
  m.direction = pushDirection(angle);
  m.remaining = magnitude.value;

  Event e = eventNow(EventType::Push, b.name);
  e.face = arrow.face;
  e.angle = angle;
  e.step = magnitude.value;
  record(e);
  noteRest();
}

void RuleEngine::rotate(const std::string& entity, double degrees) {
  const std::size_t i = index(entity);
  bodies_[i].yawDegrees += degrees;
  Event e = eventNow(EventType::Rotate, entity);
  e.angle = degrees;
  record(e);
}

void RuleEngine::step() {
  const double dt = settings_.timestep;
  double left = dt;
  for (int count = 0;; ++count) {
    if (count > kMaxEventsPerStep) {
      throw std::logic_error("rule engine: events keep causing each other at t = " + std::to_string(now_));
    }
    const Next next = nextEvent(left);
    work_.ruleChecks += next.checks;
    advance(next.t);
    left -= next.t;
    now_ = time_ + (dt - left);
    if (next.kind == Next::Kind::None) break;
    handle(next);
    noteRest();
  }
  ++steps_;
  time_ = clock_.time(steps_, dt);
  now_ = time_;
  noteRest();
}

bool RuleEngine::allAtRest() const {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (moving(i)) return false;
  }
  return true;
}

std::vector<EntityState> RuleEngine::snapshot() const {
  std::vector<EntityState> out;
  out.reserve(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const RuleBody& b = bodies_[i];
    EntityState s;
    s.name = b.name;
    s.shape = b.shape;
    s.position = b.position;
    const double half = 0.5 * convertAngle(b.yawDegrees);
    s.orientation = {std::cos(half), 0.0, std::sin(half), 0.0};
    s.yawDegrees = b.yawDegrees;
    s.linearVelocity = velocity(i);
    s.status = b.status;
    s.support = supportOf(b.support);
    out.push_back(s);
  }
  return out;
}

}  // namespace tabletop::rules

namespace tabletop::rules {

void RuleEngine::setTimestep(double seconds) {
  clock_.changeAt(steps_, time_);
  settings_.timestep = seconds;
}

}  // namespace tabletop::rules
