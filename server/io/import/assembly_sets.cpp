/// The model's `sets` written by the import (docs/import.md, "Named sets"): one per physical group
/// the assembly uses, under the group's name: a point group's nodes, a curve group's nodes and its
/// edges (each as the one solid element that owns it runs, when it is a boundary edge), a surface
/// group's elements.
#include "io/import/assembly_importer.hpp"

#include <algorithm>

namespace saasgaps::io::assembly {

void Importer::sets(json& model) const {
  if (used_groups_.empty() || !mesh_loaded_ || !groups_) return;
  json nodes = json::object(), edges = json::object(), elements = json::object();
  for (const auto& [name, g] : used_groups_) {
    if (g->dim <= 1) {
      bool off_mesh = false;
      json ids = json::array();
      for (const int node : groups_->nodes(*g, off_mesh)) ids.push_back(tag_of(node));
      if (!ids.empty()) nodes[name] = std::move(ids);
    }
    if (g->dim == 1) {
      json list = json::array();
      for (auto [a, b] : groups_->edges(*g)) {
        if (a < 0 || b < 0) continue;
        const std::vector<int> owner = groups_->owners(a, b);
        if (owner.empty()) continue;
        if (owner.size() == 1) {  // counter-clockwise in its element, as a pressure runs
          const MeshFace& f = mesh_.faces[static_cast<std::size_t>(owner.front())];
          const auto k = static_cast<int>(std::find(f.nodes.begin(), f.nodes.begin() + f.count, a) - f.nodes.begin());
          if (f.nodes[static_cast<std::size_t>((k + 1) % f.count)] != b) std::swap(a, b);
        }
        list.push_back({tag_of(a), tag_of(b)});
      }
      if (!list.empty()) edges[name] = std::move(list);
    }
    if (g->dim == 2) {
      json ids = json::array();
      for (const MeshFace& f : mesh_.faces) {
        if (std::find(g->entities.begin(), g->entities.end(), f.surface) != g->entities.end() &&
            surface_material_.contains(f.surface)) {
          ids.push_back(static_cast<int>(f.tag));
        }
      }
      if (!ids.empty()) elements[name] = std::move(ids);
    }
  }
  json out = json::object();
  if (!nodes.empty()) out["nodes"] = std::move(nodes);
  if (!edges.empty()) out["edges"] = std::move(edges);
  if (!elements.empty()) out["elements"] = std::move(elements);
  if (!out.empty()) model["sets"] = std::move(out);
}

}  // namespace saasgaps::io::assembly
