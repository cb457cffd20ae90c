#include "io/results/history_json.hpp"

namespace saasgaps::io {

using nlohmann::json;

bool has_friction_columns(const IterationRecord& row) {
  // A frictionless run leaves all three at 0; any touching point of a run with friction sticks or
  // slips, and a residual alone (nothing touching yet) is still worth showing.
  return row.stick_points + row.slip_points > 0 || row.friction_residual != 0.0;
}

void write_history_row(JsonWriter& out, const IterationRecord& r) {
  // Exact contact mode only (classic rows have no pairs): active sets, complementarity, pairs in
  // contact, each in its alphabetical place like every member.
  const bool exact = r.active_set_iterations > 0;
  // Stepped models only (a model without steps writes its rows exactly as before).
  const bool stepped = r.step > 0;
  const bool friction = has_friction_columns(r);
  out.begin_object();
  if (exact) out.field("active_set_iterations", r.active_set_iterations);
  out.field("attempt", r.attempt)
      .field("average_closure", r.average_closure)
      .field("bimodulus_changes", r.bimodulus_changes)
      .field("closed_gaps", r.closed_gaps);
  if (exact) out.field("complementarity", r.complementarity).field("contact_pairs", r.contact_pairs);
  out.field("extrapolated", r.extrapolated);
  if (friction) out.field("friction_residual", r.friction_residual);
  out.field("gap_closures", r.gap_closures);
  if (stepped) out.field("increment", r.increment);
  out.field("iteration", r.iteration)
      .field("max_closure", r.max_closure)
      .field("nonconverged_gaps", r.nonconverged_gaps)
      .field("nonconverged_plastic", r.nonconverged_plastic);
  // The end of a converged increment only (history_json.hpp).
  if (!r.pair_forces.empty()) {
    out.key("pair_forces").begin_array();
    for (const PairForce& f : r.pair_forces) {
      out.begin_object().field("fr", f.f_r).field("fz", f.f_z);
      out.key("surfaces").begin_array().value(f.surfaces[0]).value(f.surfaces[1]).end_array().end_object();
    }
    out.end_array();
  }
  out.field("seconds", r.seconds);
  if (!r.set_reactions.empty()) {
    out.key("set_reactions").begin_array();
    for (const SetReaction& f : r.set_reactions) {
      out.begin_object().field("fr", f.f_r).field("fz", f.f_z).field("set", f.set).end_object();
    }
    out.end_array();
  }
  if (friction) out.field("slip_points", r.slip_points);
  if (stepped) out.field("step", r.step);
  if (friction) out.field("stick_points", r.stick_points);
  out.field("tensile_modulus", r.tensile_modulus);
  out.key("watch").begin_object().key("elements").begin_array();
  for (const WatchedElement& e : r.watch_elements) {
    out.begin_object()
        .field("effective", e.effective)
        .field("id", e.id)
        .field("sigma_r", e.sigma_r)
        .field("sigma_theta", e.sigma_theta)
        .field("sigma_z", e.sigma_z)
        .field("tau_rz", e.tau_rz)
        .end_object();
  }
  out.end_array().key("gaps").begin_array();
  for (const WatchedGap& g : r.watch_gaps) {
    out.begin_object()
        .field("closure", g.closure)
        .field("id", g.id)
        .field("modulus", g.modulus)
        .field("sigma_m", g.sigma_m)
        .end_object();
  }
  out.end_array().end_object();
  out.field("yielded_elements", r.yielded_elements).end_object();
}

std::string history_row_text(const IterationRecord& row) {
  std::string text;
  JsonWriter out(string_sink(text));
  write_history_row(out, row);
  out.flush();
  return text;
}

json history_row_json(const IterationRecord& r) {
  json elements = json::array();
  for (const WatchedElement& e : r.watch_elements) {
    elements.push_back({{"id", e.id},
                        {"sigma_r", e.sigma_r},
                        {"sigma_z", e.sigma_z},
                        {"tau_rz", e.tau_rz},
                        {"sigma_theta", e.sigma_theta},
                        {"effective", e.effective}});
  }
  json gaps = json::array();
  for (const WatchedGap& g : r.watch_gaps) {
    gaps.push_back({{"id", g.id}, {"modulus", g.modulus}, {"closure", g.closure}, {"sigma_m", g.sigma_m}});
  }
  json row = {{"iteration", r.iteration},
          {"tensile_modulus", r.tensile_modulus},
          {"closed_gaps", r.closed_gaps},
          {"nonconverged_gaps", r.nonconverged_gaps},
          {"average_closure", r.average_closure},
          {"max_closure", r.max_closure},
          {"yielded_elements", r.yielded_elements},
          {"nonconverged_plastic", r.nonconverged_plastic},
          {"bimodulus_changes", r.bimodulus_changes},
          {"extrapolated", r.extrapolated},
          {"watch", {{"elements", elements}, {"gaps", gaps}}},
          {"gap_closures", r.gap_closures},
          {"seconds", r.seconds},
          {"attempt", r.attempt}};
  // Exact contact mode (classic rows have no pairs): pairs in contact, the largest complementarity
  // residual, the active sets tried.
  if (r.active_set_iterations > 0) {
    row["contact_pairs"] = r.contact_pairs;
    row["complementarity"] = r.complementarity;
    row["active_set_iterations"] = r.active_set_iterations;
  }
  if (has_friction_columns(r)) {
    row["stick_points"] = r.stick_points;
    row["slip_points"] = r.slip_points;
    row["friction_residual"] = r.friction_residual;
  }
  if (r.step > 0) {
    row["step"] = r.step;
    row["increment"] = r.increment;
  }
  for (const SetReaction& f : r.set_reactions) row["set_reactions"].push_back({{"set", f.set}, {"fr", f.f_r}, {"fz", f.f_z}});
  for (const PairForce& f : r.pair_forces) {
    row["pair_forces"].push_back({{"surfaces", json::array({f.surfaces[0], f.surfaces[1]})}, {"fr", f.f_r}, {"fz", f.f_z}});
  }
  return row;
}

IterationRecord history_row_from_json(const json& j) {
  IterationRecord r;
  r.iteration = j.at("iteration").get<int>();
  r.tensile_modulus = j.at("tensile_modulus").get<double>();
  r.closed_gaps = j.at("closed_gaps").get<int>();
  r.nonconverged_gaps = j.at("nonconverged_gaps").get<int>();
  r.average_closure = j.at("average_closure").get<double>();
  r.max_closure = j.at("max_closure").get<double>();
  r.yielded_elements = j.at("yielded_elements").get<int>();
  r.nonconverged_plastic = j.at("nonconverged_plastic").get<int>();
  r.bimodulus_changes = j.value("bimodulus_changes", 0);
  r.extrapolated = j.at("extrapolated").get<bool>();
  r.seconds = j.at("seconds").get<double>();
  r.gap_closures = j.value("gap_closures", std::vector<double>{});
  r.attempt = j.value("attempt", 1);
  r.contact_pairs = j.value("contact_pairs", 0);
  r.complementarity = j.value("complementarity", 0.0);
  r.active_set_iterations = j.value("active_set_iterations", 0);
  r.stick_points = j.value("stick_points", 0);
  r.slip_points = j.value("slip_points", 0);
  r.friction_residual = j.value("friction_residual", 0.0);
  r.step = j.value("step", 0);
  r.increment = j.value("increment", 0);
  if (const auto sets = j.find("set_reactions"); sets != j.end()) {
    for (const json& f : *sets) r.set_reactions.push_back({f.at("set").get<std::string>(), f.at("fr").get<double>(), f.at("fz").get<double>()});
  }
  if (const auto pairs = j.find("pair_forces"); pairs != j.end()) {
    for (const json& f : *pairs) {
      r.pair_forces.push_back({{f.at("surfaces").at(0).get<std::string>(), f.at("surfaces").at(1).get<std::string>()},
                               f.at("fr").get<double>(),
                               f.at("fz").get<double>()});
    }
  }
  for (const json& e : j.at("watch").at("elements")) {
    r.watch_elements.push_back({e.at("id").get<int>(), e.at("sigma_r").get<double>(), e.at("sigma_z").get<double>(),
                                e.at("tau_rz").get<double>(), e.at("sigma_theta").get<double>(),
                                e.at("effective").get<double>()});
  }
  for (const json& g : j.at("watch").at("gaps")) {
    r.watch_gaps.push_back({g.at("id").get<int>(), g.at("modulus").get<double>(), g.at("closure").get<double>(),
                            g.at("sigma_m").get<double>()});
  }
  return r;
}

}  // namespace saasgaps::io
