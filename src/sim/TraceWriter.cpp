#include "sim/TraceWriter.h"

namespace tabletop {

TraceWriter::TraceWriter(const std::string& path, std::vector<std::string> names)
    : file_(path), out_(file_.temporaryPath()), names_(std::move(names)) {
  if (!out_) {
    problem_ = "cannot write '" + path + "'";
    return;
  }
  out_.precision(17);
  out_ << "t,step,entity,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n";
}

void TraceWriter::record(const Simulation& simulation) {
  if (!problem_.empty()) return;
  const std::vector<BodyMotion> motions = simulation.motions();
  for (std::size_t i = 0; i < motions.size() && i < names_.size(); ++i) {
    const BodyMotion& m = motions[i];
    out_ << simulation.time() << ',' << simulation.steps() << ',' << names_[i] << ',' << m.position.x << ','
         << m.position.y << ',' << m.position.z << ',' << m.orientation[0] << ',' << m.orientation[1] << ','
         << m.orientation[2] << ',' << m.orientation[3] << ',' << m.linearVelocity.x << ',' << m.linearVelocity.y
         << ',' << m.linearVelocity.z << ',' << m.angularVelocity.x << ',' << m.angularVelocity.y << ','
         << m.angularVelocity.z << '\n';
  }
}

std::string TraceWriter::commit() {
  if (!problem_.empty()) return problem_;
  out_.close();
  if (!out_) return "cannot finish writing '" + file_.path() + "'";
  return file_.commit();
}

}  // namespace tabletop
