#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "rules/RuleEngine.h"

// Report 3.5 in the rules: the first strike between bodies on a surface at
// the same level. Only a pair with one moving body can strike, so the
// search is over moving x surface bodies, not every pair: a push along a
// row of N bodies costs N events of N checks, not N events of N^2.
namespace tabletop::rules {
namespace {

bool isZero(const Vec3& v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; }

// Bodies' footprints closer than this may touch: a margin for rounding
// over the bounding circles, far wider than any footprint test's.
constexpr double kReach = 1e-9;  // m

// The radius of a circle about the centre that holds the footprint at any yaw.
double footRadius(const RuleBody& b) {
  return b.round() ? b.halfExtents.x : std::hypot(b.halfExtents.x, b.halfExtents.z);
}

// False when `a`, moved by `sweep` in the table plane, stays out of reach
// of `b`: their bounding circles never meet, so neither can the
// footprints. A cheap test before the report's exact one.
bool mayMeet(const RuleBody& a, const RuleBody& b, const Vec3& sweep) {
  const double dx = b.position.x - a.position.x, dz = b.position.z - a.position.z;
  const double len2 = sweep.x * sweep.x + sweep.z * sweep.z;
  double t = len2 > 0.0 ? (dx * sweep.x + dz * sweep.z) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double gap = std::hypot(dx - t * sweep.x, dz - t * sweep.z);
  return gap <= footRadius(a) + footRadius(b) + kReach;
}

}  // namespace

std::vector<Vec3> RuleEngine::velocities() const {
  // velocity(i) is a body's own velocity plus its support's, down the chain;
  // each body's is made once, in the same sums as velocity(i).
  const std::size_t n = bodies_.size();
  std::vector<Vec3> v(n);
  std::vector<char> done(n, 0);
  std::vector<std::size_t> chain;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t k = i;
    chain.clear();
    while (!done[k]) {
      chain.push_back(k);
      const int s = bodies_[k].support;
      if (motion_[k].phase == Phase::Released || s < 0) break;
      k = static_cast<std::size_t>(s);
    }
    for (auto c = chain.rbegin(); c != chain.rend(); ++c) {
      const std::size_t b = *c;
      const int s = bodies_[b].support;
      if (motion_[b].phase == Phase::Released) {
        v[b] = {};
      } else {
        v[b] = s >= 0 ? ownVelocity(b) + v[static_cast<std::size_t>(s)] : ownVelocity(b);
      }
      done[b] = 1;
    }
  }
  return v;
}

std::vector<std::pair<std::size_t, std::size_t>> RuleEngine::pairsNear(const std::vector<std::size_t>& movers,
                                                                       const std::vector<Vec3>& v,
                                                                       double horizon) const {
  // Each body's box in the table plane over the horizon: its footprint's
  // bounding circle, stretched along its motion. Surface bodies sorted by
  // the box's low x; each mover is checked against the bodies whose boxes
  // may overlap its own, found by binary search.
  struct Box {
    double x0, x1, z0, z1;
    std::size_t body;
  };
  const auto box = [&](std::size_t i) {
    const RuleBody& b = bodies_[i];
    const double r = footRadius(b) + kReach;
    const double dx = v[i].x * horizon, dz = v[i].z * horizon;
    return Box{b.position.x - r + std::min(dx, 0.0), b.position.x + r + std::max(dx, 0.0),
               b.position.z - r + std::min(dz, 0.0), b.position.z + r + std::max(dz, 0.0), i};
  };
  std::vector<Box> boxes;
  double widest = 0.0;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!onSurface(i)) continue;
    boxes.push_back(box(i));
    widest = std::max(widest, boxes.back().x1 - boxes.back().x0);
  }
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) { return a.x0 < b.x0; });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t m : movers) {
    const Box mb = box(m);
    auto k = std::lower_bound(boxes.begin(), boxes.end(), mb.x0 - widest,
                              [](const Box& b, double x) { return b.x0 < x; });
    for (; k != boxes.end() && k->x0 <= mb.x1; ++k) {
      if (k->body == m || k->x1 < mb.x0 || k->z1 < mb.z0 || k->z0 > mb.z1) continue;
      pairs.emplace_back(std::min(m, k->body), std::max(m, k->body));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

RuleEngine::Next RuleEngine::nextStrike(Next best) const {
  const std::size_t n = bodies_.size();
  const std::vector<Vec3> v = velocities();
  std::vector<std::size_t> movers;  // on a surface and moving, ascending
  for (std::size_t i = 0; i < n; ++i) {
    if (onSurface(i) && !isZero(v[i])) movers.push_back(i);
  }
  // Pairs (i < j) in the order of the plain double loop over every pair, so
  // that ties and the shrinking horizon come out as they always did; the
  // pairs left out are those that cannot meet before the horizon.
  const auto check = [&](std::size_t i, std::size_t j) {
    if (!onSurface(j)) return;
    const RuleBody& a = bodies_[i];
    const RuleBody& b = bodies_[j];
    if (a.bottom() >= b.top() - kLevelSlack || b.bottom() >= a.top() - kLevelSlack) return;
    const Vec3 relative = v[i] - v[j];
    if (isZero(relative)) return;
    const Vec3 sweep = relative * best.t;
    if (!mayMeet(a, b, sweep)) return;
    const std::optional<Hit> hit = finder_->firstHit(i, a, j, b, sweep);
    if (!hit) return;
    const double t = hit->fraction * best.t;
    if (!(t < best.t)) return;
    // The striker is the one running into the other faster.
    const bool iStrikes = v[i].dot(hit->normal) >= -v[j].dot(hit->normal);
    best = Next{};
    best.kind = Next::Kind::Strike;
    best.t = t;
    best.body = iStrikes ? i : j;
    best.other = iStrikes ? j : i;
    best.normal = iStrikes ? hit->normal : hit->normal * -1.0;
  };
  const auto pairs = pairsNear(movers, v, best.t);
  for (const auto& [i, j] : pairs) check(i, j);
  best.checks = static_cast<double>(n + pairs.size());
  return best;
}

}  // namespace tabletop::rules
