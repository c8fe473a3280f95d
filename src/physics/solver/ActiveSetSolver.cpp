#include "physics/solver/ActiveSetSolver.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>

namespace tabletop {
namespace {

// Bullet bounds a contact's normal row by 0 and 1e10.
constexpr double kUnbounded = 1e9;

}  // namespace

bool ActiveSetSolver::solveMLCP(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x, const btVectorXu& lo,
                                const btVectorXu& hi, const btAlignedObjectArray<int>& limitDependency,
                                int /*numIterations*/, bool /*useSparsity*/) {
  // Neither the guess nor Dantzig's pivoting (the fallback) uses the
  // iteration count or the sparsity flag.
  return solve(A, b, x, lo, hi, limitDependency, nullptr) != Answer::kNone;
}

ActiveSetSolver::Answer ActiveSetSolver::solve(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x,
                                               const btVectorXu& lo, const btVectorXu& hi,
                                               const btAlignedObjectArray<int>& limitDependency,
                                               const RowBodies* rowBodies) {
  if (b.rows() > 0) {
    if (rowBodies != nullptr && rowBodies->size() != static_cast<std::size_t>(b.rows())) rowBodies = nullptr;
    if (solveByGuess(A, b, lo, hi, limitDependency, rowBodies, TurnedRows::kHandOn, x)) {
      ++solved_;
      return Answer::kByGuess;
    }
    ++handedOn_;
  }
  return fallback_.solveMLCP(A, b, x, lo, hi, limitDependency, 0) ? Answer::kByFallback : Answer::kNone;
}

bool ActiveSetSolver::solveStickingTurns(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x, const btVectorXu& lo,
                                         const btVectorXu& hi, const btAlignedObjectArray<int>& limitDependency,
                                         const RowBodies* rowBodies) {
  if (rowBodies != nullptr && rowBodies->size() != static_cast<std::size_t>(b.rows())) rowBodies = nullptr;
  return b.rows() > 0 && solveByGuess(A, b, lo, hi, limitDependency, rowBodies, TurnedRows::kStick, x);
}

bool ActiveSetSolver::solveByGuess(const btMatrixXu& A, const btVectorXu& b, const btVectorXu& lo,
                                   const btVectorXu& hi, const btAlignedObjectArray<int>& limitDependency,
                                   const RowBodies* rowBodies, TurnedRows turned, btVectorXu& x) {
  const int n = b.rows();
  if (A.rows() != n || A.cols() != n || limitDependency.size() != n || x.rows() != n) return false;
  if (!collectPoints(b, lo, hi, limitDependency)) return false;
  const int numPoints = static_cast<int>(points_.size());
  const double* a = A.getBufferPointer();
  // A small island is factored whole, in its own order: ordering it would
  // cost more than the zeros it skips.
  const bool small = numPoints <= kWholePoints;
  if (small) {
    order_.resize(numPoints);
    for (int k = 0; k < numPoints; ++k) order_[k] = k;
  } else {
    findNeighbours(a, n, rowBodies);
    orderPoints();
  }

  // The first guess: the points that pressed in the last step (the warm
  // start, when there is one) or whose gap does not open faster than a
  // resting point's rounding; each friction row slides against its slip,
  // or sticks.
  pressing_.resize(numPoints);
  slide_.assign(n, 0);
  for (int k = 0; k < numPoints; ++k) {
    pressing_[k] = x[points_[k]] > 0 || b[points_[k]] > -kOpeningSpeed;
    guessFriction(k, b, hi);
  }
  y_.resize(n);
  for (int guess = 0; guess < kMaxGuesses; ++guess) {
    rows_.clear();
    slid_.clear();
    for (const int k : order_) {
      if (!pressing_[k]) continue;
      rows_.push_back(points_[k]);
      for (const int f : frictionRows_[k]) {
        if (hi[f] > 0) (slide_[f] != 0 ? slid_ : rows_).push_back(f);
      }
    }
    if (small) first_.assign(rows_.size(), 0);
    else findProfile(a, n, rowBodies);
    if (!(slid_.empty() ? factor(a, n) : factorSliding(a, n, hi))) return false;
    solution_.assign(n, 0.0);
    substitute(b, !slid_.empty());
    for (const int f : slid_) solution_[f] = slide_[f] * hi[f] * solution_[limitDependency[f]];
    // Points in and out, then friction rows from sticking to sliding: a
    // guess changes what its answer shows wrong, all at once.
    bool changed = false;
    for (int k = 0; k < numPoints; ++k) {
      const int p = points_[k];
      if (pressing_[k]) {
        if (solution_[p] < 0) pressing_[k] = 0, changed = true;
      } else if (gapSpeed(a, n, b, p) < -kClosingTolerance) {
        pressing_[k] = 1, changed = true;
        guessFriction(k, b, hi);
      }
    }
    if (changed) continue;
    for (int k = 0; k < numPoints; ++k) {
      if (!pressing_[k]) continue;
      const double bound = solution_[points_[k]];
      for (const int f : frictionRows_[k]) {
        if (slide_[f] == 0 && std::abs(solution_[f]) > hi[f] * bound) {
          slide_[f] = solution_[f] > 0 ? 1 : -1;
          changed = true;
        }
      }
    }
    if (changed) continue;
    // A sliding row whose answer turns its slip round would stick: where
    // friction sticks and slides on one problem, sticking answers can
    // press harder than sliding, so that is the fallback's to answer,
    // unless the fallback has failed (solveStickingTurns).
    for (const int f : slid_) {
      if (slide_[f] * gapSpeed(a, n, b, f) <= kClosingTolerance) continue;
      if (turned == TurnedRows::kHandOn) return false;
      slide_[f] = 0;
      changed = true;
    }
    if (changed) continue;
    // A non-finite answer (from a matrix that is not finite) would pass
    // every test above, each comparison with NaN being false: hand it on.
    for (int i = 0; i < n; ++i) {
      if (!std::isfinite(solution_[i])) return false;
    }
    for (int i = 0; i < n; ++i) x[i] = solution_[i];
    return true;
  }
  return false;
}

void ActiveSetSolver::guessFriction(int point, const btVectorXu& b, const btVectorXu& hi) {
  for (const int f : frictionRows_[point]) {
    const bool slips = hi[f] > 0 && std::abs(b[f]) > kSlipSpeed;
    slide_[f] = !slips ? 0 : b[f] > 0 ? 1 : -1;
  }
}

double ActiveSetSolver::gapSpeed(const double* a, int n, const btVectorXu& b, int row) const {
  double w = -b[row];
  const double* r = a + static_cast<std::size_t>(row) * n;
  for (const int j : rows_) w += r[j] * solution_[j];
  for (const int j : slid_) w += r[j] * solution_[j];
  return w;
}

bool ActiveSetSolver::collectPoints(const btVectorXu& b, const btVectorXu& lo, const btVectorXu& hi,
                                    const btAlignedObjectArray<int>& limitDependency) {
  const int n = b.rows();
  // The points are the rows that hang on no other; each must be a contact's
  // normal row (0 to unbounded), each other row a friction row (+-hi).
  points_.clear();
  pointOf_.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(b[i])) return false;
    if (limitDependency[i] >= 0) continue;
    if (lo[i] != 0 || !(hi[i] > kUnbounded)) return false;
    pointOf_[i] = static_cast<int>(points_.size());
    points_.push_back(i);
  }
  const int numPoints = static_cast<int>(points_.size());
  if (frictionRows_.size() < points_.size()) frictionRows_.resize(points_.size());
  for (int k = 0; k < numPoints; ++k) frictionRows_[k].clear();
  for (int i = 0; i < n; ++i) {
    const int normal = limitDependency[i];
    if (normal < 0) continue;
    if (normal >= n || pointOf_[normal] < 0 || !(hi[i] >= 0) || lo[i] != -hi[i]) return false;
    frictionRows_[pointOf_[normal]].push_back(i);
  }
  return true;
}

void ActiveSetSolver::findNeighbours(const double* a, int n, const RowBodies* rowBodies) {
  const int numPoints = static_cast<int>(points_.size());
  if (neighbours_.size() < points_.size()) neighbours_.resize(points_.size());
  for (int k = 0; k < numPoints; ++k) neighbours_[k].clear();
  if (rowBodies == nullptr) {
    for (int k = 0; k < numPoints; ++k) {
      const double* row = a + static_cast<std::size_t>(points_[k]) * n;
      for (int q = 0; q < numPoints; ++q) {
        if (q != k && row[points_[q]] != 0) neighbours_[k].push_back(q);
      }
    }
    return;
  }
  for (std::vector<int>& points : bodyPoints_) points.clear();
  for (int k = 0; k < numPoints; ++k) {
    for (const int body : (*rowBodies)[points_[k]]) {
      if (body < 0) continue;
      if (bodyPoints_.size() <= static_cast<std::size_t>(body)) bodyPoints_.resize(body + 1);
      bodyPoints_[body].push_back(k);
    }
  }
  // Each body's points are listed in rising order, so a point's
  // neighbours are the sorted union of its (at most two) bodies' lists.
  const std::vector<int> none;
  for (int k = 0; k < numPoints; ++k) {
    std::vector<int>& mine = neighbours_[k];
    const auto& [first, second] = (*rowBodies)[points_[k]];
    const std::vector<int>& one = first >= 0 ? bodyPoints_[first] : none;
    const std::vector<int>& other = second >= 0 && second != first ? bodyPoints_[second] : none;
    std::set_union(one.begin(), one.end(), other.begin(), other.end(), std::back_inserter(mine));
    mine.erase(std::remove(mine.begin(), mine.end(), k), mine.end());
  }
}

void ActiveSetSolver::orderPoints() {
  const int numPoints = static_cast<int>(points_.size());
  const auto fewer = [this](int p, int q) {
    return neighbours_[p].size() != neighbours_[q].size() ? neighbours_[p].size() < neighbours_[q].size() : p < q;
  };
  // Cuthill-McKee: breadth first from a point of fewest neighbours, each
  // point's unvisited neighbours fewest first; then reversed.
  order_.clear();
  visited_.assign(numPoints, 0);
  while (static_cast<int>(order_.size()) < numPoints) {
    int start = -1;
    for (int k = 0; k < numPoints; ++k) {
      if (!visited_[k] && (start < 0 || fewer(k, start))) start = k;
    }
    visited_[start] = 1;
    std::size_t head = order_.size();
    order_.push_back(start);
    for (; head < order_.size(); ++head) {
      const std::size_t from = order_.size();
      for (const int q : neighbours_[order_[head]]) {
        if (!visited_[q]) visited_[q] = 1, order_.push_back(q);
      }
      std::sort(order_.begin() + static_cast<std::ptrdiff_t>(from), order_.end(), fewer);
    }
  }
  std::reverse(order_.begin(), order_.end());
}

void ActiveSetSolver::findProfile(const double* a, int n, const RowBodies* rowBodies) {
  const int m = static_cast<int>(rows_.size());
  first_.resize(m);
  if (rowBodies == nullptr) {
    for (int i = 0; i < m; ++i) {
      const double* row = a + static_cast<std::size_t>(rows_[i]) * n;
      int j = 0;
      while (j < i && row[rows_[j]] == 0) ++j;
      first_[i] = j;
    }
    return;
  }
  // A row starts at the first row that shares one of its bodies.
  bodyFirst_.assign(bodyPoints_.size(), -1);
  for (int i = 0; i < m; ++i) {
    first_[i] = i;
    for (const int body : (*rowBodies)[rows_[i]]) {
      if (body < 0) continue;
      if (static_cast<std::size_t>(body) >= bodyFirst_.size()) bodyFirst_.resize(body + 1, -1);
      int& at = bodyFirst_[body];
      if (at < 0) at = i;
      first_[i] = std::min(first_[i], at);
    }
  }
}

std::size_t ActiveSetSolver::layOutProfile() {
  const int m = static_cast<int>(rows_.size());
  start_.resize(m);
  std::size_t total = 0;
  for (int i = 0; i < m; ++i) {
    start_[i] = total;  // row i's entry in column j is at start_[i] + j - first_[i]
    total += static_cast<std::size_t>(i - first_[i] + 1);
  }
  return total;
}

bool ActiveSetSolver::factor(const double* a, int n) {
  const int m = static_cast<int>(rows_.size());
  l_.resize(layOutProfile());
  for (int i = 0; i < m; ++i) {
    const double* row = a + static_cast<std::size_t>(rows_[i]) * n;
    double* li = l_.data() + start_[i];
    const int fi = first_[i];
    for (int j = fi; j < i; ++j) {
      const double* lj = l_.data() + start_[j];
      const int fj = first_[j];
      double s = row[rows_[j]];
      for (int k = std::max(fi, fj); k < j; ++k) s -= li[k - fi] * lj[k - fj];
      li[j - fi] = s / lj[j - fj];
    }
    double d = row[rows_[i]];
    for (int k = fi; k < i; ++k) d -= li[k - fi] * li[k - fi];
    if (!(d > 0)) return false;
    li[i - fi] = std::sqrt(d);
  }
  return true;
}

bool ActiveSetSolver::factorSliding(const double* a, int n, const btVectorXu& hi) {
  const int m = static_cast<int>(rows_.size());
  // M(i, j): A's entry, and where row j is a point's normal, what its
  // sliding friction rows (x_f = s hi x_j) add to row i.
  const auto element = [&](int i, int j) {
    const double* row = a + static_cast<std::size_t>(rows_[i]) * n;
    double v = row[rows_[j]];
    const int point = pointOf_[rows_[j]];
    if (point >= 0) {
      for (const int f : frictionRows_[point]) {
        if (slide_[f] != 0) v += slide_[f] * hi[f] * row[f];
      }
    }
    return v;
  };
  const std::size_t total = layOutProfile();
  l_.resize(total);
  u_.resize(total);
  // Doolittle along the profile: row i of L (unit diagonal) and column i
  // of U, both from first_[i].
  for (int i = 0; i < m; ++i) {
    double* li = l_.data() + start_[i];
    double* ui = u_.data() + start_[i];
    const int fi = first_[i];
    for (int j = fi; j < i; ++j) {
      const double* lj = l_.data() + start_[j];
      const double* uj = u_.data() + start_[j];
      const int fj = first_[j];
      double s = element(i, j), t = element(j, i);
      for (int k = std::max(fi, fj); k < j; ++k) {
        s -= li[k - fi] * uj[k - fj];
        t -= lj[k - fj] * ui[k - fi];
      }
      li[j - fi] = s / uj[j - fj];
      ui[j - fi] = t;
    }
    double d = element(i, i);
    for (int k = fi; k < i; ++k) d -= li[k - fi] * ui[k - fi];
    if (!(d > 0)) return false;
    ui[i - fi] = d;
  }
  return true;
}

void ActiveSetSolver::substitute(const btVectorXu& b, bool sliding) {
  const int m = static_cast<int>(rows_.size());
  // L y = b, then U x = y (L^T for the Cholesky factor), each along the
  // rows' profiles.
  for (int i = 0; i < m; ++i) {
    const double* li = l_.data() + start_[i];
    const int fi = first_[i];
    double s = b[rows_[i]];
    for (int k = fi; k < i; ++k) s -= li[k - fi] * y_[k];
    y_[i] = sliding ? s : s / li[i - fi];
  }
  const std::vector<double>& upper = sliding ? u_ : l_;
  for (int i = m - 1; i >= 0; --i) {
    const double* ui = upper.data() + start_[i];
    const int fi = first_[i];
    const double xi = y_[i] / ui[i - fi];
    solution_[rows_[i]] = xi;
    for (int k = fi; k < i; ++k) y_[k] -= ui[k - fi] * xi;
  }
}

}  // namespace tabletop
