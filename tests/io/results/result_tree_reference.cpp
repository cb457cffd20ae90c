#include "io/results/result_tree_reference.hpp"

#include "io/results/history_json.hpp"
#include "solver/assembly/element_data.hpp"

namespace saasgaps::io::reference {

using nlohmann::json;

namespace {

const char* analysis_name(AnalysisType type) {
  switch (type) {
    case AnalysisType::plane_stress: return "plane_stress";
    case AnalysisType::plane_strain: return "plane_strain";
    case AnalysisType::axisymmetric: return "axisymmetric";
  }
  return "?";
}

/// User ids of an element's corner nodes.
json node_ids(const Model& model, std::span<const int> nodes) {
  json ids = json::array();
  for (int n : nodes) ids.push_back(model.nodes[n].id);
  return ids;
}

json element_json(const Model& model, const Element& el, const ElementResult& e) {
  return {{"id", e.id},
          {"nodes", node_ids(model, el.node_span())},
          {"material", model.materials[el.material].id},
          {"temperature", element_temperature(model, el.node_span())},
          {"sigma_r", e.stress[rr]},
          {"sigma_z", e.stress[zz]},
          {"tau_rz", e.stress[rz]},
          {"sigma_theta", e.stress[th]},
          {"sigma_1", e.principal.s1},
          {"sigma_2", e.principal.s2},
          {"angle", e.principal.angle_deg},
          {"effective", e.effective},
          {"eps_r", e.strain[rr]},
          {"eps_z", e.strain[zz]},
          {"gamma_rz", e.strain[rz]},
          {"eps_theta", e.strain[th]},
          {"yield", e.yielded},
          {"plastic_converged", e.plastic_converged}};
}

json gap_json(const Model& model, const GapElement& gap, const GapResult& g) {
  json j = {{"id", g.id},
            {"nodes", node_ids(model, gap.node_span())},
            {"angle", gap.angle_deg},
            {"eps_m", g.eps_m},
            {"closure", g.closure},
            {"modulus", g.modulus},
            {"sigma_m", g.sigma_m},
            {"contact_pressure", g.sigma_m < 0.0 ? -g.sigma_m : 0.0},
            {"state", to_string(g.state)},
            {"converged", g.converged}};
  if (!g.converged) j["failure"] = describe(g.failure);
  return j;
}

}  // namespace

json result_document(const Model& model, const Solution& s) {
  json history = json::array();
  for (const IterationRecord& row : s.history) history.push_back(io::history_row_json(row));
  // Coordinates, connectivity and temperatures ride along so that a result can be plotted or
  // exported on its own.
  json nodes = json::array();
  for (std::size_t n = 0; n < s.nodes.size(); ++n) {
    nodes.push_back({{"id", s.nodes[n].id},
                     {"r", model.nodes[n].r},
                     {"z", model.nodes[n].z},
                     {"T", model.loads.node_temperature[n]},
                     {"u_r", s.nodes[n].u_r},
                     {"u_z", s.nodes[n].u_z}});
    if (s.recovered.has(n)) {  // the recovered stresses: the mean of the node's material sides
      const Vec4 m = s.recovered.mean(n);
      json& node = nodes.back();
      node["sigma_r"] = m[rr];
      node["sigma_z"] = m[zz];
      node["tau_rz"] = m[rz];
      node["sigma_theta"] = m[th];
      node["effective"] = von_mises(m);
    }
  }
  json elements = json::array();
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    elements.push_back(element_json(model, model.elements[e], s.elements[e]));
    if (s.error_estimate) elements.back()["error"] = s.elements[e].error;
  }
  json gaps = json::array();
  for (std::size_t g = 0; g < s.gaps.size(); ++g) gaps.push_back(gap_json(model, model.gaps->elements[g], s.gaps[g]));
  json reactions = json::array();
  double sum_r = 0.0, sum_z = 0.0;  // in node order, as the writer sums them
  for (const NodeReaction& r : s.reactions) {
    reactions.push_back({{"node", r.id}, {"fr", r.f_r}, {"fz", r.f_z}});
    sum_r += r.f_r;
    sum_z += r.f_z;
  }
  json document = {{"status", s.status == RunStatus::converged ? "converged" : "not_converged"},
          {"iterations", s.iterations},
          {"message", s.message},
          {"title", model.title},
          {"analysis", analysis_name(model.analysis)},
          {"reference_temperature", model.reference_temperature},
          {"history", history},
          {"nodes", nodes},
          {"reactions", reactions},
          {"reaction_sum", {{"fr", sum_r}, {"fz", sum_z}}},
          {"elements", elements},
          {"gaps", gaps}};
  // The model's unit names, only those given; no member when it gives none.
  json units = json::object();
  for (const auto& [key, name] : {std::pair{"length", &model.units.length}, std::pair{"force", &model.units.force},
                                  std::pair{"stress", &model.units.stress},
                                  std::pair{"temperature", &model.units.temperature}}) {
    if (!name->empty()) units[key] = *name;
  }
  if (!units.empty()) document["units"] = units;
  if (s.error_estimate) {
    document["error_estimate"] = {{"relative", s.error_estimate->relative},
                                  {"error", s.error_estimate->error},
                                  {"energy_norm", s.error_estimate->energy_norm}};
  }
  if (!s.recovered.empty()) {
    json sides = json::array();
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
      if (s.recovered.side_count(n) < 2) continue;
      for (std::uint32_t k = s.recovered.first[n]; k < s.recovered.first[n + 1]; ++k) {
        const Vec4& v = s.recovered.value[k];
        sides.push_back({{"node", model.nodes[n].id},
                         {"material", model.materials[static_cast<std::size_t>(s.recovered.material[k])].id},
                         {"sigma_r", v[rr]},
                         {"sigma_z", v[zz]},
                         {"tau_rz", v[rz]},
                         {"sigma_theta", v[th]},
                         {"effective", von_mises(v)}});
      }
    }
    document["node_sides"] = sides;
  }
  return document;
}

json failed_result_document(const std::string& message) {
  return {{"status", "failed"},
          {"iterations", 0},
          {"message", message},
          {"history", json::array()},
          {"nodes", json::array()},
          {"reactions", json::array()},
          {"elements", json::array()},
          {"gaps", json::array()}};
}

}  // namespace saasgaps::io::reference
