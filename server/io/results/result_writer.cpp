#include "io/results/result_writer.hpp"

#include "io/results/history_json.hpp"
#include "io/results/result_annotations.hpp"
#include "solver/analysis/reactions.hpp"
#include "solver/model/load_schedule.hpp"

namespace saasgaps::io {

namespace {

/// User ids of an element's corner nodes.
template <std::size_t N>
void write_node_ids(JsonWriter& out, const Model& model, const std::array<int, N>& nodes, int count) {
  out.begin_array();
  for (int a = 0; a < count; ++a) out.value(model.nodes[nodes[a]].id);
  out.end_array();
}

// Keys in alphabetical order in every object (see the header).

/// The recovered stress keys of a node or a node side, in alphabetical order after "effective"
/// (which the caller places): sigma_r, sigma_theta, sigma_z, tau_rz.
void write_stress_components(JsonWriter& out, const Vec4& s) {
  out.field("sigma_r", s[rr]).field("sigma_theta", s[th]).field("sigma_z", s[zz]).field("tau_rz", s[rz]);
}

/// recovered: the node's recovered stress (the mean of its material sides), nullptr for a node of no
/// solid element or a result without recovery.
void write_node(JsonWriter& out, const Model& model, const NodeResult& n, std::size_t index, double T,
                const Vec4* recovered) {
  out.begin_object().field("T", T);
  if (recovered != nullptr) out.field("effective", von_mises(*recovered));
  out.field("id", n.id).field("r", model.nodes[index].r);
  if (recovered != nullptr) write_stress_components(out, *recovered);
  out.field("u_r", n.u_r).field("u_z", n.u_z).field("z", model.nodes[index].z).end_object();
}

/// Nodes where elements of several materials meet: each material side's recovered stress
/// (docs/results.md, `node_sides`).
void write_node_sides(JsonWriter& out, const Model& model, const RecoveredField& f) {
  out.key("node_sides").begin_array();
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (f.side_count(n) < 2) continue;
    for (std::uint32_t k = f.first[n]; k < f.first[n + 1]; ++k) {
      out.begin_object()
          .field("effective", von_mises(f.value[k]))
          .field("material", model.materials[static_cast<std::size_t>(f.material[k])].id)
          .field("node", model.nodes[n].id);
      write_stress_components(out, f.value[k]);
      out.end_object();
    }
  }
  out.end_array();
}

/// temperature: the element's mean; flux: (q_r, q_z) of thermal runs, else nullptr.
/// with_error: the result carries an error estimate (every solved model's does).
/// heat_error: the element's estimated flux error (runs with `thermal`), else nullptr.
void write_element(JsonWriter& out, const Model& model, const Element& el, const ElementResult& e, double temperature,
                   const Vec2* flux, bool with_error, const double* heat_error) {
  out.begin_object()
      .field("angle", e.principal.angle_deg)
      .field("effective", e.effective)
      .field("eps_r", e.strain[rr])
      .field("eps_theta", e.strain[th])
      .field("eps_z", e.strain[zz]);
  if (with_error) out.field("error", e.error);
  out.field("gamma_rz", e.strain[rz]);
  if (heat_error != nullptr) out.field("heat_error", *heat_error);
  out.field("id", e.id)
      .field("material", model.materials[el.material].id);
  out.key("nodes");
  write_node_ids(out, model, el.nodes, el.node_count);
  out.field("plastic_converged", e.plastic_converged);
  if (flux != nullptr) out.field("q_r", flux->x()).field("q_z", flux->y());
  out.field("sigma_1", e.principal.s1)
      .field("sigma_2", e.principal.s2)
      .field("sigma_r", e.stress[rr])
      .field("sigma_theta", e.stress[th])
      .field("sigma_z", e.stress[zz])
      .field("tau_rz", e.stress[rz])
      .field("temperature", temperature)
      .field("yield", e.yielded)
      .end_object();
}

void write_gap(JsonWriter& out, const Model& model, const GapElement& gap, const GapResult& g) {
  out.begin_object()
      .field("angle", gap.angle_deg)
      .field("closure", g.closure)
      .field("contact_pressure", contact_pressure(g.sigma_m))
      .field("converged", g.converged)
      .field("eps_m", g.eps_m);
  if (!g.converged) out.field("failure", describe(g.failure));
  out.field("id", g.id).field("modulus", g.modulus);
  out.key("nodes");
  write_node_ids(out, model, gap.nodes, gap.node_count);
  out.field("sigma_m", g.sigma_m).field("state", to_string(g.state)).end_object();
}

/// {"fr": f.x(), "fz": f.y()}: a force in the (r, z) plane.
void write_force(JsonWriter& out, const Vec2& f) { out.begin_object().field("fr", f.x()).field("fz", f.y()).end_object(); }

/// A contact pair: the force B exerts on A, its Coulomb coefficient (pairs with friction > 0 only:
/// frictionless results are written as before friction existed), its surfaces [A, B] and its
/// points along A (keys in alphabetical order). The plots draw mu x pressure from the friction
/// written here.
void write_contact_pair(JsonWriter& out, const ContactPairResult& pair, double friction) {
  out.begin_object().key("force");
  write_force(out, pair.force);
  if (friction > 0.0) out.field("friction", friction);
  out.key("points").begin_array();
  for (const ContactPointResult& p : pair.points) {
    out.begin_object()
        .field("gap", p.gap)
        .field("pressure", p.pressure)
        .field("r", p.r)
        .field("shear", p.shear)
        .field("slip", p.slip)
        .field("state", to_string(p.state))
        .field("z", p.z)
        .end_object();
  }
  out.end_array().key("surfaces").begin_array().value(pair.surfaces[0]).value(pair.surfaces[1]).end_array();
  out.end_object();
}

}  // namespace

void write_result(JsonWriter& out, const Model& model, const Solution& s, const ItemPieces& pieces,
                  const std::function<void(JsonWriter&)>& leading) {
  out.begin_object();
  if (leading) leading(out);
  out.field("analysis", analysis_type_names.name(model.analysis));
  if (model.contact) {  // models with contact surfaces only: other results stay as they were
    out.key("contact").begin_array();
    for (std::size_t k = 0; k < s.contact.size(); ++k) {
      // s.contact has one entry per model pair, in order (solution.hpp).
      write_contact_pair(out, s.contact[k], k < model.contact->pairs.size() ? model.contact->pairs[k].friction : 0.0);
    }
    out.end_array();
  }
  // Coordinates, connectivity and temperatures ride along so that a result can be plotted or
  // exported on its own.
  // A stepped run ends in its last step's loads: nodes and elements both show those temperatures.
  const std::vector<double>& T = s.thermal ? s.thermal->T : final_loads(model).node_temperature;
  // The two arrays that grow with the mesh are formatted on several cores (io/parallel_items.hpp).
  out.key("elements").begin_array();
  write_items(out, s.elements.size(), [&](JsonWriter& item, std::size_t e) {
    const Element& el = model.elements[e];
    double mean = 0.0;  // of the node temperatures, as element_temperature does for the model's loads
    for (int a = 0; a < el.node_count; ++a) mean += T[static_cast<std::size_t>(el.nodes[a])];
    const bool heat_error = s.thermal && e < s.thermal->heat_error.size();
    write_element(item, model, el, s.elements[e], mean / el.node_count, s.thermal ? &s.thermal->flux[e] : nullptr,
                  s.error_estimate.has_value(), heat_error ? &s.thermal->heat_error[e] : nullptr);
  }, pieces);
  out.end_array();
  if (s.error_estimate) {
    out.key("error_estimate")
        .begin_object()
        .field("energy_norm", s.error_estimate->energy_norm)
        .field("error", s.error_estimate->error)
        .field("relative", s.error_estimate->relative)
        .end_object();
  }
  out.key("gaps").begin_array();
  for (std::size_t g = 0; g < s.gaps.size(); ++g) write_gap(out, model, model.gaps->elements[g], s.gaps[g]);
  out.end_array();
  if (s.thermal && s.thermal->heat_error_estimate) {  // runs with `thermal`: the heat flux's estimate
    const ErrorEstimate& h = *s.thermal->heat_error_estimate;
    out.key("heat_error_estimate")
        .begin_object()
        .field("energy_norm", h.energy_norm)
        .field("error", h.error)
        .field("relative", h.relative)
        .end_object();
  }
  out.key("history").begin_array();
  for (const IterationRecord& row : s.history) write_history_row(out, row);
  out.end_array();
  out.field("iterations", s.iterations).field("message", s.message);
  if (!s.recovered.empty()) write_node_sides(out, model, s.recovered);
  out.key("nodes").begin_array();
  write_items(out, s.nodes.size(), [&](JsonWriter& item, std::size_t n) {
    const bool recovered = s.recovered.has(n);
    const Vec4 stress = recovered ? s.recovered.mean(n) : Vec4::Zero();
    write_node(item, model, s.nodes[n], n, T[n], recovered ? &stress : nullptr);
  }, pieces);
  out.end_array();
  out.key("reaction_sum");
  write_force(out, reaction_sum(s.reactions));
  out.key("reactions").begin_array();
  for (const NodeReaction& r : s.reactions) {
    out.begin_object().field("fr", r.f_r).field("fz", r.f_z).field("node", r.id).end_object();
  }
  out.end_array();
  out.field("reference_temperature", model.reference_temperature);
  if (!model.reaction_groups.empty()) {  // models whose constraints name node sets only
    out.key("set_reactions").begin_array();
    for (const SetReaction& r : s.set_reactions) out.begin_object().field("fr", r.f_r).field("fz", r.f_z).field("set", r.set).end_object();
    out.end_array();
  }
  out.field("status", s.status == RunStatus::converged ? "converged" : "not_converged");
  if (!s.steps.empty()) {  // stepped models only
    // A transient heat run's steps are its output times: each gives its time and the node
    // temperatures there (the temperature history), in the model's node order.
    const bool transient = s.thermal && !s.thermal->times.empty();
    out.key("steps").begin_array();
    for (std::size_t k = 0; k < s.steps.size(); ++k) {
      const StepResult& step = s.steps[k];
      const bool reached = transient && k < s.thermal->times.size();
      out.begin_object();
      if (reached) out.field("T", s.thermal->history[k]);
      out.field("increments", step.increments).field("name", step.name).field("status", to_string(step.status));
      if (reached) out.field("time", s.thermal->times[k]);
      out.end_object();
    }
    out.end_array();
  }
  out.field("title", model.title);
  write_units(out, model.units);  // "units" sorts last
  out.end_object();
}

void write_failed_result(JsonWriter& out, const std::string& message) {
  out.begin_object();
  for (const char* list : {"elements", "gaps", "history"}) out.key(list).begin_array().end_array();
  out.field("iterations", 0).field("message", message);
  out.key("nodes").begin_array().end_array();
  out.key("reactions").begin_array().end_array();
  out.field("status", "failed").end_object();
}

std::string result_text(const Model& model, const Solution& solution) {
  std::string text;
  JsonWriter out(string_sink(text));
  write_result(out, model, solution);
  out.flush();
  return text;
}

std::string failed_result_text(const std::string& message) {
  std::string text;
  JsonWriter out(string_sink(text));
  write_failed_result(out, message);
  out.flush();
  return text;
}

}  // namespace saasgaps::io
