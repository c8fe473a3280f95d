#pragma once

namespace tabletop {

/// What a simulation has done so far, counted where its cost is, so that
/// a run's work is bounded by what it does, not by what its settings say
/// (steps x iterations x entities misses contacts and parts). The counts
/// are deterministic: the same scene stops at the same step on any
/// machine. units() weighs them in nanoseconds of one core of the
/// reference machine (docs/limits.md, measured by docs/make-work.py).
struct WorkCount {
  double partBodies = 0.0;     ///< bodies x parts: each part's world-wide passes
  double contactPoints = 0.0;  ///< contact points x parts: narrow phase and events
  double pairs = 0.0;          ///< overlapping pairs x parts: the narrow phase
  double sweptRows = 0.0;      ///< rows x sweeps of the islands swept
  double pivotedRows = 0.0;    ///< rows^2 of the islands solved exactly (their matrix)
  double ruleChecks = 0.0;     ///< the rules' pair and body checks

  /// Weights, ns per count, fitted by docs/make-work.py (rounded up).
  static constexpr double kPartBody = 800.0;
  static constexpr double kContactPoint = 1800.0;
  static constexpr double kPair = 3400.0;
  static constexpr double kSweptRow = 16.0;
  static constexpr double kPivotedRow = 2.0;
  static constexpr double kRuleCheck = 26.0;
  /// The most work one run (or one stepping call from Python) may do:
  /// about ten minutes of one core of the reference machine. A run that
  /// passes it stops with a located refusal (ScriptPlayer).
  static constexpr double kRunLimit = 6e11;

  double units() const {
    return kPartBody * partBodies + kContactPoint * contactPoints + kPair * pairs + kSweptRow * sweptRows +
           kPivotedRow * pivotedRows + kRuleCheck * ruleChecks;
  }
  WorkCount& operator+=(const WorkCount& o) {
    partBodies += o.partBodies;
    contactPoints += o.contactPoints;
    pairs += o.pairs;
    sweptRows += o.sweptRows;
    pivotedRows += o.pivotedRows;
    ruleChecks += o.ruleChecks;
    return *this;
  }
};

}  // namespace tabletop
