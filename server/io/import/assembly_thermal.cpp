/// The assembly's `thermal` section (docs/import.md, "Heat conduction"): the model's `thermal`
/// (docs/model.md) with boundary conditions on physical curves instead of edges and sources on
/// physical surfaces instead of material ids:
///
///   "thermal": {"type": "steady",
///               "boundary": [{"group": "outer_surface", "film": 0.02, "ambient": 3000.0},
///                            {"group": "retainer_bore", "temperature": 2000.0}],
///               "sources": [{"group": "retainer", "power_density": 1.5}]}
///
/// boundary[i] becomes the model's boundary[i] (same index, so the model reader's findings on its
/// values keep their pointers) with `edges` the group's line elements, each a side of exactly one
/// solid element; sources[i] with `group` becomes one source per material of the group's surfaces,
/// and the group must hold every surface of those materials (a model's source heats every element
/// of its material, so a group holding part of one would heat more than it names). A source may
/// name `material` instead, as in the model. The other keys (type, initial_temperature, time_step,
/// end_time, output_times) pass through.
#include "io/import/assembly_importer.hpp"

#include <map>
#include <set>

#include "io/json/json_pointer.hpp"
#include "io/json/value_quote.hpp"

namespace saasgaps::io::assembly {

void Importer::thermal(json& model) {
  const auto it = doc_.find("thermal");
  if (it == doc_.end()) return;
  if (!it->is_object()) {
    report("/thermal", "expected an object, got " + describe(*it));
    return;
  }
  if (const auto loads = doc_.find("loads"); loads != doc_.end() && loads->is_object() && loads->contains("temperatures")) {
    report("/loads/temperatures", "the temperatures are given here and computed by /thermal; remove one of them (a "
                                  "thermal run solves the node temperatures itself)");
  }
  json out = *it;
  if (const json* list = array(*it, "/thermal", "boundary", false); list != nullptr && mesh_loaded_) {
    thermal_boundary(*list, "/thermal/boundary", out["boundary"]);
  }
  if (const json* list = array(*it, "/thermal", "sources", false); list != nullptr && mesh_loaded_) {
    thermal_sources(*list, "/thermal/sources", out["sources"]);
  }
  model["thermal"] = std::move(out);
}

/// [{group (curve), temperature | flux | film + ambient}]: the values pass through for the model
/// reader to judge at the same pointers.
void Importer::thermal_boundary(const json& list, const std::string& lp, json& out) {
  out = json::array();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string p = pointer_append(lp, i);
    const json& o = list[i];
    if (o.is_object() && o.contains("edges")) {
      report(pointer_append(p, "edges"), "the edges are those of the curve group named in group; remove edges");
    }
    if (!object(o, p, {"group"}, {"temperature", "flux", "film", "ambient", "edges"})) continue;
    json entry = o;
    entry.erase("group");
    const PhysicalGroup* g = group(o, p, {{1}, "a thermal boundary condition", "a curve (dimension 1)"});
    if (g != nullptr) {
      if (const auto edges = boundary_edges(*g, p, "a thermal boundary condition")) {
        json& generated = entry["edges"] = json::array();
        for (const BoundaryEdge& e : *edges) generated.push_back({tag_of(e.a), tag_of(e.b)});
      }
    }
    origins_.add(pointer_append(p, "edges"), pointer_append(p, "group"));
    out.push_back(std::move(entry));
  }
}

/// [{group (surface) | material, power_density}]: one model source per material.
void Importer::thermal_sources(const json& list, const std::string& lp, json& out) {
  out = json::array();
  std::map<int, std::string> heated;  // material id -> pointer of the source that heats it
  const auto add = [&](int material, const json& power, const std::string& p, const std::string& at) {
    const auto [first, fresh] = heated.emplace(material, p);
    if (!fresh) {
      report(at, "material " + std::to_string(material) + " is already heated by " + first->second +
                     "; a source heats every element of its material, so give each material one source");
      return;
    }
    origins_.add(pointer_append("/thermal/sources", out.size()), p, true);
    out.push_back({{"material", material}, {"power_density", power}});
  };
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string p = pointer_append(lp, i);
    const json& o = list[i];
    if (!object(o, p, {"power_density"}, {"group", "material"})) continue;
    if (o.contains("group") == o.contains("material")) {
      report(p, "a source names the surface group it heats in group (or a material id in material): exactly one of them");
      continue;
    }
    const auto power = o.find("power_density");
    if (power == o.end()) continue;  // reported by object()
    if (const auto m = o.find("material"); m != o.end()) {
      if (!m->is_number_integer() || !material_ids_.contains(m->get<int>())) {
        report(pointer_append(p, "material"), "material " + quote(*m) + " is not the id of an entry of /materials");
        continue;
      }
      add(m->get<int>(), *power, p, pointer_append(p, "material"));
      continue;
    }
    const PhysicalGroup* g = group(o, p, {{2}, "a heat source", "a surface (dimension 2)"});
    if (g == nullptr) continue;
    const std::set<int> surfaces(g->entities.begin(), g->entities.end());
    std::set<int> materials;
    for (const int surface : surfaces) {
      if (const auto found = surface_material_.find(surface); found != surface_material_.end()) {
        materials.insert(found->second);
      }
    }
    bool whole = true;
    for (const auto& [surface, material] : surface_material_) {
      if (!materials.contains(material) || surfaces.contains(surface)) continue;
      report(pointer_append(p, "group"),
             "surface " + std::to_string(surface) + " is material " + std::to_string(material) + " too, and group \"" +
                 g->name + "\" does not hold it: a source heats every element of its material, so the group must hold "
                 "all of them (give the heated part a material of its own)");
      whole = false;
      break;
    }
    if (!whole) continue;
    for (const int material : materials) add(material, *power, p, pointer_append(p, "group"));
  }
}

}  // namespace saasgaps::io::assembly
