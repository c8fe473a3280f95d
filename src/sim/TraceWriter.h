#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "core/Simulation.h"
#include "io/AtomicFile.h"

namespace tabletop {

/// Writes every entity's motion after every step to a CSV file, one row
/// per entity and step, in SI units:
///   t,step,entity,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz
/// (s, m, unit quaternion, m/s, rad/s). Numbers are written with 17
/// significant digits, so a trace reads back bit for bit; names are quoted
/// as RFC 4180 says. The file appears only through commit(), whole (see
/// AtomicFile). It stops at the step that takes it past `maxBytes`: then
/// problem() says so and no file is written.
class TraceWriter {
 public:
  /// The size a trace may reach unless told otherwise (run --trace-max-mb).
  static constexpr double kDefaultMaxMegabytes = 1024.0;

  /// Opens the temporary file; `names` are the entities in scenario order.
  TraceWriter(const std::string& path, std::vector<std::string> names,
              double maxBytes = kDefaultMaxMegabytes * 1e6);

  /// "" or why the file cannot be written.
  const std::string& problem() const { return problem_; }
  /// Appends the rows of the simulation's current state.
  void record(const Simulation& simulation);
  /// Puts the file in place; "" or what went wrong.
  std::string commit();

 private:
  AtomicFile file_;
  std::ofstream out_;
  std::vector<std::string> names_;
  double maxBytes_;
  std::string problem_;
};

}  // namespace tabletop
