/// The assembly's materials and parts: the materials pass through (their ids are what regions and
/// thermal sources name), and `regions` give each surface of the mesh its material, making its
/// elements the model's `elements`.
#include "io/import/assembly_importer.hpp"

#include <map>
#include <string>
#include <utility>

#include "io/json/json_pointer.hpp"
#include "io/json/value_quote.hpp"

namespace saasgaps::io::assembly {

/// The materials pass through for the model reader to judge (an id missing or not an integer among
/// the rest); regions and thermal sources may name only the integer ids gathered here.
void Importer::read_material_ids() {
  const auto m = doc_.find("materials");
  if (m == doc_.end() || !m->is_array()) return;
  for (const json& material : *m) {
    if (material.is_object() && material.contains("id") && material["id"].is_number_integer()) {
      material_ids_.insert(material["id"].get<int>());
    }
  }
}

/// regions: [{group (surface), material, angle?}]; every surface element gets exactly one.
void Importer::regions(json& model) {
  const json* list = array(doc_, "", "regions", true);
  if (list == nullptr || !mesh_loaded_) return;
  std::map<int, std::pair<int, double>> surface_material;  // surface -> (material id, angle)
  std::map<int, std::string> surface_pointer;
  bool complete = true;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string p = pointer_append("/regions", i);
    const json& o = (*list)[i];
    if (!object(o, p, {"group", "material"}, {"angle"})) continue;
    const PhysicalGroup* g = group(o, p, {{2}, "a region", "a surface (dimension 2)"});
    const double angle = number(o, p, "angle").value_or(0.0);
    const auto m = o.find("material");
    if (m == o.end()) {
      complete = false;  // reported by object()
      continue;
    }
    if (!m->is_number_integer() || !material_ids_.contains(m->get<int>())) {
      report(pointer_append(p, "material"), "material " + quote(*m) + " is not the id of an entry of /materials");
      complete = false;
      continue;
    }
    if (g == nullptr) {
      complete = false;
      continue;
    }
    for (const int surface : g->entities) {
      const auto [first, fresh] = surface_pointer.emplace(surface, pointer_append(p, "group"));
      if (!fresh) {
        report(pointer_append(p, "group"), "surface " + std::to_string(surface) + " of group \"" + g->name +
                                               "\" already has a material from " + first->second +
                                               "; give each surface one region");
        continue;
      }
      surface_material[surface] = {m->get<int>(), angle};
      surface_material_[surface] = m->get<int>();
    }
  }
  if (!complete) return;
  json& elements = model["elements"] = json::array();
  std::map<int, std::size_t> missing;  // surface -> elements without a region
  for (const MeshFace& f : mesh_.faces) {
    const auto it = surface_material.find(f.surface);
    if (it == surface_material.end()) {
      ++missing[f.surface];
      continue;
    }
    json nodes = json::array();
    for (int k = 0; k < f.count; ++k) nodes.push_back(tag_of(f.nodes[static_cast<std::size_t>(k)]));
    json e = {{"id", static_cast<int>(f.tag)}, {"nodes", std::move(nodes)}, {"material", it->second.first}};
    if (it->second.second != 0.0) e["angle"] = it->second.second;
    elements.push_back(std::move(e));
  }
  for (const auto& [surface, count] : missing) {
    report("/regions", "surface " + std::to_string(surface) + " of the mesh (" + std::to_string(count) +
                           " elements) is in no region; put it in a physical surface named by a region");
  }
}

}  // namespace saasgaps::io::assembly
