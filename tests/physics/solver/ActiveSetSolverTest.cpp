// ActiveSetSolver: the contact problems of resting and sliding islands
// solved by the guess, checked against the complementarity conditions that define their
// solution; the problems it must hand to the fallback handed on.

#include "physics/solver/ActiveSetSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <LinearMath/btVector3.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

struct Body {
  double mass;
  btVector3 inertia;  // principal moments, kg m^2 (axes along the world's)
  btVector3 centre;
};

// A contact point between body `a` (-1: the ground) and body `b`, with the
// normal pointing from a to b; its rows: the normal, then two friction rows.
struct Point {
  int a, b;
  btVector3 at, normal;
  double mu;
};

// Bullet's MLCP for a set of points: normal rows first, then each point's
// two friction rows, A = J M^-1 J^T + cfm on the diagonal, b = -J v for the
// bodies' velocities v (6 per body: linear, then angular): each row's
// velocity brought to zero.
struct Problem {
  btMatrixXu A;
  btVectorXu b, x, lo, hi;
  btAlignedObjectArray<int> dependency;
  std::vector<std::vector<double>> jac;  // per row: 6 entries per body
  std::vector<double> inverseMass;       // per body entry: 1/m or 1/I
  ActiveSetSolver::RowBodies bodies;     // per row: its two bodies, -1 for the ground
};

// The bodies' change of velocity, M^-1 J^T x (6 per body).
std::vector<double> velocityChange(const Problem& p, const btVectorXu& x) {
  std::vector<double> dv(p.inverseMass.size(), 0.0);
  for (std::size_t r = 0; r < p.jac.size(); ++r) {
    for (std::size_t c = 0; c < dv.size(); ++c) dv[c] += p.inverseMass[c] * p.jac[r][c] * x[static_cast<int>(r)];
  }
  return dv;
}

Problem makeProblem(const std::vector<Body>& bodies, const std::vector<Point>& points,
                    const std::vector<double>& velocities, double cfm = 1e-8 * 60) {
  const int np = static_cast<int>(points.size());
  const int n = 3 * np;
  // Each row's Jacobian: 6 entries per body.
  std::vector<std::vector<double>> jac(n, std::vector<double>(6 * bodies.size(), 0.0));
  Problem p;
  p.b.resize(n), p.x.resize(n), p.lo.resize(n), p.hi.resize(n);
  p.dependency.resize(n);
  for (int k = 0; k < np; ++k) {
    const Point& pt = points[k];
    btVector3 t1, t2;
    btPlaneSpace1(pt.normal, t1, t2);
    const btVector3 dirs[3] = {pt.normal, t1, t2};
    const int rows[3] = {k, np + 2 * k, np + 2 * k + 1};
    for (int d = 0; d < 3; ++d) {
      const int r = rows[d];
      for (int side = 0; side < 2; ++side) {
        const int body = side == 0 ? pt.a : pt.b;
        if (body < 0) continue;
        const double sign = side == 0 ? -1.0 : 1.0;
        const btVector3 lever = (pt.at - bodies[body].centre).cross(dirs[d]);
        for (int c = 0; c < 3; ++c) {
          jac[r][6 * body + c] = sign * dirs[d][c];
          jac[r][6 * body + 3 + c] = sign * lever[c];
        }
      }
      p.b[r] = 0;
      for (std::size_t c = 0; c < velocities.size(); ++c) p.b[r] -= jac[r][c] * velocities[c];
      p.x[r] = 0;
      p.lo[r] = d == 0 ? 0.0 : -pt.mu;
      p.hi[r] = d == 0 ? 1e10 : pt.mu;
      p.dependency[r] = d == 0 ? -1 : k;
      p.bodies.resize(n);
      p.bodies[r] = {pt.a, pt.b};
    }
  }
  for (const Body& body : bodies) {
    for (int c = 0; c < 3; ++c) p.inverseMass.push_back(1 / body.mass);
    for (int c = 0; c < 3; ++c) p.inverseMass.push_back(1 / body.inertia[c]);
  }
  p.A.resize(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      double v = i == j ? cfm : 0.0;
      for (std::size_t body = 0; body < bodies.size(); ++body) {
        for (int c = 0; c < 3; ++c) {
          v += jac[i][6 * body + c] * jac[j][6 * body + c] / bodies[body].mass;
          v += jac[i][6 * body + 3 + c] * jac[j][6 * body + 3 + c] / bodies[body].inertia[c];
        }
      }
      p.A.setElem(i, j, v);
    }
  }
  p.jac = std::move(jac);
  return p;
}

// Whether x solves the problem: each normal impulse non-negative with its
// gap speed w = A x - b zero where it presses and non-negative where it
// does not, each friction impulse inside its cone with w zero, or at its
// bound with w against it (a slip the impulse opposes; a point that does
// not press bounds its friction at zero and says nothing of w). Returns
// the worst violation, m/s or N s.
constexpr double kAtBound = 1e-12;  // N s: a friction impulse this near its bound is at it

double violation(const Problem& p, const btVectorXu& x) {
  const int n = p.b.rows();
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    double w = -p.b[i];
    for (int j = 0; j < n; ++j) w += p.A(i, j) * x[j];
    if (p.dependency[i] < 0) {
      worst = std::max(worst, -x[i]);
      worst = std::max(worst, x[i] > 0 ? std::abs(w) : -w);
    } else {
      const double bound = p.hi[i] * x[p.dependency[i]];
      worst = std::max(worst, std::abs(x[i]) - bound);
      if (std::abs(x[i]) < bound - kAtBound) worst = std::max(worst, std::abs(w));
      else if (bound > 0) worst = std::max(worst, x[i] > 0 ? w : -w);
    }
  }
  return worst;
}

// A column of boxes of random masses (0.05 to 5 kg) and sizes resting on
// the ground, four corner points under each, each box falling at g dt and
// moving besides at up to 0.05 mm/s and 0.5 mrad/s: the ten-cube stack's
// problem.
Problem stackProblem(int count, std::mt19937& random) {
  std::uniform_real_distribution<double> mass(0.05, 5.0), half(0.02, 0.1), unit(-1.0, 1.0);
  std::vector<double> velocities;
  std::vector<Body> bodies;
  std::vector<Point> points;
  double top = 0, below = 1e9;  // the top of the column, the half size of its top box
  for (int i = 0; i < count; ++i) {
    const double m = mass(random), h = half(random);
    const double moment = m * (2 * h) * (2 * h) / 6;
    bodies.push_back({m, btVector3(moment, moment, moment), btVector3(0, top + h, 0)});
    const double corner = std::min(h, below);  // the points: the smaller face's corners
    for (const double sx : {-1.0, 1.0}) {
      for (const double sz : {-1.0, 1.0}) {
        points.push_back({i - 1, i, btVector3(sx * corner, top, sz * corner), btVector3(0, 1, 0), 0.5});
      }
    }
    top += 2 * h;
    below = h;
    for (int c = 0; c < 6; ++c) velocities.push_back((c < 3 ? 5e-5 : 5e-4) * unit(random) - (c == 1 ? 9.81 / 60 : 0));
  }
  return makeProblem(bodies, points, velocities);
}

// The stack above with its top box sliding at 0.1 to 1 m/s along its
// points' first friction direction, either way (Bullet lays a slipping
// point's first friction row along its slip), the friction under it 0.05
// to 0.3: the top box's first friction rows slip, the others stick.
Problem slidingStackProblem(int count, std::mt19937& random) {
  std::uniform_real_distribution<double> speed(0.1, 1.0), mu(0.05, 0.3);
  std::bernoulli_distribution backwards(0.5);
  Problem p = stackProblem(count, random);
  btVector3 along, across;
  btPlaneSpace1(btVector3(0, 1, 0), along, across);
  const btVector3 slip = (backwards(random) ? -1.0 : 1.0) * speed(random) * along;
  const double friction = mu(random);
  const int np = 4 * count;
  for (int r = 0; r < 3 * np; ++r) {
    for (int c = 0; c < 3; ++c) p.b[r] -= p.jac[r][6 * (count - 1) + c] * slip[c];
  }
  for (int k = np - 4; k < np; ++k) {
    for (const int r : {np + 2 * k, np + 2 * k + 1}) p.lo[r] = -friction, p.hi[r] = friction;
  }
  return p;
}

// A fallback that says whether it was asked.
class Recorder : public btMLCPSolverInterface {
 public:
  bool solveMLCP(const btMatrixXu&, const btVectorXu&, btVectorXu&, const btVectorXu&, const btVectorXu&,
                 const btAlignedObjectArray<int>&, int, bool) override {
    ++calls;
    return false;
  }
  int calls = 0;
};

// Stacks of 1 to 20 boxes: every problem solved by the guess, to the
// conditions within 1e-12, and the bodies' velocities after it those of
// Dantzig's pivoting within 1e-9 m/s and rad/s. Given the rows' bodies,
// the solver finds the same answer to the last bit without scanning A. (The impulses themselves
// differ more: how a face's load is shared among its four corners is
// fixed only by the CFM, and both solutions keep it to rounding.)
TEST(ActiveSetSolver, SolvesRestingStacksByTheGuess) {
  std::mt19937 random(7);
  btDantzigSolver dantzig;
  ActiveSetSolver solver(dantzig);
  for (int trial = 0; trial < 40; ++trial) {
    const int count = 1 + trial % 20;
    Problem p = stackProblem(count, random);
    btVectorXu x = p.x;
    ASSERT_TRUE(solver.solveMLCP(p.A, p.b, x, p.lo, p.hi, p.dependency, 0));
    EXPECT_EQ(solver.solved(), 2 * trial + 1) << count << " boxes: handed on";  // two solves a trial
    EXPECT_LT(violation(p, x), 1e-12) << count << " boxes";
    btVectorXu fromBodies = p.x;
    ASSERT_EQ(solver.solve(p.A, p.b, fromBodies, p.lo, p.hi, p.dependency, &p.bodies),
              ActiveSetSolver::Answer::kByGuess);
    for (int i = 0; i < p.b.rows(); ++i) EXPECT_EQ(fromBodies[i], x[i]) << count << " boxes, row " << i;
    btVectorXu pivoted = p.x;
    ASSERT_TRUE(dantzig.solveMLCP(p.A, p.b, pivoted, p.lo, p.hi, p.dependency, 0));
    const std::vector<double> guessed = velocityChange(p, x), exact = velocityChange(p, pivoted);
    for (std::size_t c = 0; c < exact.size(); ++c) EXPECT_NEAR(guessed[c], exact[c], 1e-9) << count << " boxes, " << c;
  }
}

// A rod on the ground, struck up at one end: the other end goes down
// (1/m - L^2 / (4 I) < 0), so the first guess (only the struck end
// presses) is wrong, and the second takes both ends in. Closed form, the
// rod alone: with both ends held, x0 + x1 = m v and the turn cancels.
TEST(ActiveSetSolver, TakesInAPointTheFirstGuessLeftOut) {
  const double m = 2.0, length = 1.0;
  const double moment = m * length * length / 12;
  const std::vector<Body> rod = {{m, btVector3(moment, moment, moment), btVector3(0, 0, 0)}};
  const std::vector<Point> ends = {{-1, 0, btVector3(-0.5, 0, 0), btVector3(0, 1, 0), 0.0},
                                   {-1, 0, btVector3(0.5, 0, 0), btVector3(0, 1, 0), 0.0}};
  // End 0 closes at 1 m/s, end 1 opens at 0.1 m/s: the rod falls at
  // 0.45 m/s and turns at 1.1 rad/s.
  Problem p = makeProblem(rod, ends, {0, -0.45, 0, 0, 0, 1.1});
  ASSERT_NEAR(p.b[0], 1.0, 1e-12);
  ASSERT_NEAR(p.b[1], -0.1, 1e-12);
  Recorder never;
  ActiveSetSolver solver(never);
  btVectorXu x = p.x;
  ASSERT_TRUE(solver.solveMLCP(p.A, p.b, x, p.lo, p.hi, p.dependency, 0));
  EXPECT_EQ(never.calls, 0);
  EXPECT_GT(x[1], 0.0) << "the end that opened presses";
  EXPECT_LT(violation(p, x), 1e-12);
  // Both ends' gap speeds reach their targets: the rod rises at the mean,
  // 0.45 m/s, and turns at (1 - (-0.1)) / L = 1.1 rad/s: x0 + x1 = m 0.45,
  // (x1 - x0) L / 2 = I 1.1 (to the CFM's 1e-6).
  EXPECT_NEAR(x[0] + x[1], m * 0.45, 1e-6);
  EXPECT_NEAR((x[0] - x[1]) * length / 2, moment * 1.1, 1e-6);
}

// A cube sliding on the ground along its first friction direction at v,
// falling at g dt: every corner presses, the sliding rows sit at mu times
// their normals and the cross rows stick. Closed form: the cube stops
// falling and turning, and slows by mu g dt: v' = v - mu g dt along the
// slip, 0 across it (to the CFM's 1e-6). A cube whose friction cannot
// hold it (mu 1e-6, slipping just under kSlipSpeed: guessed to stick)
// is moved to sliding by the second guess.
TEST(ActiveSetSolver, SolvesASlideWithFrictionAtItsBound) {
  const double m = 1.5, h = 0.05, mu = 0.3, v = 0.5, g = 9.81, dt = 1.0 / 60;
  const double moment = m * (2 * h) * (2 * h) / 6;
  const std::vector<Body> cube = {{m, btVector3(moment, moment, moment), btVector3(0, h, 0)}};
  std::vector<Point> corners;
  for (const double sx : {-h, h}) {
    for (const double sz : {-h, h}) corners.push_back({-1, 0, btVector3(sx, 0, sz), btVector3(0, 1, 0), mu});
  }
  btVector3 along, across;
  btPlaneSpace1(btVector3(0, 1, 0), along, across);
  const btVector3 slip = v * along;
  Problem p = makeProblem(cube, corners, {slip.x(), -g * dt, slip.z(), 0, 0, 0});
  Recorder never;
  ActiveSetSolver solver(never);
  btVectorXu x = p.x;
  ASSERT_TRUE(solver.solveMLCP(p.A, p.b, x, p.lo, p.hi, p.dependency, 0));
  EXPECT_EQ(never.calls, 0);
  EXPECT_LT(violation(p, x), 1e-12);
  const std::vector<double> dv = velocityChange(p, x);
  const btVector3 after = slip + btVector3(dv[0], -g * dt + dv[1], dv[2]);
  EXPECT_NEAR(after.dot(along), v - mu * g * dt, 1e-6);
  EXPECT_NEAR(after.dot(across), 0.0, 1e-6);
  EXPECT_NEAR(after.y(), 0.0, 1e-6);
  for (int c = 3; c < 6; ++c) EXPECT_NEAR(dv[c], 0.0, 1e-6) << "turn " << c;

  Problem slight = makeProblem(cube, corners, {0, -g * dt, 0, 0, 0, 0});
  for (int r = 4; r < 12; ++r) slight.hi[r] = 1e-6, slight.lo[r] = -1e-6, slight.b[r] = 0.9 * ActiveSetSolver::kSlipSpeed;
  x = slight.x;
  ASSERT_TRUE(solver.solveMLCP(slight.A, slight.b, x, slight.lo, slight.hi, slight.dependency, 0));
  EXPECT_EQ(never.calls, 0);
  EXPECT_LT(violation(slight, x), 1e-12);
  for (int r = 4; r < 12; ++r) EXPECT_NEAR(std::abs(x[r]), 1e-6 * x[slight.dependency[r]], 1e-18) << "row " << r;
}

// Stacks of 1 to 12 boxes whose top box slides: solved by the guess, to
// the conditions within 1e-12, with the top box's first friction rows at
// their bounds. (Dantzig's pivoting, which bounds each friction row by
// its normal as it stood when the row was taken in, leaves the top box's
// friction at the same share on every corner while the slide's torque
// moves the load forwards: its answers break Coulomb's law at a corner by
// up to half the friction impulse, and are no reference here.)
TEST(ActiveSetSolver, SolvesSlidingStacksByTheGuess) {
  std::mt19937 random(13);
  Recorder never;
  ActiveSetSolver solver(never);
  for (int trial = 0; trial < 36; ++trial) {
    const int count = 1 + trial % 12;
    Problem p = slidingStackProblem(count, random);
    btVectorXu x = p.x;
    ASSERT_EQ(solver.solve(p.A, p.b, x, p.lo, p.hi, p.dependency, &p.bodies), ActiveSetSolver::Answer::kByGuess)
        << count << " boxes";
    EXPECT_LT(violation(p, x), 1e-12) << count << " boxes";
    const int np = 4 * count;
    for (int k = np - 4; k < np; ++k) {
      const int along = np + 2 * k;
      EXPECT_NEAR(std::abs(x[along]), p.hi[along] * x[k], kAtBound) << count << " boxes, corner " << k;
    }
  }
  EXPECT_EQ(never.calls, 0);
}

// Problems the guess must not answer go to the fallback: a slip that
// friction stops within the step (its answer would turn the slip round:
// the guess never makes a sliding row stick), a row bounded on both
// sides that hangs on no other (a joint's), and a right-hand side that is
// not a number: the fallback's answer is the solver's.
TEST(ActiveSetSolver, HandsOnWhatTheGuessMustNotAnswer) {
  std::mt19937 random(11);
  Recorder fallback;
  ActiveSetSolver solver(fallback);

  // A cube slipping at twice kSlipSpeed that friction (mu 0.5, taking
  // 82 mm/s in a step) stops.
  const double m = 1.0, h = 0.05, moment = m * (2 * h) * (2 * h) / 6;
  const std::vector<Body> cube = {{m, btVector3(moment, moment, moment), btVector3(0, h, 0)}};
  std::vector<Point> corners;
  for (const double sx : {-h, h}) {
    for (const double sz : {-h, h}) corners.push_back({-1, 0, btVector3(sx, 0, sz), btVector3(0, 1, 0), 0.5});
  }
  btVector3 along, across;
  btPlaneSpace1(btVector3(0, 1, 0), along, across);
  const btVector3 slip = 2 * ActiveSetSolver::kSlipSpeed * along;
  Problem slipping = makeProblem(cube, corners, {slip.x(), -9.81 / 60, slip.z(), 0, 0, 0});
  btVectorXu x = slipping.x;
  EXPECT_FALSE(solver.solveMLCP(slipping.A, slipping.b, x, slipping.lo, slipping.hi, slipping.dependency, 0));
  EXPECT_EQ(fallback.calls, 1);

  Problem joint = stackProblem(2, random);
  joint.lo[0] = -1, joint.hi[0] = 1;
  EXPECT_FALSE(solver.solveMLCP(joint.A, joint.b, x, joint.lo, joint.hi, joint.dependency, 0));
  EXPECT_EQ(fallback.calls, 2);

  // A non-finite right-hand side: handed on, x left as it was.
  Problem broken = stackProblem(2, random);
  broken.b[0] = std::numeric_limits<double>::quiet_NaN();
  x = broken.x;
  EXPECT_FALSE(solver.solveMLCP(broken.A, broken.b, x, broken.lo, broken.hi, broken.dependency, 0));
  EXPECT_EQ(fallback.calls, 3);
  EXPECT_EQ(x[1], 0.0);
  // Handed on with the rows' bodies, the answer says the fallback failed too.
  EXPECT_EQ(solver.solve(joint.A, joint.b, x, joint.lo, joint.hi, joint.dependency, &joint.bodies),
            ActiveSetSolver::Answer::kNone);
  EXPECT_EQ(fallback.calls, 4);
  EXPECT_EQ(solver.solved(), 0);
  EXPECT_EQ(solver.handedOn(), 4);
}

}  // namespace
}  // namespace tabletop
