#include "sim/DivergenceGuard.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tabletop {
namespace {

std::string message(const std::string& entity, double time, const std::string& detail) {
  std::ostringstream o;
  o << "diverged at t = " << time << " s: entity '" << entity << "': " << detail;
  return o.str();
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string shown(const Vec3& v) {
  std::ostringstream o;
  o << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return o.str();
}

}  // namespace

DivergenceError::DivergenceError(std::string entity, double time, std::string quantity, const std::string& detail)
    : std::runtime_error(message(entity, time, detail)),
      entity_(std::move(entity)),
      time_(time),
      quantity_(std::move(quantity)) {}

DivergenceGuard::DivergenceGuard(const Scenario& scenario, const Settings& settings,
                                 const std::vector<BodyMotion>& start)
    : table_(scenario.table) {
  for (const EntitySpec& e : scenario.entities) {
    names_.push_back(e.name);
    masses_.push_back(e.mass);
    radii_.push_back(e.geometry.boundingRadius());
  }
  if (!masses_.empty()) lightest_ = *std::min_element(masses_.begin(), masses_.end());
  smallest_ = 0.0;
  for (const EntitySpec& e : scenario.entities) {
    const double r = e.geometry.smallestHalfDimension();
    smallest_ = smallest_ == 0.0 ? r : std::min(smallest_, r);
  }
  // Potential energy above the floor (y = 0), the lowest any centre can go.
  for (std::size_t i = 0; i < start.size() && i < masses_.size(); ++i) {
    energy_ += masses_[i] * settings.gravity * std::max(0.0, start[i].position.y);
  }
  energy_ += kineticEnergy(start);
}

// Translational, and an upper bound on the rotational: no moment of
// inertia exceeds m R^2, R the bounding radius.
double DivergenceGuard::kineticEnergy(const std::vector<BodyMotion>& states) const {
  double e = 0.0;
  for (std::size_t i = 0; i < states.size() && i < masses_.size(); ++i) {
    const double r2 = radii_[i] * radii_[i];
    e += 0.5 * masses_[i] *
         (states[i].linearVelocity.dot(states[i].linearVelocity) +
          r2 * states[i].angularVelocity.dot(states[i].angularVelocity));
  }
  return e;
}

void DivergenceGuard::pushed(const std::vector<BodyMotion>& before, const std::vector<BodyMotion>& after) {
  energy_ += std::max(0.0, kineticEnergy(after) - kineticEnergy(before));
}

double DivergenceGuard::speedBound() const {
  return kSafety * std::sqrt(2.0 * energy_ / lightest_) + kSlack;
}

double DivergenceGuard::angularSpeedBound() const {
  return (kSafety * std::sqrt(5.0) * std::sqrt(2.0 * energy_ / lightest_) + kSlack) / smallest_;
}

void DivergenceGuard::check(const std::vector<BodyMotion>& states, double time) const {
  const double vMax = speedBound(), wMax = angularSpeedBound();
  for (std::size_t i = 0; i < states.size(); ++i) {
    const BodyMotion& s = states[i];
    const auto fail = [&](const std::string& quantity, const std::string& detail) {
      throw DivergenceError(i < names_.size() ? names_[i] : std::to_string(i), time, quantity, detail);
    };
    if (!finite(s.position)) fail("position", "position is not finite " + shown(s.position));
    if (!finite(s.linearVelocity)) fail("velocity", "velocity is not finite " + shown(s.linearVelocity));
    if (!finite(s.angularVelocity)) {
      fail("angular velocity", "angular velocity is not finite " + shown(s.angularVelocity));
    }
    for (double q : s.orientation) {
      if (!std::isfinite(q)) fail("orientation", "orientation is not finite");
    }
    // The message is built only on failure: this check runs every step.
    if (s.position.length() > kWorldRadius) {
      std::ostringstream o;
      o << "position " << shown(s.position) << " m is beyond the world's radius of " << kWorldRadius << " m";
      fail("position", o.str());
    }
    if (i < radii_.size() && s.position.y < -radii_[i]) {
      std::ostringstream o;
      o << "centre at y = " << s.position.y << " m is below the floor: the body has passed through it";
      fail("position", o.str());
    }
    // A centre inside the solid top: the body is passing through it (a
    // load far heavier than what it stands on pushes that through).
    const TableSpec& t = table_;
    if (std::abs(s.position.x - t.centreX) < 0.5 * t.width && std::abs(s.position.z - t.centreZ) < 0.5 * t.depth &&
        s.position.y < t.height && s.position.y > t.height - t.thickness) {
      std::ostringstream o;
      o << "centre at y = " << s.position.y << " m is inside the table top (" << t.height - t.thickness << " to "
        << t.height << " m): the body is passing through it";
      fail("position", o.str());
    }
    if (s.linearVelocity.length() > vMax) {
      std::ostringstream o;
      o << "speed " << s.linearVelocity.length() << " m/s exceeds the scene's bound of " << vMax
        << " m/s (energy " << energy_ << " J)";
      fail("speed", o.str());
    }
    if (s.angularVelocity.length() > wMax) {
      std::ostringstream o;
      o << "angular speed " << s.angularVelocity.length() << " rad/s exceeds the scene's bound of " << wMax
        << " rad/s (energy " << energy_ << " J)";
      fail("angular speed", o.str());
    }
  }
}

}  // namespace tabletop
