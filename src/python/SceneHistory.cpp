#include "python/SceneHistory.h"

#include <stdexcept>

#include "core/Settings.h"
#include "scenario/ValueRanges.h"

namespace tabletop::python {
namespace {

using nlohmann::json;

nlohmann::json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

[[noreturn]] void refuse(std::size_t i, const std::string& why) {
  throw std::invalid_argument("history: call " + std::to_string(i) + ": " + why);
}

double number(const json& j, const char* key, const ranges::Range& range, std::size_t i) {
  if (!j.contains(key) || !j[key].is_number()) refuse(i, std::string("expected a number '") + key + "'");
  const double v = j[key].get<double>();
  if (!ranges::inRange(v, range)) refuse(i, std::string("'") + key + "' out of range");
  return v;
}

Vec3 vector(const json& j, const char* key, std::size_t i) {
  if (!j.contains(key) || !j[key].is_array() || j[key].size() != 3) {
    refuse(i, std::string("expected 3 numbers '") + key + "'");
  }
  double c[3];
  for (std::size_t k = 0; k < 3; ++k) {
    if (!j[key][k].is_number()) refuse(i, std::string("expected 3 numbers '") + key + "'");
    c[k] = j[key][k].get<double>();
    if (!ranges::inRange(c[k], ranges::kFinite)) refuse(i, std::string("'") + key + "' not finite");
  }
  return {c[0], c[1], c[2]};
}

std::string text(const json& j, const char* key, std::size_t i) {
  if (!j.contains(key) || !j[key].is_string()) refuse(i, std::string("expected a string '") + key + "'");
  return j[key].get<std::string>();
}

}  // namespace

void SceneHistory::add(const SceneCall& call) {
  if (call.kind == SceneCall::Kind::Steps) {
    if (call.count == 0) return;
    steps_ += static_cast<double>(call.count);
    if (!calls_.empty() && calls_.back().kind == SceneCall::Kind::Steps &&
        calls_.back().count <= static_cast<long long>(kMaxSteps) - call.count) {
      calls_.back().count += call.count;
      return;
    }
  }
  if (calls_.size() >= kMaxCalls) {
    complete_ = false;
    return;
  }
  calls_.push_back(call);
}

json SceneHistory::toJson() const {
  json out = json::array();
  for (const SceneCall& c : calls_) {
    switch (c.kind) {
      case SceneCall::Kind::Steps: out.push_back({{"call", "steps"}, {"count", c.count}}); break;
      case SceneCall::Kind::RunDue: out.push_back({{"call", "run_due"}}); break;
      case SceneCall::Kind::Push: {
        json p = {{"call", "push"}, {"entity", c.arrow.entity}, {"angle", c.arrow.angleDegrees},
                  {c.magnitude.kind == PushMagnitude::Kind::Impulse ? "impulse" : "step", c.magnitude.value}};
        if (c.arrow.face) p["face"] = std::string(toString(*c.arrow.face));
        out.push_back(p);
        break;
      }
      case SceneCall::Kind::Rotate:
        out.push_back({{"call", "rotate"}, {"entity", c.arrow.entity}, {"degrees", c.value}});
        break;
      case SceneCall::Kind::Timestep: out.push_back({{"call", "timestep"}, {"seconds", c.value}}); break;
      case SceneCall::Kind::Gravity: out.push_back({{"call", "gravity"}, {"g", c.value}}); break;
      case SceneCall::Kind::Impulse: {
        json p = {{"call", "impulse"}, {"entity", c.arrow.entity}, {"impulse", vec(c.vector)}};
        if (c.point) p["point"] = vec(*c.point);
        out.push_back(p);
        break;
      }
      case SceneCall::Kind::Load: {
        json p = {{"call", "load"}, {"entity", c.arrow.entity}, {"force", vec(c.vector)}, {"torque", vec(c.torque)}};
        if (c.point) p["point"] = vec(*c.point);
        out.push_back(p);
        break;
      }
    }
  }
  return out;
}

SceneHistory SceneHistory::fromJson(const json& j) {
  if (!j.is_array()) throw std::invalid_argument("history: expected a list of calls");
  if (j.size() > kMaxCalls) throw std::invalid_argument("history: more than 1e5 calls");
  SceneHistory h;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const json& c = j[i];
    if (!c.is_object()) refuse(i, "expected an object");
    const std::string kind = text(c, "call", i);
    SceneCall call;
    if (kind == "steps") {
      call.kind = SceneCall::Kind::Steps;
      if (!c.contains("count") || !c["count"].is_number_integer()) refuse(i, "expected a whole number 'count'");
      call.count = c["count"].get<long long>();
      if (call.count < 0 || call.count > static_cast<long long>(kMaxSteps)) refuse(i, "'count' out of range");
    } else if (kind == "run_due") {
      call.kind = SceneCall::Kind::RunDue;
    } else if (kind == "push") {
      call.kind = SceneCall::Kind::Push;
      call.arrow.entity = text(c, "entity", i);
      call.arrow.angleDegrees = number(c, "angle", ranges::kAngle, i);
      if (c.contains("face")) {
        call.arrow.face = directionFromString(text(c, "face", i));
        if (!call.arrow.face) refuse(i, "unknown 'face'");
      }
      const bool impulse = c.contains("impulse");
      call.magnitude = impulse ? PushMagnitude{PushMagnitude::Kind::Impulse, number(c, "impulse", ranges::kImpulse, i)}
                               : PushMagnitude{PushMagnitude::Kind::Step, number(c, "step", ranges::kStep, i)};
    } else if (kind == "rotate") {
      call.kind = SceneCall::Kind::Rotate;
      call.arrow.entity = text(c, "entity", i);
      call.value = number(c, "degrees", ranges::kAngle, i);
    } else if (kind == "timestep") {
      call.kind = SceneCall::Kind::Timestep;
      call.value = number(c, "seconds", ranges::kTimestep, i);
    } else if (kind == "gravity") {
      call.kind = SceneCall::Kind::Gravity;
      call.value = number(c, "g", ranges::kGravity, i);
    } else if (kind == "impulse") {
      call.kind = SceneCall::Kind::Impulse;
      call.arrow.entity = text(c, "entity", i);
      call.vector = vector(c, "impulse", i);
      if (c.contains("point")) call.point = vector(c, "point", i);
    } else if (kind == "load") {
      call.kind = SceneCall::Kind::Load;
      call.arrow.entity = text(c, "entity", i);
      call.vector = vector(c, "force", i);
      call.torque = vector(c, "torque", i);
      if (c.contains("point")) call.point = vector(c, "point", i);
    } else {
      refuse(i, "unknown call");
    }
    if (call.kind == SceneCall::Kind::Steps) h.steps_ += static_cast<double>(call.count);
    h.calls_.push_back(call);
  }
  return h;
}

}  // namespace tabletop::python
