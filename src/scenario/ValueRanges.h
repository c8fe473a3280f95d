#pragma once

#include <limits>
#include <string>

#include "core/Settings.h"

/// The numbers a scenario accepts, one home for every reader of them: the
/// file loader checks each field against these, and the Python module
/// checks its arguments against the same ranges, in the same words.
/// Every quantity has bounds that keep Bullet meaningful in double
/// precision and a run finite in time: nothing smaller than a millimetre or
/// larger than a kilometre, no mass ratio beyond 1e9, no more than
/// kMaxSteps steps.
namespace tabletop::ranges {

struct Range {
  double lo;
  double hi;
  bool loOpen;  ///< lo itself is refused (a positive quantity)
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline constexpr Range kFinite{-kInf, kInf, false};
inline constexpr Range kPositive{0.0, kInf, true};
inline constexpr Range kNonNegative{0.0, kInf, false};
inline constexpr Range kUnitInterval{0.0, 1.0, false};
inline constexpr Range kLength{1e-3, 1e3, false};        ///< metres: sizes, the table
inline constexpr Range kCoordinate{-1e4, 1e4, false};    ///< metres from the origin
inline constexpr Range kLengthOffset{-1e3, 1e3, false};  ///< metres from a body's centre, one component
inline constexpr Range kMass{1e-4, 1e5, false};          ///< kg
inline constexpr Range kAngle{-1e6, 1e6, false};         ///< degrees
inline constexpr Range kFriction{0.0, 10.0, false};
inline constexpr Range kTimestep{kMinTimestep, kMaxTimestep, false};  ///< seconds
inline constexpr Range kTime{0.0, 3600.0, false};        ///< seconds
inline constexpr Range kSpan{0.0, 3600.0, true};         ///< seconds, positive
inline constexpr Range kGravity{0.0, 100.0, false};      ///< m/s^2
inline constexpr Range kStep{0.0, 100.0, true};          ///< metres
inline constexpr Range kImpulse{0.0, 1e6, true};         ///< N s
inline constexpr Range kImpulseComponent{-1e6, 1e6, false};  ///< N s, one component
inline constexpr Range kForceComponent{-1e7, 1e7, false};    ///< N or N m, one component
inline constexpr Range kSpeedTolerance{0.0, 1.0, false};  ///< m/s
inline constexpr Range kSpeed{-1e3, 1e3, false};         ///< m/s, one component
inline constexpr Range kSpin{-1e4, 1e4, false};          ///< rad/s, one component

/// Whole-number settings: solver iterations and substeps per step.
struct IntRange {
  long long lo;
  long long hi;
};
inline constexpr IntRange kIterations{1, 10000};
inline constexpr IntRange kMaxSubsteps{1, 1000};

/// A number as messages write it (shortest form).
std::string number(double v);
/// "a positive number", "a number from 0 to 1", ...
std::string rangeText(const Range& r);
/// Finite and within the range.
bool inRange(double v, const Range& r);
/// What a message says was expected instead of `v`: "a positive number"
/// for a sign error, the range's bounds for a wrong magnitude.
std::string expectedText(double v, const Range& r);

}  // namespace tabletop::ranges
