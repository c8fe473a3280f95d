#include "sim/TraceWriter.h"

#include <sstream>

#include "core/Text.h"

namespace tabletop {

TraceWriter::TraceWriter(const std::string& path, std::vector<std::string> names, double maxBytes)
    : file_(path), names_(std::move(names)), maxBytes_(maxBytes) {
  if (!file_.problem().empty()) {
    problem_ = file_.problem();
    return;
  }
  out_.open(file_.temporaryPath(), std::ios::binary | std::ios::trunc);
  if (!out_) {
    problem_ = "cannot write '" + shownText(path) + "'";
    return;
  }
  for (std::string& name : names_) name = csvField(name);
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
  if (static_cast<double>(out_.tellp()) > maxBytes_) {
    std::ostringstream why;
    why << "the trace would be larger than " << maxBytes_ / 1e6 << " MB (--trace-max-mb); none was written";
    problem_ = why.str();
    out_.close();
  }
}

std::string TraceWriter::commit() {
  if (!problem_.empty()) return problem_;
  out_.close();
  if (!out_) return "cannot finish writing '" + file_.path() + "'";
  return file_.commit();
}

}  // namespace tabletop
