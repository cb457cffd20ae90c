#include "io/study/study_outputs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_set>
#include <vector>

#include "io/json/value_quote.hpp"

namespace saasgaps::io {

using nlohmann::json;

namespace {

enum class Shape { items, contact, object };

struct Section {
  std::string_view name;
  Shape shape;
  /// The fields known today and those the fourth round adds (nodes' recovered stresses,
  /// elements' error, set reactions, the error estimate): a result without one makes the point's
  /// output an OutputError, not the study's.
  std::vector<std::string_view> fields;
};

const std::array<Section, 8>& sections() {
  static const std::array<Section, 8> table{{
      {"nodes", Shape::items, {"r", "z", "T", "u_r", "u_z", "sigma_r", "sigma_z", "tau_rz", "sigma_theta", "effective"}},
      {"elements", Shape::items, {"temperature", "sigma_r", "sigma_z", "tau_rz", "sigma_theta", "sigma_1", "sigma_2",
                                  "angle", "effective", "eps_r", "eps_z", "gamma_rz", "eps_theta", "q_r", "q_z", "error"}},
      {"gaps", Shape::items, {"angle", "eps_m", "closure", "modulus", "sigma_m"}},
      {"reactions", Shape::items, {"fr", "fz"}},
      {"set_reactions", Shape::items, {"fr", "fz"}},
      {"contact", Shape::contact, {"pressure", "shear", "gap", "slip", "r", "z", "force.fr", "force.fz"}},
      {"reaction_sum", Shape::object, {"fr", "fz"}},
      {"error_estimate", Shape::object, {"relative", "error", "energy_norm"}},
  }};
  return table;
}

std::string join_names(const std::vector<std::string_view>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

/// The section of `of` and its field, or nullptr.
const Section* section_of(std::string_view of, std::string_view& field) {
  const auto dot = of.find('.');
  if (dot == std::string_view::npos) return nullptr;
  const std::string_view name = of.substr(0, dot);
  field = of.substr(dot + 1);
  for (const Section& s : sections()) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

/// The member at a dotted path ("force.fz") of an object, or nullptr.
const json* member(const json& item, std::string_view path) {
  const json* at = &item;
  while (true) {
    if (!at->is_object()) return nullptr;
    const auto dot = path.find('.');
    const auto it = at->find(std::string(path.substr(0, dot)));
    if (it == at->end()) return nullptr;
    at = &*it;
    if (dot == std::string_view::npos) return at;
    path = path.substr(dot + 1);
  }
}

bool selected(const json& item, const std::optional<std::vector<int>>& ids, const char* key) {
  if (!ids) return true;
  const auto it = item.find(key);
  if (it == item.end() || !it->is_number_integer()) return false;
  return std::find(ids->begin(), ids->end(), it->get<int>()) != ids->end();
}

void take(const json* value, const std::string& where, std::vector<double>& out) {
  if (value == nullptr) return;
  // A boolean (yield) reads as 1 or 0, as the plots read it; anything else is not a number here.
  if (!value->is_number() && !value->is_boolean()) throw OutputError(where + " is " + describe(*value) + ", not a number");
  out.push_back(value->get<double>());
}

}  // namespace

std::string unknown_output_field(std::string_view of) {
  std::string_view field;
  const Section* s = section_of(of, field);
  if (s == nullptr) {
    std::vector<std::string_view> names;
    for (const Section& t : sections()) names.push_back(t.name);
    return "unknown result field " + quote_string(of) + ": need SECTION.FIELD with SECTION one of " + join_names(names);
  }
  if (std::find(s->fields.begin(), s->fields.end(), field) == s->fields.end()) {
    return "unknown result field " + quote_string(of) + ": the fields of " + std::string(s->name) + " are " +
           join_names(s->fields);
  }
  return {};
}

std::string selection_problem(const StudyOutput& output) {
  std::string_view field;
  const Section* s = section_of(output.of, field);
  if (s == nullptr) return {};
  if (output.elements && s->name != "elements") return "\"elements\" selects elements: it applies to elements.* only";
  if (output.nodes && s->name != "nodes" && s->name != "reactions") {
    return "\"nodes\" selects nodes: it applies to nodes.* and reactions.* only";
  }
  if (output.pair && s->name != "contact") return "\"pair\" selects a contact pair: it applies to contact.* only";
  if (output.set && s->name != "set_reactions") {
    return "\"set\" selects a node set: it applies to set_reactions.* only";
  }
  return {};
}

double reduce_output(const json& result, const StudyOutput& output) {
  std::string_view field;
  const Section* s = section_of(output.of, field);
  if (s == nullptr) throw OutputError(unknown_output_field(output.of));
  const auto it = result.find(std::string(s->name));
  if (it == result.end()) throw OutputError("the result has no " + std::string(s->name));
  std::vector<double> values;
  const std::string name(s->name);
  switch (s->shape) {
    case Shape::object:
      take(member(*it, field), "/" + name + "/" + std::string(field), values);
      break;
    case Shape::items: {
      if (!it->is_array()) throw OutputError("the result's " + name + " is not an array");
      const char* id_key = name == "reactions" ? "node" : "id";
      for (std::size_t k = 0; k < it->size(); ++k) {
        const json& item = (*it)[k];
        if (!selected(item, name == "elements" ? output.elements : output.nodes, id_key)) continue;
        if (output.set && item.value("set", json()) != *output.set) continue;
        take(member(item, field), "/" + name + "/" + std::to_string(k) + "/" + std::string(field), values);
      }
      break;
    }
    case Shape::contact: {
      if (!it->is_array()) throw OutputError("the result's contact is not an array");
      const bool of_pair = field.starts_with("force.");
      for (std::size_t k = 0; k < it->size(); ++k) {
        const json& pair = (*it)[k];
        if (output.pair && pair.value("surfaces", json()) != json(*output.pair)) continue;
        const std::string at = "/contact/" + std::to_string(k);
        if (of_pair) {
          take(member(pair, field), at + "/" + std::string(field), values);
          continue;
        }
        const auto points = pair.find("points");
        if (points == pair.end() || !points->is_array()) continue;
        for (std::size_t j = 0; j < points->size(); ++j) {
          take(member((*points)[j], field), at + "/points/" + std::to_string(j) + "/" + std::string(field), values);
        }
      }
      break;
    }
  }
  if (values.empty()) {
    std::string which = output.of;
    if (output.elements) which += " over the elements named";
    if (output.nodes) which += " over the nodes named";
    if (output.pair) which += " of the pair [" + (*output.pair)[0] + ", " + (*output.pair)[1] + "]";
    if (output.set) which += " of the set " + quote_string(*output.set);
    throw OutputError("the result has no value of " + which);
  }
  switch (output.reduce) {
    case Reducer::max:
      return *std::max_element(values.begin(), values.end());
    case Reducer::min:
      return *std::min_element(values.begin(), values.end());
    case Reducer::sum:
    case Reducer::mean: {
      double sum = 0.0;
      for (const double v : values) sum += v;
      return output.reduce == Reducer::sum ? sum : sum / static_cast<double>(values.size());
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace saasgaps::io
