#include "draw/CameraChoice.h"

#include "draw/SceneDrawing.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "core/Angle.h"
#include "core/Text.h"

namespace tabletop {
namespace {

constexpr double kMostMetres = 1e4;     // an eye or target coordinate, either way
constexpr double kLeastDistance = 1e-3; // eye to target, metres
constexpr double kFollowReach = 4.0;    // bounding radii of the followed entity in view
constexpr double kMostPitch = 89.0;     // degrees, as Camera::orbit keeps it

// "X,Y,Z" in metres, each finite and within kMostMetres.
std::optional<Vec3> parsePoint(std::string_view text) {
  double v[3];
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 3; ++i) {
    const auto [next, ec] = std::from_chars(p, end, v[i]);
    if (ec != std::errc() || !std::isfinite(v[i]) || std::abs(v[i]) > kMostMetres) return std::nullopt;
    p = next;
    if (i < 2) {
      if (p == end || *p != ',') return std::nullopt;
      ++p;
    }
  }
  if (p != end) return std::nullopt;
  return Vec3{v[0], v[1], v[2]};
}

const EntitySpec* entityNamed(const Scenario& scenario, const std::string& name) {
  for (const EntitySpec& e : scenario.entities) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

}  // namespace

std::variant<CameraChoice, std::string> CameraChoice::parse(const std::string& text) {
  CameraChoice c;
  if (text == "fit") return c;
  const std::vector<std::string> presets = Camera::names();
  if (std::find(presets.begin(), presets.end(), text) != presets.end()) {
    c.kind = Kind::Preset, c.name = text;
    return c;
  }
  if (text.rfind("follow:", 0) == 0) {
    c.kind = Kind::Follow, c.name = text.substr(7);
    if (c.name.empty()) return std::string("follow: expected an entity's name after the colon");
    return c;
  }
  const std::size_t colon = text.find(':');
  if (colon != std::string::npos && text.find_first_of("0123456789") < colon) {
    const auto eye = parsePoint(std::string_view(text).substr(0, colon));
    const auto target = parsePoint(std::string_view(text).substr(colon + 1));
    if (!eye || !target) {
      return "expected EX,EY,EZ:TX,TY,TZ, six numbers in metres within " + fixed(kMostMetres, 0) + ", got '" +
             shownText(text) + "'";
    }
    if ((*eye - *target).length() < kLeastDistance) return std::string("the eye and the target are the same point");
    c.kind = Kind::EyeTarget, c.eye = *eye, c.target = *target;
    return c;
  }
  return "expected fit, front, corner, side, top, follow:NAME or EX,EY,EZ:TX,TY,TZ, got '" + shownText(text) + "'";
}

std::string CameraChoice::help() {
  return "View: fit (the default: the report's direction, the whole scene in view), front (the report's view of the "
         "table), corner, side, top, follow:NAME (centred on entity NAME), or EX,EY,EZ:TX,TY,TZ (an eye and a "
         "target, metres)";
}

std::variant<CameraChoice, std::string> CameraChoice::forScene(const std::string& text, const Scenario& scenario) {
  auto parsed = parse(text);
  if (const auto* choice = std::get_if<CameraChoice>(&parsed)) {
    if (std::string problem = choice->problemWith(scenario); !problem.empty()) return problem;
  }
  return parsed;
}

std::string CameraChoice::problemWith(const Scenario& scenario) const {
  if (kind != Kind::Follow || entityNamed(scenario, name)) return "";
  return "follow: no entity is named '" + shownText(name) + "' in " + shownText(scenario.name);
}

SceneExtent SceneExtent::of(const Scenario& scenario, const std::vector<EntityState>& states) {
  SceneExtent extent;
  extent.add(sceneBounds(scenario, states));
  return extent;
}

void SceneExtent::add(const std::vector<Camera::Bound>& bounds) {
  for (const Camera::Bound& b : bounds) {
    const Vec3 r{b.radius, b.radius, b.radius}, lo = b.centre - r, hi = b.centre + r;
    if (empty_) low_ = lo, high_ = hi, empty_ = false;
    low_ = {std::min(low_.x, lo.x), std::min(low_.y, lo.y), std::min(low_.z, lo.z)};
    high_ = {std::max(high_.x, hi.x), std::max(high_.y, hi.y), std::max(high_.z, hi.z)};
  }
}

std::vector<Camera::Bound> SceneExtent::corners() const {
  std::vector<Camera::Bound> out;
  if (empty_) return out;
  for (const double x : {low_.x, high_.x}) {
    for (const double y : {low_.y, high_.y}) {
      for (const double z : {low_.z, high_.z}) out.push_back({{x, y, z}, 0.0});
    }
  }
  return out;
}

double SceneExtent::reachFrom(double x, double z) const {
  if (empty_) return 0.0;
  return std::max({std::abs(low_.x - x), std::abs(high_.x - x), std::abs(low_.z - z), std::abs(high_.z - z)});
}

Camera cameraFor(const CameraChoice& choice, const Scenario& scenario, const std::vector<EntityState>& states,
                 const SceneExtent& extent, double aspect) {
  Camera c = *Camera::named("front", scenario.table);
  switch (choice.kind) {
    case CameraChoice::Kind::Preset:
      c = Camera::named(choice.name, scenario.table).value_or(c);
      break;
    case CameraChoice::Kind::Fit:
      c.fit(extent.corners(), aspect);
      break;
    case CameraChoice::Kind::Follow:
      for (std::size_t i = 0; i < scenario.entities.size() && i < states.size(); ++i) {
        if (scenario.entities[i].name != choice.name) continue;
        c.fit({{states[i].position, kFollowReach * scenario.entities[i].geometry.boundingRadius()}}, aspect);
      }
      break;
    case CameraChoice::Kind::EyeTarget: {
      const Vec3 d = choice.eye - choice.target;
      c.target = choice.target;
      c.distance = d.length();
      c.yawDegrees = toDegrees(std::atan2(d.x, d.z));
      c.pitchDegrees = std::clamp(toDegrees(std::atan2(d.y, std::hypot(d.x, d.z))),
                                  -kMostPitch, kMostPitch);
      break;
    }
  }
  // Whatever is framed stays in front of the far plane.
  c.farPlane = std::max(c.farPlane, 4.0 * c.distance);
  return c;
}

}  // namespace tabletop
