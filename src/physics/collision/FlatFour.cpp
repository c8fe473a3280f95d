#include "physics/collision/FlatFour.h"

#include <algorithm>

namespace tabletop {

double spannedArea(const btVector3& a, const btVector3& b, const btVector3& c, const btVector3& d) {
  return std::max({(a - c).cross(b - d).length(), (a - b).cross(c - d).length(), (a - d).cross(b - c).length()});
}

void OfferedPoints::clear() {
  for (std::size_t i = 0; i < used_; ++i) offers_[i].points.clear();
  used_ = 0;
}

void OfferedPoints::offer(const btPersistentManifold& manifold, const btManifoldPoint& point) {
  for (std::size_t i = 0; i < used_; ++i) {
    if (offers_[i].manifold == &manifold) {
      offers_[i].points.push_back(point);
      return;
    }
  }
  if (used_ == offers_.size()) offers_.emplace_back();
  Offers& fresh = offers_[used_++];
  fresh.manifold = &manifold;
  fresh.points.clear();
  fresh.points.push_back(point);
  fresh.beforeCount = std::min(manifold.getNumContacts(), 4);
  for (int p = 0; p < fresh.beforeCount; ++p) fresh.before[p] = manifold.getContactPoint(p).m_localPointA;
}

namespace {

// Where two points of body A count as one place, m: a point found again
// at rest is found at its place to rounding.
constexpr double kSamePlace = 1e-9;

}  // namespace

bool widestFour(const OfferedPoints::Offers& offers, std::array<int, 4>& chosen) {
  const std::vector<btManifoldPoint>& points = offers.points;
  const int n = static_cast<int>(points.size());
  if (n <= 4 || n > kMostOffered) return false;
  const auto [lowest, highest] = std::minmax_element(
      points.begin(), points.end(), [](const btManifoldPoint& a, const btManifoldPoint& b) {
        return a.getDistance() < b.getDistance();
      });
  if (highest->getDistance() - lowest->getDistance() > kFlatDepths) return false;
  // Whether each point stands where the manifold held one before the pass.
  int held[kMostOffered];
  for (int i = 0; i < n; ++i) {
    held[i] = 0;
    for (int b = 0; b < offers.beforeCount; ++b) {
      if ((points[i].m_localPointA - offers.before[b]).length2() <= kSamePlace * kSamePlace) held[i] = 1;
    }
  }
  double widest = -1.0;
  std::array<int, 4> best{};
  // The widest area first, then every four near it: the one holding most.
  for (int pass = 0; pass < 2; ++pass) {
    int mostHeld = -1;
    for (int a = 0; a < n; ++a) {
      for (int b = a + 1; b < n; ++b) {
        for (int c = b + 1; c < n; ++c) {
          for (int d = c + 1; d < n; ++d) {
            const double s = spannedArea(points[a].m_localPointA, points[b].m_localPointA, points[c].m_localPointA,
                                         points[d].m_localPointA);
            if (pass == 0) {
              if (s > widest) widest = s;
              continue;
            }
            if (s < widest * (1.0 - kAreaTie)) continue;
            const int h = held[a] + held[b] + held[c] + held[d];
            if (h > mostHeld) mostHeld = h, best = {a, b, c, d};
          }
        }
      }
    }
  }
  if (!(widest > 0)) return false;
  chosen = best;
  return true;
}

}  // namespace tabletop
