#pragma once

#include <vector>

#include "io/ResultTable.h"
#include "measure/BenchRuns.h"
#include "scenes/LawScenes.h"

namespace tabletop {

/// The laws every shape on every support must follow, each against its
/// closed form computed here (bench --laws; tests/physics/laws/SlideTest.cpp holds
/// the same laws to their tolerances):
///  - slide: a cube, a box, cylinders and a cone given v0 = 1.6 m/s
///    (mu 0.25) travel d = v0^2 / (2 mu g) without turning;
///  - roll: spheres, and a cylinder lying on its side pushed across its
///    axis (rf 2 mm), given v0 = 0.4 m/s slip, then roll, to
///    rollingDistance(); the same cylinder pushed along its axis slides;
///  - step: every shape pushed by a 0.2 m step travels it;
///  - spin: a cube, a box and cylinders spun about the vertical at 5 and
///    -12 rad/s turn w0^2 / (2 alpha) and stay where they stand
///    (tests/physics/laws/SpinTest.cpp); the error is how far the base's contact
///    points end from their closed-form place, or the drift if larger;
///  - circle: cones and a truncated cone set rolling on their sides,
///    precessing at -2 and 3 rad/s, keep their centre of mass on its level
///    circle about the apex for 3 s (scenes/ConeRoll.h,
///    tests/physics/laws/ConeRollTest.cpp);
///  - strike: a cube and a box struck level with their centre but off it
///    (J = 0.225 N s) on a frictionless support slide at J / m and turn
///    at (r x J) / I about the vertical;
///  - free: a box spun about each principal axis in free flight keeps
///    turning steadily about it (one row, support "none");
///  - bounce: a sphere, and every other shape landing flat, dropped 0.3 m
///    with e = 0, 0.5 and 0.9, follows free fall and its rebound at e
///    times the impact speed (tests/physics/laws/RestitutionTest.cpp).
/// Each on the table, the floor and a slab resting on the floor, pushed at
/// 0, 45, 77 and 200 degrees.
struct LawPoint {
  std::string law, shape, support;
  double rate = 0;         ///< Hz
  double worstError = 0;   ///< m, over the push angles or the drops
  double worstTurn = 0;    ///< degrees, likewise (not for spheres)
};

/// Every law at every rate; with `jobs` > 1 the runs go to that many
/// worker processes (io/ProcessPool.h), the points coming back in the
/// same order with the same values.
std::vector<LawPoint> measureLaws(const std::vector<double>& rates, const MeasureHooks& hooks, int jobs = 1);

/// One row per law, shape and support, the worst error at each rate.
ResultTable lawTable(const std::vector<LawPoint>& points);

}  // namespace tabletop
