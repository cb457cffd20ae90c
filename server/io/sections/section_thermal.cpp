/// Heat conduction in the model: the materials' k and c, the `thermal` section, and the conductance
/// of gap elements (solver/thermal_analysis.hpp says how they are used).
#include <algorithm>
#include <array>
#include <cmath>

#include "io/json/value_quote.hpp"
#include "io/sections/run_limits.hpp"
#include "io/sections/section_reader.hpp"

namespace saasgaps::io {

namespace {

constexpr Range emissivity_range{Bound{0.0, true}, Bound{1.0, true}, "an emissivity is a fraction of a black body's"};

std::string material_name(const Material& m) { return "material " + std::to_string(m.id); }

}  // namespace

/// k (isotropic) or k1, k2, k3 (orthotropic), and c: each in every row of `table` or in none;
/// never in compression_table (conduction does not depend on the sign of the stress).
void SectionReader::read_heat_properties(const Obj& material, Material& m) {
  const std::vector<std::string_view> conductivity_keys =
      m.isotropic ? std::vector<std::string_view>{"k"} : std::vector<std::string_view>{"k1", "k2", "k3"};
  if (const json* rows = material.find("compression_table"); rows != nullptr && rows->is_array()) {
    for (std::size_t i = 0; i < rows->size(); ++i) {
      if (!(*rows)[i].is_object()) continue;
      for (const auto& [key, value] : (*rows)[i].items()) {
        if (key != "c" && std::ranges::find(conductivity_keys, key) == conductivity_keys.end()) continue;
        report(pointer_append(pointer_append(material.at("compression_table"), i), key),
               key + " belongs in table: compression_table holds the elastic constants in compression only");
      }
    }
  }
  const json* rows = material.find("table");
  if (rows == nullptr || !rows->is_array() || rows->empty()) return;
  // Whether row i has every key of a group; the first row decides what the others must have.
  const auto has_all = [&](std::size_t i, std::span<const std::string_view> keys) {
    const json& row = (*rows)[i];
    return row.is_object() && std::ranges::all_of(keys, [&](std::string_view k) { return row.contains(k); });
  };
  const auto has_any = [&](std::size_t i, std::span<const std::string_view> keys) {
    const json& row = (*rows)[i];
    return row.is_object() && std::ranges::any_of(keys, [&](std::string_view k) { return row.contains(k); });
  };
  const std::array<std::string_view, 1> c_key{"c"};
  bool conducts = true;
  bool stores_heat = true;
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const std::string row = pointer_append(material.at("table"), i);
    if (has_any(i, conductivity_keys) && !has_all(i, conductivity_keys)) {
      report(row, "an orthotropic row gives the conductivity along all three material axes: k1, k2 and k3 together");
    }
    if (has_all(i, conductivity_keys) != has_all(0, conductivity_keys)) {
      report(row, std::string(has_all(0, conductivity_keys) ? "the first row gives" : "this row gives") +
                      " the conductivity and " + (has_all(0, conductivity_keys) ? "this row does not" : "the first does not") +
                      "; give it in every row of the table or in none (it is interpolated in T like every property)");
    }
    if (has_all(i, c_key) != has_all(0, c_key)) {
      report(row, std::string(has_all(0, c_key) ? "the first row gives c and this row does not"
                                                : "this row gives c and the first does not") +
                      "; give it in every row of the table or in none");
    }
    conducts = conducts && has_all(i, conductivity_keys);
    stores_heat = stores_heat && has_all(i, c_key);
  }
  m.conducts = conducts;
  m.stores_heat = stores_heat;
}

/// [a, b]: two node ids, consecutive corners of exactly one solid element (a boundary edge); or
/// [a, m, b], naming the mid-side node m of a quadratic element's edge too (as a pressure may).
std::optional<ThermalEdge> SectionReader::read_thermal_edge(const json& ids, const std::string& pointer,
                                                            const EdgeOwners& owners) {
  if (!ids.is_array() || (ids.size() != 2 && ids.size() != 3)) {
    report(pointer, "an edge is an array of 2 node ids [a, b] (or [a, m, b] with the mid-side node of a quadratic "
                    "element's edge), got " + describe(ids));
    return std::nullopt;
  }
  const std::size_t count = ids.size();
  std::array<int, 3> nodes{-1, -1, -1};
  for (std::size_t k = 0; k < count; ++k) {
    const Entry* node = resolve_node(ids[k], Where(pointer, k));
    if (node != nullptr) nodes[k] = node->index;
  }
  const int a = nodes[0], b = nodes[count - 1];
  if (std::count(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(count), -1) > 0 || !solids_complete_) {
    return std::nullopt;
  }
  const auto found = owners.find(std::minmax(a, b));
  if (a == b || found == owners.end()) {
    report(pointer, "no solid element has the edge " + quote(ids) + (count == 3 ? ": its end nodes" : ": the two nodes") +
                        " must be consecutive corners of one solid element");
    return std::nullopt;
  }
  if (found->second.size() > 1) {
    report(pointer, "the edge " + quote(ids) +
                        " lies between two solid elements; a thermal boundary condition acts on a boundary edge, "
                        "which exactly one solid element has");
    return std::nullopt;
  }
  if (count == 3 && !check_middle_node(ids, pointer, found->second.front(), a, nodes[1], b)) return std::nullopt;
  return ThermalEdge{found->second.front(), a, b};
}

/// {edges: [[a, b], ...], and exactly one of temperature, flux, film with ambient, or emissivity with
/// ambient and stefan_boltzmann (radiation; value = emissivity x stefan_boltzmann)}.
std::optional<ThermalBoundary> SectionReader::read_thermal_boundary(const json& item, const std::string& pointer,
                                                                    const EdgeOwners& owners) {
  if (!object(item, pointer, {"edges"}, {"temperature", "flux", "film", "ambient", "emissivity", "stefan_boltzmann"})) {
    return std::nullopt;
  }
  const Obj o{&item, pointer};
  ThermalBoundary b;
  bool valid = true;
  int kinds = 0;
  for (const auto& [kind, key] : thermal_boundary_keys.entries()) {
    if (o.find(key) == nullptr) continue;
    ++kinds;
    b.kind = kind;
    const Range& range = b.kind == ThermalBoundary::Kind::film        ? non_negative
                         : b.kind == ThermalBoundary::Kind::radiation ? emissivity_range
                                                                      : any_number;
    const auto value = number_field(o, key, range);
    valid = valid && value.has_value();
    b.value = value.value_or(0.0);
  }
  if (kinds != 1) {
    report(pointer, "a thermal boundary entry gives exactly one of temperature, flux, film (with ambient), or "
                    "emissivity (with ambient and stefan_boltzmann); this one gives " + std::to_string(kinds));
    valid = false;
  }
  const bool radiates = kinds == 1 && b.kind == ThermalBoundary::Kind::radiation;
  if (kinds == 1 && (b.kind == ThermalBoundary::Kind::film || radiates)) {
    if (o.find("ambient") == nullptr) {
      report(pointer, radiates ? "radiation needs the ambient temperature: the flux out is emissivity "
                                 "stefan_boltzmann (T^4 - ambient^4)"
                               : "a film needs the ambient temperature: the flux out is film (T - ambient)");
      valid = false;
    }
    // Radiation's temperatures are absolute (T^4): a negative ambient is a temperature on another scale.
    const auto ambient = number_field(o, "ambient", radiates ? non_negative : any_number);
    valid = valid && (ambient.has_value() || o.find("ambient") == nullptr);
    b.ambient = ambient.value_or(0.0);
  } else if (o.find("ambient") != nullptr) {
    report(o.at("ambient"), "ambient belongs to a film or radiation; this entry has neither");
    valid = false;
  }
  if (radiates) {
    if (o.find("stefan_boltzmann") == nullptr) {
      report(pointer, "radiation needs stefan_boltzmann, the Stefan-Boltzmann constant in the model's units (5.670374e-8 "
                      "W/(m^2 K^4) in SI, temperatures in kelvin): the flux out is emissivity stefan_boltzmann (T^4 - "
                      "ambient^4)");
      valid = false;
    }
    const auto sigma = number_field(o, "stefan_boltzmann", positive);
    valid = valid && (sigma.has_value() || o.find("stefan_boltzmann") == nullptr);
    b.value *= sigma.value_or(0.0);
  } else if (o.find("stefan_boltzmann") != nullptr) {
    report(o.at("stefan_boltzmann"), "stefan_boltzmann belongs to radiation (an entry with emissivity); this entry "
                                     "does not radiate");
    valid = false;
  }
  if (const json* edges = array_field(o, "edges", 1)) {
    for (std::size_t i = 0; i < edges->size(); ++i) {
      const auto edge = read_thermal_edge((*edges)[i], pointer_append(o.at("edges"), i), owners);
      if (edge) b.edges.push_back(*edge);
      valid = valid && edge.has_value();
    }
  } else {
    valid = false;
  }
  if (!valid) return std::nullopt;
  return b;
}

/// Every material needs its conductivity; a transient run also its specific heat and density.
void SectionReader::check_thermal_materials(const Thermal& thermal) {
  for (const Material& m : model_.materials) {
    const Entry* entry = materials_.find(m.id);
    if (entry == nullptr) continue;
    const std::string pointer = pointer_append("/materials", static_cast<std::size_t>(entry->item));
    if (!m.conducts) {
      report(pointer_append(pointer, "table"),
             material_name(m) + " has no conductivity: a thermal run needs " +
                 (m.isotropic ? "k" : "k1, k2 and k3") + " > 0 in every row of its table");
    }
    if (thermal.type != ThermalType::transient) continue;
    if (!m.stores_heat) {
      report(pointer_append(pointer, "table"),
             material_name(m) + " has no specific heat: a transient run needs c > 0 in every row of its table");
    }
    if (!(m.density > 0.0)) {
      report(pointer, material_name(m) + " has density " + format_number(m.density) +
                          ": a transient run stores heat density c per unit volume, so it needs density > 0");
    }
  }
}

/// Transient: output times strictly increasing in (0, end_time]; default [end_time]. A time step
/// that does not divide them is shortened before each output time so that every one is hit
/// exactly (documented in docs/model.md), not an error.
void SectionReader::read_output_times(const Obj& o, Thermal& thermal) {
  const json* list = array_field(o, "output_times", 1);
  if (list == nullptr) {
    if (o.find("output_times") == nullptr && thermal.end_time > 0.0) thermal.output_times = {thermal.end_time};
    return;
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = pointer_append(o.at("output_times"), i);
    const auto t = number((*list)[i], pointer, "an output time", positive);
    if (!t) continue;
    if (thermal.end_time > 0.0 && *t > thermal.end_time) {
      report(pointer, "output time " + format_number(*t) + " is after end_time = " + format_number(thermal.end_time));
      continue;
    }
    if (!thermal.output_times.empty() && !(*t > thermal.output_times.back())) {
      report(pointer, "output time " + format_number(*t) + " does not follow " +
                          format_number(thermal.output_times.back()) + "; output times must be strictly increasing");
      continue;
    }
    thermal.output_times.push_back(*t);
  }
}

/// Optional {type, boundary?, sources?, initial_temperature?, time_step?, end_time?, output_times?}.
void SectionReader::read_thermal(const Obj& root) {
  const json* v = root.find("thermal");
  if (v == nullptr) return;
  const std::string pointer = root.at("thermal");
  if (!object(*v, pointer, {"type"},
              {"boundary", "sources", "initial_temperature", "time_step", "end_time", "output_times"})) {
    return;
  }
  const Obj o{v, pointer};
  Thermal thermal;
  const auto type = choice_field(o, "type", thermal_type_names);
  if (type) thermal.type = *type;
  for (const std::string& given : temperature_pointers_) {
    report(given, "the temperatures are given here and computed by " + pointer +
                      "; remove one of them (a thermal run solves the node temperatures itself)");
  }
  bool fixes_level = false;  // some temperature or film ties the steady solution down
  if (const json* list = array_field(o, "boundary", 0)) {
    const EdgeOwners owners = solid_edge_owners();
    std::map<int, std::pair<double, std::string>> held;  // node index -> (temperature, pointer of its entry)
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string item = pointer_append(o.at("boundary"), i);
      auto b = read_thermal_boundary((*list)[i], item, owners);
      if (!b) continue;
      fixes_level = fixes_level || b->kind != ThermalBoundary::Kind::flux;
      if (b->kind == ThermalBoundary::Kind::temperature) {
        for (const ThermalEdge& e : b->edges) {
          for (const int n : {e.node_a, e.node_b}) {
            const auto [first, fresh] = held.emplace(n, std::pair{b->value, item});
            if (!fresh && first->second.first != b->value) {
              report(pointer_append(item, "temperature"),
                     "node " + std::to_string(model_.nodes[static_cast<std::size_t>(n)].id) + " is already held at " +
                         format_number(first->second.first) + " by " + first->second.second +
                         "; a node has one prescribed temperature");
            }
          }
        }
      }
      thermal.boundary.push_back(std::move(*b));
    }
  }
  if (const json* list = array_field(o, "sources", 0)) {
    std::map<int, std::string> named;  // material index -> pointer of its source
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string item = pointer_append(o.at("sources"), i);
      if (!object((*list)[i], item, {"material", "power_density"})) continue;
      const Obj s{&(*list)[i], item};
      const auto power = number_field(s, "power_density");
      const json* id = s.find("material");
      const Entry* m = id == nullptr ? nullptr
                                     : resolve(materials_, materials_complete_, *id, s.at("material"), "material",
                                               "/materials");
      if (m == nullptr || !power) continue;
      const auto [first, fresh] = named.emplace(m->index, item);
      if (!fresh) {
        report(s.at("material"), "material " + quote(*id) + " already has a source at " + first->second +
                                     "; give each material one power_density");
        continue;
      }
      thermal.sources.push_back({m->index, *power});
    }
  }
  const bool transient = type && thermal.type == ThermalType::transient;
  if (type && !transient) {
    for (const std::string_view key : {"initial_temperature", "time_step", "end_time", "output_times"}) {
      if (o.find(key) != nullptr) report(o.at(key), std::string(key) + " applies only to a transient run; type is steady");
    }
    if (!fixes_level) {
      report(o.find("boundary") != nullptr ? o.at("boundary") : pointer,
             "a steady run needs a prescribed temperature or a film on some edge: with fluxes and insulated edges only "
             "the temperature is fixed up to a constant (the conduction matrix is singular)");
    }
  }
  if (transient) {
    for (const std::string_view key : {"initial_temperature", "time_step", "end_time"}) {
      if (o.find(key) == nullptr) report(pointer, "a transient run needs " + std::string(key));
    }
    thermal.initial_temperature = number_field(o, "initial_temperature").value_or(0.0);
    thermal.time_step = number_field(o, "time_step", positive).value_or(0.0);
    thermal.end_time = number_field(o, "end_time", positive).value_or(0.0);
    if (thermal.time_step > 0.0 && thermal.end_time / thermal.time_step > max_time_steps_limit) {
      report(o.at("time_step"), "time_step = " + format_number(thermal.time_step) + " takes " +
                                    format_number(std::ceil(thermal.end_time / thermal.time_step)) +
                                    " steps to end_time = " + format_number(thermal.end_time) + "; at most " +
                                    format_number(max_time_steps_limit) + " are allowed");
    }
    read_output_times(o, thermal);
    if (!model_.steps.empty()) {
      report("/steps", "a transient thermal run makes its load steps itself, one per output time; remove steps");
    }
  }
  if (type) check_thermal_materials(thermal);
  model_.thermal = std::move(thermal);
}

}  // namespace saasgaps::io
