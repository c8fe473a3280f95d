#include "sweep/SweepSpec.h"

#include <cmath>

namespace tabletop {
namespace {

// SplitMix64: a run's random draws depend only on the seed, the run and
// the parameter, never on which process draws them or in what order.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A uniform number in [0, 1) from 53 bits of the draw `k` of one parameter.
double unit(std::uint64_t seed, std::size_t run, std::size_t parameter, int k) {
  const std::uint64_t h = mix(mix(mix(seed) ^ run) ^ (parameter * 4 + static_cast<std::uint64_t>(k)));
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

}  // namespace

std::size_t SweepSpec::runs() const {
  if (random) return random->runs;
  std::size_t n = samples;
  for (const SweepParameter& p : parameters) {
    if (p.kind == SweepParameter::Kind::List) n *= p.values.size();
  }
  return n;
}

std::vector<nlohmann::json> SweepSpec::valuesOf(std::size_t index) const {
  if (random) return {seed + index};
  std::vector<nlohmann::json> out(parameters.size());
  // The grid point, with the last listed parameter varying fastest.
  std::size_t point = index / samples;
  for (std::size_t k = parameters.size(); k-- > 0;) {
    const SweepParameter& p = parameters[k];
    if (p.kind != SweepParameter::Kind::List) continue;
    out[k] = p.values[point % p.values.size()];
    point /= p.values.size();
  }
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    const SweepParameter& p = parameters[k];
    if (p.kind == SweepParameter::Kind::Uniform) {
      out[k] = p.a + (p.b - p.a) * unit(seed, index, k, 0);
    } else if (p.kind == SweepParameter::Kind::Normal) {
      // Box-Muller; 1 - u keeps the logarithm's argument in (0, 1].
      const double u = 1.0 - unit(seed, index, k, 0), v = unit(seed, index, k, 1);
      out[k] = p.a + p.b * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * 3.14159265358979323846 * v);
    }
  }
  return out;
}

std::vector<std::string> SweepSpec::valueNames() const {
  if (random) return {"seed"};
  std::vector<std::string> names;
  for (const SweepParameter& p : parameters) names.push_back(p.name);
  return names;
}

std::string SweepSpec::sceneOf(std::size_t index) const {
  nlohmann::json s = scene;
  const std::vector<nlohmann::json> values = valuesOf(index);
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    for (const std::string& pointer : parameters[k].pointers) s[nlohmann::json::json_pointer(pointer)] = values[k];
  }
  return s.dump();
}

std::string SweepSpec::selfContained() const {
  nlohmann::json j{{"version", 1}, {"name", name}, {"seed", seed}};
  if (random) {
    j["random"] = {{"runs", random->runs}};
    if (random->rate > 0) j["random"]["rate"] = random->rate;
  } else {
    nlohmann::json params = nlohmann::json::array();
    for (const SweepParameter& p : parameters) {
      nlohmann::json q{{"name", p.name}, {"pointer", p.pointers}};
      if (p.kind == SweepParameter::Kind::List) q["values"] = p.values;
      if (p.kind == SweepParameter::Kind::Uniform) q["random"] = {{"uniform", {p.a, p.b}}};
      if (p.kind == SweepParameter::Kind::Normal) q["random"] = {{"normal", {p.a, p.b}}};
      params.push_back(q);
    }
    j["scene"] = scene;
    j["samples"] = samples;
    j["parameters"] = params;
  }
  nlohmann::json modeNames = nlohmann::json::array();
  for (SimulationMode m : modes) modeNames.push_back(std::string(toString(m)));
  j["modes"] = modeNames;
  nlohmann::json recorded = nlohmann::json::array();
  if (record.positions) recorded.push_back("positions");
  if (record.events) recorded.push_back("events");
  if (record.distance) recorded.push_back("distance");
  if (record.cost) recorded.push_back("cost");
  if (record.stateHash) recorded.push_back("state_hash");
  j["record"] = recorded;
  return j.dump();
}

}  // namespace tabletop
