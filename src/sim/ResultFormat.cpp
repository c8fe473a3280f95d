#include "sim/ResultFormat.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/StateHash.h"

namespace tabletop {

namespace {

nlohmann::json eventJson(const Event& e) {
  nlohmann::json j{{"t", e.t}, {"type", toString(e.type)}, {"entities", eventEntities(e)}};
  switch (e.type) {
    case EventType::Push:
      if (e.face) j["direction"] = toString(*e.face);
      j["angle"] = e.angle;
      if (e.impulse > 0) j["impulse"] = e.impulse;  // the rules push by steps, not impulses
      if (e.step > 0) j["step"] = e.step;
      break;
    case EventType::Rotate: j["angle"] = e.angle; break;
    case EventType::LeavesTable: j["edge"] = e.edge ? toString(*e.edge) : ""; break;
    case EventType::Lands: j["on"] = e.on.name(); break;
    default: break;
  }
  return j;
}

}  // namespace

std::string describe(const Event& e) {
  switch (e.type) {
    case EventType::Push: {
      std::string s = "push " + e.entity + " " +
                      (e.face ? std::string(toString(*e.face)) : "at " + fixed(e.angle, 1) + " deg");
      if (e.step > 0) s += ", step " + fixed(e.step, 3) + " m";
      return e.impulse > 0 ? s + " (impulse " + fixed(e.impulse, 4) + " N s)" : s;
    }
    case EventType::Rotate: return "rotate " + e.entity + " by " + fixed(e.angle, 1) + " deg";
    case EventType::ContactBegin: return "contact begins between " + e.entity + " and " + e.other;
    case EventType::LeavesTable:
      return e.entity + " leaves the table (" + std::string(e.edge ? toString(*e.edge) : "") + " edge)";
    case EventType::Lands: return e.entity + " lands on " + e.on.name();
    case EventType::AtRest: return e.entity + " comes to rest";
  }
  return "";
}

nlohmann::json runDocument(const std::vector<RunResult>& results) {
  nlohmann::json runs = nlohmann::json::array();
  for (const RunResult& r : results) runs.push_back(toJson(r));
  return {{"format_version", kRunFormatVersion}, {"runs", std::move(runs)}};
}

std::string formatText(const RunResult& r) {
  std::ostringstream out;
  out << r.scenario << "  (" << r.file << ")\n";
  // The rules solve no contacts: their header names no solver.
  out << "  mode " << r.mode << ", timestep " << fixed(r.settings.timestep, 6) << " s, ";
  if (r.mode != "rules") out << describeSolver(r.settings.solver, r.settings.iterations) << ", ";
  out << toString(r.settings.integrator) << " integrator; simulated " << fixed(r.simTime, 3) << " s in " << r.steps
      << " steps (" << fixed(r.wallSeconds, 3) << " s wall)\n";
  if (r.mode != "rules") out << "  " << describeUse(r.solverUse) << "\n";
  if (!r.complete) out << "  INCOMPLETE, the run stopped: " << r.failure << "\n";
  // The name column fits the longest name, so the columns after it align.
  std::size_t nameWidth = 10;
  for (const EntityState& e : r.entities) nameWidth = std::max(nameWidth, e.name.size() + 2);
  out << "  " << padded("entity", nameWidth) << padded("shape", 9) << padded("x [m]", 9) << padded("y [m]", 9)
      << padded("z [m]", 9) << padded("yaw [deg]", 10) << padded("status", 22) << "support\n";
  for (const EntityState& e : r.entities) {
    out << "  " << padded(e.name, nameWidth) << padded(std::string(toString(e.shape)), 9)
        << padded(fixed(e.position.x, 4), 9) << padded(fixed(e.position.y, 4), 9)
        << padded(fixed(e.position.z, 4), 9) << padded(fixed(e.yawDegrees, 1), 10)
        << padded(std::string(toString(e.status)), 22) << e.support.name() << "\n";
  }
  out << "  events\n";
  for (const Event& e : r.events) out << "    " << padded(fixed(e.t, 3) + " s", 10) << describe(e) << "\n";
  out << "  state_hash " << formatHash(r.stateHash) << "\n";
  return out.str();
}

nlohmann::json toJson(const RunResult& r) {
  nlohmann::json entities = nlohmann::json::array();
  for (const EntityState& e : r.entities) {
    entities.push_back({{"name", e.name},
                        {"shape", toString(e.shape)},
                        {"position", {e.position.x, e.position.y, e.position.z}},
                        {"orientation", e.orientation},
                        {"yaw", e.yawDegrees},
                        {"linear_velocity", {e.linearVelocity.x, e.linearVelocity.y, e.linearVelocity.z}},
                        {"angular_velocity", {e.angularVelocity.x, e.angularVelocity.y, e.angularVelocity.z}},
                        {"status", toString(e.status)},
                        {"support", e.support.name()}});
  }
  nlohmann::json events = nlohmann::json::array();
  for (const Event& e : r.events) events.push_back(eventJson(e));
  nlohmann::json j = {{"scenario", r.scenario},
          {"file", r.file},
          {"complete", r.complete},
          {"mode", r.mode},
          {"settings",
           {{"timestep", r.settings.timestep},
            {"iterations", r.settings.iterations},
            {"max_substeps", r.settings.maxSubsteps},
            {"solver", toString(r.settings.solver)},
            {"integrator", toString(r.settings.integrator)},
            {"duration", r.settings.duration},
            {"gravity", r.settings.gravity},
            {"end_at_rest", r.settings.endAtRest},
            {"sleeping", r.settings.bullet.sleeping},
            {"warm_start", r.settings.bullet.warmStart},
            {"solver_tolerance", r.settings.bullet.solverTolerance},
            {"gyroscopic", toString(r.settings.bullet.gyroscopic)},
            {"broadphase", toString(r.settings.bullet.broadphase)},
            {"legs_when_reachable", r.settings.bullet.legsWhenReachable},
            {"floor_pairs_near_floor", r.settings.bullet.floorPairsNearFloor}}},
          {"sim_time", r.simTime},
          {"steps", r.steps},
          {"islands",
           {{"direct", r.solverUse.direct}, {"guessed", r.solverUse.guessed}, {"swept", r.solverUse.swept},
            {"long_swept", r.solverUse.longSwept},
            {"fallbacks", r.solverUse.fallbacks},
            {"part_budget", r.solverUse.partBudget},
            {"parts", r.solverUse.parts},
            {"largest", r.solverUse.largestIsland}}},
          {"work",
           {{"units", r.work.units()},
            {"part_bodies", r.work.partBodies},
            {"contact_points", r.work.contactPoints},
            {"pairs", r.work.pairs},
            {"swept_rows", r.work.sweptRows},
            {"pivoted_rows", r.work.pivotedRows},
            {"rule_checks", r.work.ruleChecks}}},
          {"wall_seconds", r.wallSeconds},
          {"entities", entities},
          {"events", events},
          {"state_hash", formatHash(r.stateHash)}};
  if (!r.complete) j["failure"] = r.failure;
  return j;
}

}  // namespace tabletop
