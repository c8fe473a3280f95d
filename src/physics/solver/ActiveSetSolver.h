#pragma once

#include <array>
#include <vector>

#include <BulletDynamics/MLCPSolvers/btMLCPSolverInterface.h>

namespace tabletop {

/// An island's contact problem as Bullet's MLCP solver poses it (A x = b + w,
/// each x between lo and hi with w >= 0 at lo, w <= 0 at hi and w = 0
/// between; a friction row's bounds are +-hi times its normal row's x),
/// solved the way the problems of islands at rest and of slides look:
/// every pressing point's normal row an equation, each friction row either
/// an equation (it sticks) or at the bound that opposes its slip.
///
/// It guesses which points press (those that pressed in the last step, and
/// those whose gap does not open faster than kOpeningSpeed) and which
/// friction rows slide (those slipping faster than kSlipSpeed, against the
/// slip), solves the rest as equations, then moves a point whose impulse
/// came out negative out of the guess and one whose gap would close into
/// it, and a sticking row outside its cone to its bound, and solves again
/// (block principal pivoting), at most kMaxGuesses times. With no row
/// sliding the equations are A's, positive definite (Bullet's global CFM
/// on every row), and solved by a Cholesky factorization; with a sliding
/// row its impulse is its normal's times +-hi, which makes the reduced
/// matrix non-symmetric, and solved by an LU factorization without row
/// exchanges. Friction bounds hang on the normals, though, and where a
/// point slips a sticking answer can exist beside the sliding one,
/// pressing the bodies together harder and gaining energy (a heavy cone
/// pushed fast over a light box). So a
/// sliding row is never made to stick: a problem whose answer would turn a
/// slip round, a guess that does not settle, or a non-positive pivot goes
/// to `fallback` (Dantzig's pivoting). Where both answer, they agree on
/// the normal impulses; on friction the guess keeps Coulomb's law where
/// Dantzig, which fixes a friction row's bounds from its normal as it
/// stood when the row was taken in, can leave friction on a point whose
/// normal ended at zero.
///
/// Why: Dantzig's pivoting adds one row at a time and solves the
/// triangular factors afresh for each, about 2 n^3 operations for n rows;
/// the ten-cube stack's 120 rows took 2.9 M instructions a step. The
/// factorization here runs along the profile of A, whose rows are ordered
/// point by point and the points by a reverse Cuthill-McKee sweep over the
/// points that share a body, so a stack costs rows times the square of the
/// rows of two contacts, not the cube of all its rows.
class ActiveSetSolver : public btMLCPSolverInterface {
 public:
  explicit ActiveSetSolver(btMLCPSolverInterface& fallback) : fallback_(fallback) {}

  bool solveMLCP(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x, const btVectorXu& lo, const btVectorXu& hi,
                 const btAlignedObjectArray<int>& limitDependency, int numIterations, bool useSparsity = true) override;

  /// Each row's two bodies (an index per body, -1 for one that does not
  /// move). Rows with no body in common meet in a zero of A, so with these
  /// the points' neighbours and the factor's profile come from the bodies,
  /// not from scanning A for zeros (a tenth of the ten-cube stack's step).
  using RowBodies = std::vector<std::array<int, 2>>;
  /// Which way a problem was answered: by the guess, by the fallback, or
  /// not at all (the fallback failed too).
  enum class Answer { kByGuess, kByFallback, kNone };
  /// As above, with the rows' bodies (nullptr, or not one per row: scan A),
  /// saying which way it was answered.
  Answer solve(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x, const btVectorXu& lo, const btVectorXu& hi,
               const btAlignedObjectArray<int>& limitDependency, const RowBodies* rowBodies);

  /// The guess alone, a sliding row whose answer would turn its slip round
  /// made to stick: for a problem the fallback failed on (a cube spun on
  /// the table whose spin stops inside a scene's first step left Dantzig's
  /// pivoting failing twice, and sweeps left it creeping). False if the
  /// guess does not settle.
  bool solveStickingTurns(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x, const btVectorXu& lo,
                          const btVectorXu& hi, const btAlignedObjectArray<int>& limitDependency,
                          const RowBodies* rowBodies);

  /// How many problems were solved by the guess, and how many handed on.
  long solved() const { return solved_; }
  long handedOn() const { return handedOn_; }

  /// A friction row that slips faster than this (m/s) is guessed to slide.
  static constexpr double kSlipSpeed = 1e-3;
  /// A point whose gap opens slower than this (m/s) is guessed to press: the
  /// points of a stack at rest open and close by rounding, and a guess
  /// that left them out took a sweep of guesses per layer.
  static constexpr double kOpeningSpeed = 1e-3;
  /// Problems of at most this many points are factored whole, unordered.
  static constexpr int kWholePoints = 8;
  /// The most guesses before the problem is handed on.
  static constexpr int kMaxGuesses = 8;
  /// A point out of the guess joins it when its gap would close faster
  /// than this, m/s: below it the two answers differ by rounding.
  static constexpr double kClosingTolerance = 1e-12;

 private:
  // What the guess does with a sliding row whose answer turns its slip
  // round: hands the problem on (the fallback's to answer), or makes the
  // row stick.
  enum class TurnedRows { kHandOn, kStick };
  bool solveByGuess(const btMatrixXu& A, const btVectorXu& b, const btVectorXu& lo, const btVectorXu& hi,
                    const btAlignedObjectArray<int>& limitDependency, const RowBodies* rowBodies, TurnedRows turned,
                    btVectorXu& x);
  // Finds the points (normal rows) and each one's friction rows; false if
  // the problem is not a contact problem the guess may answer.
  bool collectPoints(const btVectorXu& b, const btVectorXu& lo, const btVectorXu& hi,
                     const btAlignedObjectArray<int>& limitDependency);
  // Each point's neighbours (the points it meets in a non-zero of A): from
  // the rows' bodies when given, else from A's normal rows.
  void findNeighbours(const double* a, int n, const RowBodies* rowBodies);
  // Orders the points (normal rows) by reverse Cuthill-McKee over their
  // neighbours; fills order_.
  void orderPoints();
  // Finds where each row of rows_ starts along the profile (first_), from
  // the rows' bodies when given, else by scanning A.
  void findProfile(const double* a, int n, const RowBodies* rowBodies);
  // Sets where each row of rows_ starts in the factor's storage (start_),
  // from its profile; returns the storage's length.
  std::size_t layOutProfile();
  // Factors A's rows rows_ (in that order) along their profile into l_;
  // false at a non-positive pivot.
  bool factor(const double* a, int n);
  // The same for M, A's rows_ with the sliding rows' impulses written as
  // their normals' (non-symmetric), into l_ (unit lower) and u_ (upper,
  // by columns); false at a non-positive pivot.
  bool factorSliding(const double* a, int n, const btVectorXu& hi);
  // Solves with l_ (and u_ when `sliding`) for the right-hand side b over
  // rows_, into solution_.
  void substitute(const btVectorXu& b, bool sliding);
  // Sets a point's friction rows to slide against their slip, or to stick.
  void guessFriction(int point, const btVectorXu& b, const btVectorXu& hi);
  // A row's gap speed w = A x - b for the answer in solution_.
  double gapSpeed(const double* a, int n, const btVectorXu& b, int row) const;

  btMLCPSolverInterface& fallback_;
  long solved_ = 0;
  long handedOn_ = 0;
  // Scratch, kept between problems so that a step allocates nothing.
  std::vector<int> points_;          // the normal rows
  std::vector<int> pointOf_;         // each row's point (its index in points_)
  std::vector<std::vector<int>> frictionRows_;  // per point
  std::vector<std::vector<int>> neighbours_;    // per point
  std::vector<int> order_;           // points in factoring order
  std::vector<char> visited_;        // per point (orderPoints)
  std::vector<std::vector<int>> bodyPoints_;  // per body: its points (findNeighbours)
  std::vector<int> bodyFirst_;       // per body: its first row in rows_ (findProfile)
  std::vector<char> pressing_;       // per point: in the guess
  std::vector<int> rows_;            // the rows solved as equations, in order
  std::vector<int> first_;           // per row of rows_: its profile's first column
  std::vector<std::size_t> start_;   // per row of rows_: where L(i, first_[i]) is in l_
  std::vector<double> l_;            // the factor's rows along the profile
  std::vector<double> u_;            // the columns of U along the profile (factorSliding)
  std::vector<signed char> slide_;   // per row: a friction row sliding up (+1), down (-1), or sticking
  std::vector<int> slid_;            // the sliding rows of the pressing points
  std::vector<double> y_;            // per row of rows_ (substitute)
  std::vector<double> solution_;     // per row of the problem
};

}  // namespace tabletop
