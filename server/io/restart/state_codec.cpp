#include "io/restart/state_codec.hpp"

#include <cstdio>

#include "io/json/json_limits.hpp"
#include "io/results/history_json.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {

using nlohmann::json;

namespace {

constexpr const char* format_name = "saasgaps-restart-state";

/// Entries that differ from `usual`, as [index, value] pairs: most elements stay elastic and in
/// tension, so the material state is stored sparsely.
template <class T>
json sparse(const std::vector<T>& values, T usual) {
  json pairs = json::array();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] != usual) pairs.push_back(json::array({i, values[i]}));
  }
  return pairs;
}

template <class T>
std::vector<T> dense(const json& pairs, std::size_t size, T usual) {
  std::vector<T> values(size, usual);
  for (const json& p : pairs) {
    const auto i = p.at(0).get<std::size_t>();
    if (i >= size) throw SolverError("restart state: material index " + std::to_string(i) + " out of range");
    values[i] = p.at(1).get<T>();
  }
  return values;
}

/// Version 3: the elements' plastic peaks as [index, eps_max, sigma_max, eps_p (4)] and the indices
/// of the elements on the unloading branch; both only for the elements that have them.
json plastic_branches(const MaterialState& m) {
  json peaks = json::array();
  for (std::size_t e = 0; e < m.peaks.size(); ++e) {
    const PlasticPeak& p = m.peaks[e];
    if (!p.reached()) continue;
    peaks.push_back(json::array({e, p.strain, p.stress, p.plastic_strain[0], p.plastic_strain[1], p.plastic_strain[2],
                                 p.plastic_strain[3]}));
  }
  json unloading = json::array();
  for (std::size_t e = 0; e < m.unloading.size(); ++e) {
    if (m.unloads(e)) unloading.push_back(e);
  }
  return {{"peaks", peaks}, {"unloading", unloading}};
}

/// The model's dimensions; "material_points" only when they are not one per element (an element
/// family with several), so that the states of the report's elements keep their bytes and a state
/// without the member reads as one point per element.
json dimensions_json(const RestartState& s) {
  json d = {{"nodes", s.node_count}, {"elements", s.element_count}, {"gaps", s.gap_count}};
  if (s.material_point_count != s.element_count) d["material_points"] = s.material_point_count;
  return d;
}

/// The inverse of plastic_branches for `elements` solid elements (empty vectors when none is listed).
void read_plastic_branches(const json& j, std::size_t elements, MaterialState& m) {
  const auto index = [elements](const json& value) {
    const auto i = value.get<std::size_t>();
    if (i >= elements) throw SolverError("restart state: plastic material point index " + std::to_string(i) + " out of range");
    return i;
  };
  for (const json& p : j.at("peaks")) {
    if (p.size() != 7) throw SolverError("malformed restart state: a plastic peak is not 7 numbers");
    const std::size_t e = index(p.at(0));
    if (m.peaks.empty()) m.peaks.assign(elements, PlasticPeak{});
    m.peaks[e] = {p.at(1).get<double>(), p.at(2).get<double>(),
                  Vec4(p.at(3).get<double>(), p.at(4).get<double>(), p.at(5).get<double>(), p.at(6).get<double>())};
  }
  for (const json& u : j.at("unloading")) {
    const std::size_t e = index(u);
    if (m.unloading.empty()) m.unloading.assign(elements, 0);
    m.unloading[e] = 1;
  }
}

/// The inverse of the "friction" member of state_to_json: seven arrays of one length, states 0-2,
/// directions -1, 0, +1.
void read_friction(const json& j, FrictionState& f) {
  f.state = j.at("state").get<std::vector<std::uint8_t>>();
  f.direction = j.at("direction").get<std::vector<std::int8_t>>();
  f.normal_force = j.at("normal_force").get<std::vector<double>>();
  f.tangential_force = j.at("tangential_force").get<std::vector<double>>();
  f.position = j.at("position").get<std::vector<double>>();
  f.previous = j.at("previous").get<std::vector<double>>();
  f.slip = j.at("slip").get<std::vector<double>>();
  const std::size_t n = f.state.size();
  for (const std::size_t size : {f.direction.size(), f.normal_force.size(), f.tangential_force.size(),
                                 f.position.size(), f.previous.size(), f.slip.size()}) {
    if (size != n) throw SolverError("malformed restart state: the friction arrays differ in length");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (f.state[i] > static_cast<std::uint8_t>(SlipState::slip) || f.direction[i] < -1 || f.direction[i] > 1) {
      throw SolverError("malformed restart state: friction point " + std::to_string(i) + " has state " +
                        std::to_string(f.state[i]) + " and direction " + std::to_string(f.direction[i]) +
                        " (states 0-2, directions -1, 0, 1)");
    }
  }
}

}  // namespace

json state_to_json(const RestartState& s, const std::string& digest) {
  json history = json::array();
  for (const IterationRecord& row : s.history) history.push_back(history_row_json(row));
  const GapHistory& g = s.gaps;
  json document = {{"format", format_name},
          {"version", s.version},
          {"model_digest", digest},
          {"iteration", s.iteration},
          {"attempt", s.attempt},
          {"dimensions", dimensions_json(s)},
          {"materials",
           {{"secant_ratio", sparse(s.materials.secant_ratio, 1.0)},
            {"compression", sparse(s.materials.compression, all_tension)}}},
          {"gaps",
           {{"normal", g.used.normal},
            {"tensile", g.used.tensile},
            {"schedule_step", g.used.schedule_step},
            {"extrapolated", g.used.extrapolated},
            {"strain", g.strain},
            {"previous_normal", g.previous_normal},
            {"previous_strain", g.previous_strain},
            {"previous_tensile", g.previous_tensile}}},
          {"displacement", s.displacement},
          {"history", history}};
  // Exact mode only: the pairs' forces and active set (the next contact solve's warm start). A classic
  // state is written exactly as before, and states without it still read.
  if (!s.contact.empty()) {
    document["contact"] = {{"force", s.contact.force}, {"active", s.contact.active}};
  }
  // Contact surfaces with friction only: every point's friction state and slip history. Other
  // states are written exactly as before, and states without it still read (no version change).
  if (!s.friction.empty()) {
    const FrictionState& f = s.friction;
    document["friction"] = {{"state", f.state},
                            {"direction", f.direction},
                            {"normal_force", f.normal_force},
                            {"tangential_force", f.tangential_force},
                            {"position", f.position},
                            {"previous", f.previous},
                            {"slip", f.slip}};
  }
  // Version 3 (stepped plastic models) only: the peaks and unloading branches.
  if (s.version == RestartState::plastic_steps_version) document["plastic"] = plastic_branches(s.materials);
  // Versions 2 and 3 (stepped models) only: the increment of iteration K.
  if (s.position) {
    const StepPosition& p = *s.position;
    document["position"] = {{"step", p.step},
                            {"increment", p.increment},
                            {"iterations", p.iterations},
                            {"step_start", p.step_start}};
  }
  return document;
}

RestartState state_from_json(const json& j, const std::string& expected_digest) {
  try {
    if (!j.is_object() || j.value("format", "") != format_name) {
      throw SolverError("not a SAASGAPS restart state");
    }
    RestartState s;
    s.version = j.at("version").get<int>();
    if (s.version < RestartState::plain_version || s.version > RestartState::plastic_steps_version) {
      throw SolverError("restart state version " + std::to_string(s.version) + " is not supported (expected " +
                        std::to_string(RestartState::plain_version) + " to " +
                        std::to_string(RestartState::plastic_steps_version) + ")");
    }
    if (!expected_digest.empty() && j.at("model_digest").get<std::string>() != expected_digest) {
      throw SolverError("the restart state was saved for a different model (digest " +
                        j.at("model_digest").get<std::string>() + ", this model " + expected_digest + ")");
    }
    s.iteration = j.at("iteration").get<int>();
    s.attempt = j.at("attempt").get<int>();
    const json& dims = j.at("dimensions");
    s.node_count = dims.at("nodes").get<std::size_t>();
    s.element_count = dims.at("elements").get<std::size_t>();
    s.gap_count = dims.at("gaps").get<std::size_t>();
    s.material_point_count = dims.value("material_points", s.element_count);
    const json& m = j.at("materials");
    s.materials.secant_ratio = dense(m.at("secant_ratio"), s.material_point_count, 1.0);
    s.materials.compression = dense<DirectionChoice>(m.at("compression"), s.material_point_count, all_tension);
    const json& g = j.at("gaps");
    s.gaps.used.normal = g.at("normal").get<std::vector<double>>();
    s.gaps.used.tensile = g.at("tensile").get<double>();
    s.gaps.used.schedule_step = g.at("schedule_step").get<int>();
    s.gaps.used.extrapolated = g.at("extrapolated").get<bool>();
    s.gaps.strain = g.at("strain").get<std::vector<double>>();
    s.gaps.previous_normal = g.at("previous_normal").get<std::vector<double>>();
    s.gaps.previous_strain = g.at("previous_strain").get<std::vector<double>>();
    s.gaps.previous_tensile = g.at("previous_tensile").get<double>();
    s.displacement = j.at("displacement").get<std::vector<double>>();
    for (const json& row : j.at("history")) s.history.push_back(history_row_from_json(row));
    if (const auto contact = j.find("contact"); contact != j.end()) {
      s.contact.force = contact->at("force").get<std::vector<double>>();
      s.contact.active = contact->at("active").get<std::vector<std::uint8_t>>();
      if (s.contact.force.size() != s.contact.active.size()) {
        throw SolverError("malformed restart state: contact force and active set differ in length");
      }
    }
    if (const auto friction = j.find("friction"); friction != j.end()) read_friction(*friction, s.friction);
    if (s.version == RestartState::plastic_steps_version) {
      read_plastic_branches(j.at("plastic"), s.material_point_count, s.materials);
    } else if (j.contains("plastic")) {
      throw SolverError("malformed restart state: version " + std::to_string(s.version) + " has no plastic peaks");
    }
    if (s.version != RestartState::plain_version) {
      const json& p = j.at("position");
      s.position = StepPosition{p.at("step").get<int>(), p.at("increment").get<int>(), p.at("iterations").get<int>(),
                                p.at("step_start").get<std::vector<double>>()};
    } else if (j.contains("position")) {
      throw SolverError("malformed restart state: version 1 has no load-step position");
    }
    return s;
  } catch (const json::exception& e) {
    throw SolverError(std::string("malformed restart state: ") + e.what());
  }
}

std::vector<std::uint8_t> state_to_cbor(const RestartState& state, const std::string& digest) {
  return json::to_cbor(state_to_json(state, digest));
}

json restart_state_tree(std::span<const std::uint8_t> cbor) {
  try {
    return parse_cbor(cbor);
  } catch (const json::exception& e) {
    throw SolverError(std::string("malformed restart state: ") + e.what());
  } catch (const NestingTooDeep& e) {
    throw SolverError("malformed restart state: " + e.issues().front().pointer + ": " + e.issues().front().detail);
  }
}

RestartState state_from_cbor(const std::vector<std::uint8_t>& bytes, const std::string& expected_digest) {
  return state_from_json(restart_state_tree(bytes), expected_digest);
}

}  // namespace saasgaps::io
