#include "io/import/mesh_groups.hpp"

#include <algorithm>
#include <set>
#include <tuple>

namespace saasgaps::io {

namespace {

/// Edit distance (Levenshtein), for "did you mean" on a misspelt group name.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

MeshGroups::MeshGroups(const GmshMesh& mesh) : mesh_(mesh) {
  // A sorted array, not a map of 4 x 10^6 entries: one allocation, searched in log time.
  owners_.reserve(4 * mesh.faces.size());
  for (std::size_t e = 0; e < mesh.faces.size(); ++e) {
    const MeshFace& f = mesh.faces[e];
    const int corners = f.corners();  // an edge by its end corners; a mid-side node goes with it
    for (int k = 0; k < corners; ++k) {
      const auto [lo, hi] =
          std::minmax(f.nodes[static_cast<std::size_t>(k)], f.nodes[static_cast<std::size_t>((k + 1) % corners)]);
      owners_.push_back({lo, hi, static_cast<int>(e)});
    }
  }
  std::sort(owners_.begin(), owners_.end(),
            [](const EdgeOwner& x, const EdgeOwner& y) { return std::tie(x.lo, x.hi, x.element) < std::tie(y.lo, y.hi, y.element); });
}

const PhysicalGroup* MeshGroups::find(const std::string& name, std::initializer_list<int> dims, std::string_view role,
                                      std::string_view needs, std::string& problem) const {
  const PhysicalGroup* wrong_dim = nullptr;
  for (const PhysicalGroup& g : mesh_.groups) {
    if (g.name != name) continue;
    if (std::find(dims.begin(), dims.end(), g.dim) != dims.end()) return &g;
    wrong_dim = &g;
  }
  if (wrong_dim != nullptr) {
    problem = "physical group \"" + name + "\" has " + dimension_name(wrong_dim->dim) + "; " + std::string(role) +
              " needs " + std::string(needs);
    return nullptr;
  }
  problem = "the mesh has no physical group named \"" + name + "\"";
  std::string closest;
  std::size_t best = 3;  // suggest names within two edits
  std::string names;
  for (const PhysicalGroup& g : mesh_.groups) {
    if (g.name.empty()) continue;
    names += (names.empty() ? "" : ", ") + ("\"" + g.name + "\" (" + dimension_name(g.dim) + ")");
    const std::size_t d = edit_distance(name, g.name);
    if (d < best) {
      best = d;
      closest = g.name;
    }
  }
  if (!closest.empty()) problem += "; did you mean \"" + closest + "\"?";
  problem += names.empty() ? " (it names no physical groups at all)" : " (its named groups: " + names + ")";
  return nullptr;
}

std::vector<int> MeshGroups::nodes(const PhysicalGroup& g, bool& off_mesh) const {
  std::vector<int> nodes;
  if (g.dim == 2) {
    const std::set<int> surfaces(g.entities.begin(), g.entities.end());
    for (const MeshFace& f : mesh_.faces) {
      if (surfaces.contains(f.surface)) nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.begin() + f.count);
    }
  } else if (g.dim == 1) {
    // Every node of its line elements: a 3-node line's mid-side node too.
    for (const int curve : g.entities) {
      const auto it = mesh_.curves.find(curve);
      if (it == mesh_.curves.end()) continue;
      for (const MeshEdge& e : it->second) {
        nodes.push_back(e.a);
        nodes.push_back(e.b);
        if (e.m >= 0) nodes.push_back(e.m);
      }
    }
  } else {
    for (const int point : g.entities) {
      const auto it = mesh_.points.find(point);
      nodes.push_back(it == mesh_.points.end() ? -1 : it->second);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  off_mesh = !nodes.empty() && nodes.front() < 0;
  if (off_mesh) nodes.erase(nodes.begin());  // unique: at most one -1
  return nodes;
}

std::vector<std::array<int, 2>> MeshGroups::edges(const PhysicalGroup& g) const {
  std::vector<std::array<int, 2>> edges;
  for (const int curve : g.entities) {
    const auto it = mesh_.curves.find(curve);
    if (it == mesh_.curves.end()) continue;
    for (const MeshEdge& e : it->second) edges.push_back({e.a, e.b});
  }
  return edges;
}

std::vector<int> MeshGroups::owners(int a, int b) const {
  const auto [lo, hi] = std::minmax(a, b);
  const auto [first, last] = std::equal_range(owners_.begin(), owners_.end(), EdgeOwner{lo, hi, 0},
                                              [](const EdgeOwner& x, const EdgeOwner& y) {
                                                return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
                                              });
  std::vector<int> elements;
  for (auto it = first; it != last; ++it) elements.push_back(it->element);
  return elements;
}

}  // namespace saasgaps::io
