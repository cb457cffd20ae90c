/// The assembly's `constraints` (docs/import.md): prescribed displacements on the nodes of point and
/// curve groups, as the model's constraints node by node.
#include "io/import/assembly_importer.hpp"

#include <map>
#include <string>
#include <utility>

#include "io/json/json_pointer.hpp"

namespace saasgaps::io::assembly {

/// constraints: [{group (point or curve), r?, z?}]; a node's component prescribed twice must agree.
void Importer::constraints(json& model) {
  const json* list = array(doc_, "", "constraints", true);
  if (list == nullptr || !mesh_loaded_) return;
  // node -> component -> (value, pointer); std::map keeps the output in node order.
  std::map<int, std::map<char, std::pair<double, std::string>>> prescribed;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string p = pointer_append("/constraints", i);
    const json& o = (*list)[i];
    if (!object(o, p, {"group"}, {"r", "z"})) continue;
    if (!o.contains("r") && !o.contains("z")) report(p, "the constraint prescribes neither r nor z; give r and/or z");
    const PhysicalGroup* g = group(o, p, {{0, 1}, "a constraint", "points or curves (dimension 0 or 1)"});
    std::map<char, double> values;
    for (const char c : {'r', 'z'}) {
      if (const auto v = number(o, p, std::string(1, c))) values[c] = *v;
    }
    if (g == nullptr) continue;
    for (const int node : group_nodes(*g, p)) {
      for (const auto& [c, v] : values) {
        const std::string at = pointer_append(p, std::string(1, c));
        const auto [first, fresh] = prescribed[node].emplace(c, std::pair{v, at});
        if (!fresh && first->second.first != v) {
          report(at, std::string(1, c) + " = " + json(v).dump() + " of node " + std::to_string(tag_of(node)) +
                         " contradicts " + json(first->second.first).dump() + " from " + first->second.second);
        }
      }
    }
  }
  json& out = model["constraints"] = json::array();
  for (const auto& [node, components] : prescribed) {
    json c = {{"node", tag_of(node)}};
    for (const auto& [component, value] : components) c[std::string(1, component)] = value.first;
    out.push_back(std::move(c));
  }
}

}  // namespace saasgaps::io::assembly
