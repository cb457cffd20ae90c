/// The `sets` section (docs/model.md, "Named sets"): named lists of nodes, edges and elements, and
/// the constraints {set, r?, z?} and pressures {set, normal?, shear?} that name them. A set is
/// expanded where it is named: the solver sees node constraints and edge pressures as before, and
/// only the node sets that constraints name reach it, as reaction groups (Model::reaction_groups).
#include "io/json/value_quote.hpp"
#include "io/sections/section_reader.hpp"

namespace saasgaps::io {

namespace {
constexpr std::array<std::string_view, 3> set_kinds{"nodes", "edges", "elements"};
}  // namespace

/// Optional {nodes?: {NAME: [ids]}, edges?: {NAME: [[a, b], ...]}, elements?: {NAME: [ids]}}; each
/// set non-empty, a name non-empty, an id once per set; an edge two corners of one solid element.
void SectionReader::read_sets(const Obj& root) {
  const json* v = root.find("sets");
  if (v == nullptr) return;
  if (!check_object(*v, root.at("sets"), {}, set_kinds)) {
    sets_complete_ = false;
    return;
  }
  const Obj sets{v, root.at("sets")};
  read_node_sets(sets);
  read_edge_sets(sets);
  read_element_sets(sets);
}

namespace {
/// The members of sets[kind] when it is an object; reports the kind and every empty name.
template <class Report>
const json* named_lists(const json& sets, std::string_view kind, const std::string& pointer, Report&& report) {
  const auto it = sets.find(kind);
  if (it == sets.end()) return nullptr;
  if (!it->is_object()) {
    report(pointer, std::string(kind) + " must be an object of named lists {\"NAME\": [...]}, got " + quote(*it));
    return nullptr;
  }
  for (const auto& [name, list] : it->items()) {
    const std::string at = pointer_append(pointer, name);
    if (name.empty()) report(at, "a set name must not be empty");
    if (!list.is_array() || list.empty()) {
      report(at, "set " + quote_string(name) + " must be a non-empty array, got " + quote(list));
    }
  }
  return &*it;
}
}  // namespace

void SectionReader::read_node_sets(const Obj& sets) {
  const std::string pointer = sets.at("nodes");
  const json* named = named_lists(*sets.value, "nodes", pointer, reporter());
  if (named == nullptr) {
    sets_complete_ = sets_complete_ && sets.find("nodes") == nullptr;
    return;
  }
  for (const auto& [name, list] : named->items()) {
    if (name.empty() || !list.is_array() || list.empty()) continue;
    const std::string at = pointer_append(pointer, name);
    std::vector<int> nodes;
    std::map<int, std::size_t> listed;  // node index -> item that listed it
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Entry* node = resolve_node(list[i], Where(at, i));
      if (node == nullptr) continue;
      const auto [first, fresh] = listed.emplace(node->index, i);
      if (!fresh) {
        report(Where(at, i), "node " + quote(list[i]) + " is already in set " + quote_string(name) + " at " +
                                 pointer_append(at, first->second) + "; list each node once");
        continue;
      }
      nodes.push_back(node->index);
    }
    std::sort(nodes.begin(), nodes.end());
    node_sets_.emplace(name, std::move(nodes));
  }
}

void SectionReader::read_edge_sets(const Obj& sets) {
  const std::string pointer = sets.at("edges");
  const json* named = named_lists(*sets.value, "edges", pointer, reporter());
  if (named == nullptr) {
    sets_complete_ = sets_complete_ && sets.find("edges") == nullptr;
    return;
  }
  const EdgeOwners owners = solid_edge_owners();
  for (const auto& [name, list] : named->items()) {
    if (name.empty() || !list.is_array() || list.empty()) continue;
    const std::string at = pointer_append(pointer, name);
    std::vector<std::array<int, 2>> edges;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string item = pointer_append(at, i);
      const json& ids = list[i];
      if (!ids.is_array() || ids.size() != 2) {
        report(item, "an edge of a set is [a, b], two corner nodes of one solid element, got " + quote(ids));
        continue;
      }
      const Entry* a = resolve_node(ids[0], Where(item, std::size_t{0}));
      const Entry* b = resolve_node(ids[1], Where(item, std::size_t{1}));
      if (a == nullptr || b == nullptr || !solids_complete_) continue;
      if (!owners.contains(std::minmax(a->index, b->index))) {
        report(item, "no solid element has the edge " + quote(ids) + " of set " + quote_string(name) +
                         ": the two nodes must be consecutive corners of one solid element");
        continue;
      }
      edges.push_back({a->index, b->index});
    }
    edge_sets_.emplace(name, std::move(edges));
  }
}

void SectionReader::read_element_sets(const Obj& sets) {
  const std::string pointer = sets.at("elements");
  const json* named = named_lists(*sets.value, "elements", pointer, reporter());
  if (named == nullptr) {
    sets_complete_ = sets_complete_ && sets.find("elements") == nullptr;
    return;
  }
  for (const auto& [name, list] : named->items()) {
    if (name.empty() || !list.is_array() || list.empty()) continue;
    const std::string at = pointer_append(pointer, name);
    std::vector<int> ids;
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (resolve(elements_, elements_complete(), list[i], Where(at, i), "element", "/elements or /gaps/elements")) {
        ids.push_back(list[i].get<int>());
      }
    }
    element_sets_.emplace(name, std::move(ids));
  }
}

namespace {
/// "unknown node set "X" (the node sets are "a", "b")" or "(the model defines no node sets)".
template <class Sets>
std::string unknown_set(std::string_view kind, const std::string& name, const Sets& sets) {
  std::string text = "unknown " + std::string(kind) + " set " + quote_string(name);
  if (sets.empty()) return text + " (the model defines no " + std::string(kind) + " sets under /sets/" +
                            (kind == "node" ? "nodes" : "edges") + ")";
  text += " (defined: ";
  bool first = true;
  for (const auto& entry : sets) {
    text += (first ? "" : ", ") + quote_string(entry.first);
    first = false;
  }
  return text + ")";
}
}  // namespace

const std::vector<int>* SectionReader::resolve_set(const Obj& o, std::string_view kind) {
  const auto name = string_field(o, "set");
  if (!name) return nullptr;
  const auto found = node_sets_.find(*name);
  if (found != node_sets_.end()) return &found->second;
  if (sets_complete_) report(o.at("set"), unknown_set(kind, *name, node_sets_));
  return nullptr;
}

const std::vector<std::array<int, 2>>* SectionReader::resolve_edge_set(const Obj& o) {
  const auto name = string_field(o, "set");
  if (!name) return nullptr;
  const auto found = edge_sets_.find(*name);
  if (found != edge_sets_.end()) return &found->second;
  if (sets_complete_) report(o.at("set"), unknown_set("edge", *name, edge_sets_));
  return nullptr;
}

std::vector<Constraint> SectionReader::read_set_constraint(const Obj& o, PrescribedAt& seen) {
  const auto u_r = number_field(o, "r");
  const auto u_z = number_field(o, "z");
  if (o.find("r") == nullptr && o.find("z") == nullptr) {
    report(o.pointer, "the constraint of set " + quote(*o.find("set")) +
                          " prescribes neither r nor z; give r and/or z (the prescribed displacement)");
  }
  const std::vector<int>* nodes = resolve_set(o, "node");
  if (nodes == nullptr) return {};
  const std::string name = o.find("set")->get<std::string>();
  std::vector<Constraint> constraints;
  constraints.reserve(nodes->size());
  for (const int node : *nodes) {
    Constraint c;
    c.node = node;
    for (const char component : {'r', 'z'}) {
      const std::string_view key = component == 'r' ? "r" : "z";
      const std::optional<double>& value = component == 'r' ? u_r : u_z;
      if (o.find(key) == nullptr) continue;
      const auto [first, fresh] = seen.emplace(std::pair{node, component}, Prescribed(o.at(key), value.value_or(0.0)));
      if (fresh) {
        (component == 'r' ? c.u_r : c.u_z) = value;
        continue;
      }
      // Two sets that share a node (a corner of two faces) may prescribe it the same value.
      if (value && first->second.set_value == value) continue;
      report(o.at(key), std::string(key) + " of node " + std::to_string(model_.nodes[static_cast<std::size_t>(node)].id) +
                            " (in set " + quote_string(name) + ") is already prescribed at " + first->second.pointer +
                            (first->second.set_value ? " to another value" : "") + "; prescribe each component once");
    }
    if (c.u_r || c.u_z) constraints.push_back(c);
  }
  const auto known = std::find_if(model_.reaction_groups.begin(), model_.reaction_groups.end(),
                                  [&](const ReactionGroup& g) { return g.name == name; });
  if (known == model_.reaction_groups.end()) model_.reaction_groups.push_back({name, *nodes});
  return constraints;
}

void SectionReader::read_set_pressure(const Obj& o, const std::map<std::pair<int, int>, std::vector<int>>& owners,
                                      Loads& into) {
  if (!object(*o.value, o.pointer, {"set"}, {"normal", "shear"})) return;
  EdgePressure p;
  p.normal = number_field(o, "normal").value_or(0.0);
  p.shear = number_field(o, "shear").value_or(0.0);
  const std::vector<std::array<int, 2>>* edges = resolve_edge_set(o);
  if (edges == nullptr || !solids_complete_) return;
  for (const auto& [a, b] : *edges) {
    const auto found = owners.find(std::minmax(a, b));
    if (found == owners.end()) continue;  // read_edge_sets keeps only element edges
    if (found->second.size() > 1) {
      report(o.at("set"), "the edge [" + std::to_string(model_.nodes[static_cast<std::size_t>(a)].id) + ", " +
                              std::to_string(model_.nodes[static_cast<std::size_t>(b)].id) + "] of set " +
                              quote(*o.find("set")) +
                              " lies between two solid elements; a pressure acts on boundary edges only");
      return;
    }
    p.element = found->second.front();
    p.node_a = a;
    p.node_b = b;
    into.pressures.push_back(p);
  }
}

}  // namespace saasgaps::io
