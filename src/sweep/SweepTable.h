#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sweep/SweepRun.h"

namespace tabletop {

/// A sweep's table on disk, PREFIX.csv and PREFIX.jsonl (one JSON object
/// per line), a row appended to each as each run finishes, in run order.
/// Opening a table a sweep already began resumes it: the rows complete in
/// both files are kept (checked to be this spec's: the same columns, the
/// same runs with the same values) and a row cut off by a kill is dropped,
/// so the files never hold a half row. An advisory lock keeps a second
/// sweep out of the same table.
class SweepTable {
 public:
  /// Throws std::runtime_error (one line) when the files cannot be written,
  /// are locked, or hold another sweep's table.
  SweepTable(const std::string& prefix, const SweepSpec& spec);
  ~SweepTable();
  SweepTable(const SweepTable&) = delete;
  SweepTable& operator=(const SweepTable&) = delete;

  /// Runs already in the table: runs 0 to done() - 1.
  std::size_t done() const { return done_; }
  /// Appends run done()'s row to both files; throws std::runtime_error
  /// when a write fails.
  void append(const SweepRow& row);

  /// The rows in the table now, read back from the JSON lines.
  std::vector<SweepRow> rows() const;

  std::string csvPath() const { return prefix_ + ".csv"; }
  std::string jsonPath() const { return prefix_ + ".jsonl"; }

 private:
  // Opens the CSV and keeps the rows complete in both files.
  void resume(const SweepSpec& spec);

  std::string prefix_;
  std::vector<std::string> columns_;
  int csv_ = -1;
  int json_ = -1;
  std::size_t done_ = 0;
};

/// The CSV heading line (with its newline).
std::string csvHeading(const std::vector<std::string>& columns);
/// A row as one CSV line (with its newline).
std::string csvLine(const SweepRow& row);
/// A row as one JSON object keyed by the columns, on one line (with its newline).
std::string jsonLine(const std::vector<std::string>& columns, const SweepRow& row);

}  // namespace tabletop
