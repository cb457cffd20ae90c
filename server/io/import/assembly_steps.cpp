/// The assembly's `steps` (docs/import.md): the model's load steps with physical group names where
/// the model names sets. A step's constraints become constraints on the node set of their group
/// ({set: group, r?, z?}); its loads are converted as the top-level loads are.
#include "io/import/assembly_importer.hpp"

#include <string>
#include <utility>

#include "io/json/json_pointer.hpp"
#include "io/sections/run_limits.hpp"

namespace saasgaps::io::assembly {

/// steps: [{name, increments?, loads?, constraints?: [{group (point or curve), r?, z?}]}]. Names,
/// increments and the rules between steps are the model reader's (they keep their pointers).
void Importer::steps(json& model) {
  const json* list = array(doc_, "", "steps", true);
  if (list == nullptr) return;
  json out = json::array();
  for (std::size_t k = 0; k < list->size(); ++k) {
    const std::string p = pointer_append("/steps", k);
    const json& s = (*list)[k];
    if (!object(s, p, {"name"}, {"increments", "loads", "constraints"})) continue;
    json step = json::object();
    for (const char* key : {"name", "increments"}) {
      if (const auto v = s.find(key); v != s.end()) step[key] = *v;
    }
    if (const auto l = s.find("loads"); l != s.end()) {
      if (auto loads = converted_loads(*l, pointer_append(p, "loads"))) step["loads"] = std::move(*loads);
    }
    if (const json* constraints = array(s, p, "constraints", false)) {
      json& into = step["constraints"] = json::array();
      for (std::size_t i = 0; i < constraints->size(); ++i) {
        const std::string cp = pointer_append(pointer_append(p, "constraints"), i);
        const json& o = (*constraints)[i];
        if (!object(o, cp, {"group"}, {"r", "z"}) || !o.contains("group")) continue;
        const PhysicalGroup* g = group(o, cp, {{0, 1}, "a constraint", "points or curves (dimension 0 or 1)"});
        json c = {{"set", o.at("group")}};
        for (const char* key : {"r", "z"}) {
          if (const auto v = o.find(key); v != o.end()) c[key] = *v;
        }
        if (g == nullptr || !mesh_loaded_) continue;
        (void)group_nodes(*g, cp);  // reports a group off the mesh
        origins_.add(pointer_append(cp, "set"), pointer_append(cp, "group"), true);
        into.push_back(std::move(c));
      }
    }
    out.push_back(std::move(step));
  }
  model["steps"] = std::move(out);
}

}  // namespace saasgaps::io::assembly
