#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/Arrow.h"
#include "core/Vec3.h"

namespace tabletop::python {

/// One call that changed a scene from Python: steps taken, the script's
/// due actions carried out, a push, a turn, an impulse, a force and torque
/// for a step, a new timestep or gravity.
struct SceneCall {
  enum class Kind { Steps, RunDue, Push, Rotate, Impulse, Load, Timestep, Gravity };
  Kind kind = Kind::Steps;
  long long count = 0;         ///< Steps: how many were taken
  Arrow arrow;                 ///< Push (its entity names the body of Rotate, Impulse, Load too)
  PushMagnitude magnitude;     ///< Push
  double value = 0.0;          ///< Rotate: degrees; Timestep: s; Gravity: m/s^2
  Vec3 vector;                 ///< Impulse: N s; Load: the force, N
  Vec3 torque;                 ///< Load, N m
  std::optional<Vec3> point;   ///< Impulse, Load: where it acts, m, world frame

  /// Whether the call names an entity (arrow.entity).
  bool namesEntity() const {
    return kind == Kind::Push || kind == Kind::Rotate || kind == Kind::Impulse || kind == Kind::Load;
  }

  static SceneCall of(Kind kind, long long count = 0, double value = 0.0) {
    SceneCall call;
    call.kind = kind;
    call.count = count;
    call.value = value;
    return call;
  }
};

/// Every call that changed a scene since it was built, in order. The
/// simulation is deterministic, so building the scene again and making
/// the same calls gives a bit-identical state: how reset(), set_state(),
/// copy() and pickling restore a scene exactly. Runs of steps are kept as
/// one count; at most kMaxCalls calls are kept (a longer history cannot
/// be saved).
class SceneHistory {
 public:
  static constexpr std::size_t kMaxCalls = 100000;
  /// Its JSON is at most about 100 bytes a call: a pickle's is refused past this.
  static constexpr std::size_t kMaxJsonBytes = 64u << 20;

  /// Adds `call`, merging steps into the steps before them.
  void add(const SceneCall& call);
  const std::vector<SceneCall>& calls() const { return calls_; }
  /// The steps taken in all.
  double steps() const { return steps_; }
  /// False once more than kMaxCalls calls were made.
  bool complete() const { return complete_; }
  void clear() { *this = SceneHistory(); }

  nlohmann::json toJson() const;
  /// The history `j` describes, each value checked as the call's argument
  /// is: std::invalid_argument naming what is wrong (a pickle may come
  /// from anyone).
  static SceneHistory fromJson(const nlohmann::json& j);

 private:
  std::vector<SceneCall> calls_;
  double steps_ = 0.0;  // the Steps calls' counts summed
  bool complete_ = true;
};

}  // namespace tabletop::python
