#include "plot/result/result_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <optional>
#include <unordered_map>

#include "solver/fe/element_family.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

GapState gap_state(const std::string& name) {
  if (const auto state = gap_state_names.value(name)) return *state;
  throw std::invalid_argument("unknown gap state '" + name + "'");
}

int node_id(const json& n) { return n.get<int>(); }
int node_id(int n) { return n; }

/// Node ids (a JSON array of them, or ints) as indices into the result's nodes.
int node_index(int node, const std::unordered_map<int, int>& index, const char* what, int id) {
  const auto found = index.find(node);
  if (found == index.end()) {
    throw std::invalid_argument(std::string(what) + " " + std::to_string(id) + " refers to node " +
                                std::to_string(node) + ", which is not in the result's nodes");
  }
  return found->second;
}

template <class Ids>
std::vector<int> node_indices(const Ids& ids, const std::unordered_map<int, int>& index, const char* what, int id,
                              std::size_t outline = 0) {
  std::vector<int> nodes;
  for (const auto& n : ids) nodes.push_back(node_index(node_id(n), index, what, id));
  if (nodes.size() != outline && nodes.size() != 3 && nodes.size() != 4) {
    throw std::invalid_argument(std::string(what) + " " + std::to_string(id) + " has " +
                                std::to_string(nodes.size()) + " nodes; 3 or 4 expected");
  }
  return nodes;
}

/// A solid element with its node indices as its outline: counter-clockwise around the boundary, each
/// edge's mid-side node between its corners; a quad9's centre node is kept apart.
template <class Ids>
SolidElement solid_element(const Ids& ids, const std::unordered_map<int, int>& index, int id, int material) {
  std::vector<int> nodes;
  for (const auto& n : ids) nodes.push_back(node_id(n));
  const std::optional<ElementType> type = default_element_type(static_cast<int>(nodes.size()));
  if (!type) {
    throw std::invalid_argument("element " + std::to_string(id) + " has " + std::to_string(nodes.size()) +
                                " nodes; 3, 4, 6, 8 or 9 expected");
  }
  std::vector<int> outline;
  for (const EdgeNodes& edge : family(*type).edges) {
    for (int k = 0; k + 1 < edge.count; ++k) outline.push_back(nodes[static_cast<std::size_t>(edge.node[static_cast<std::size_t>(k)])]);
  }
  SolidElement element{id, material, node_indices(outline, index, "element", id, outline.size())};
  if (*type == ElementType::quad9) element.centre = node_index(nodes[8], index, "element", id);
  return element;
}

}  // namespace

const json& array_member(const json& document, const char* key) {
  static const json empty = json::array();
  const auto found = document.find(key);
  return found != document.end() && found->is_array() ? *found : empty;
}

namespace {

/// The members of a result every mesh reader starts from: a failed run has no mesh.
ResultMesh mesh_header(const json& result) {
  if (!result.is_object()) throw std::invalid_argument("the result document is not a JSON object");
  const std::string status = result.value("status", "");
  if (status == "failed") {
    throw std::invalid_argument("the run failed, so the result has no mesh to plot: " + result.value("message", ""));
  }
  ResultMesh mesh;
  mesh.title = result.value("title", "");
  mesh.analysis = result.value("analysis", "plane_stress");
  mesh.status = status;
  mesh.iterations = result.value("iterations", 0);
  if (const auto units = result.find("units"); units != result.end() && units->is_object()) {
    mesh.units = {units->value("length", ""), units->value("force", ""), units->value("stress", ""),
                  units->value("temperature", "")};
  }
  return mesh;
}

constexpr const char* no_coordinates =
    "the result document has no node coordinates (nodes[].r, .z): it predates self-contained results; solve the "
    "model again";

void read_gaps(const json& result, const std::unordered_map<int, int>& index, ResultMesh& mesh) {
  for (const json& g : array_member(result, "gaps")) {
    const int id = g.at("id").get<int>();
    const double sigma_m = g.value("sigma_m", 0.0);
    mesh.gaps.push_back({id, node_indices(g.at("nodes"), index, "gap element", id), g.value("angle", 0.0),
                         g.at("closure").get<double>(), sigma_m, g.value("contact_pressure", std::max(0.0, -sigma_m)),
                         gap_state(g.at("state").get<std::string>()), g.value("converged", true)});
  }
}

}  // namespace

ResultMesh ResultMesh::from_result(const json& result) {
  try {
    ResultMesh mesh = mesh_header(result);
    if (!result.contains("nodes") || result.at("nodes").empty() || !result.at("nodes").at(0).contains("r")) {
      throw std::invalid_argument(no_coordinates);
    }
    std::unordered_map<int, int> index;
    for (const json& n : result.at("nodes")) {
      MeshNode node{n.at("id").get<int>(), n.at("r").get<double>(), n.at("z").get<double>(),
                    n.value("T", 0.0),     n.at("u_r").get<double>(), n.at("u_z").get<double>()};
      constexpr std::array<const char*, 4> components{"sigma_r", "sigma_z", "tau_rz", "sigma_theta"};
      for (std::size_t k = 0; k < components.size(); ++k) {
        if (const auto v = n.find(components[k]); v != n.end() && v->is_number()) node.stress[k] = v->get<double>();
      }
      index.emplace(node.id, static_cast<int>(mesh.nodes.size()));
      mesh.nodes.push_back(node);
    }
    for (const json& e : result.at("elements")) {
      const int id = e.at("id").get<int>();
      mesh.solids.push_back(solid_element(e.at("nodes"), index, id, e.value("material", 0)));
    }
    read_gaps(result, index, mesh);
    return mesh;
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("malformed result document: ") + e.what());
  }
}

ResultMesh ResultMesh::from_arrays(const io::ResultArrays& result) {
  try {
    ResultMesh mesh = mesh_header(result.document);
    if (result.mesh_error) throw std::invalid_argument(*result.mesh_error);
    if (!result.nodes) {
      if (result.document.contains("nodes")) throw std::invalid_argument("malformed result document: /nodes is not an array");
      throw std::invalid_argument(no_coordinates);
    }
    const io::ResultNodes& nodes = *result.nodes;
    if (nodes.id.empty()) throw std::invalid_argument(no_coordinates);
    std::unordered_map<int, int> index;
    mesh.nodes.reserve(nodes.id.size());
    for (std::size_t n = 0; n < nodes.id.size(); ++n) {
      index.emplace(nodes.id[n], static_cast<int>(n));
      mesh.nodes.push_back({nodes.id[n], nodes.r[n], nodes.z[n], nodes.T[n], nodes.u_r[n], nodes.u_z[n],
                            {nodes.stress[0][n], nodes.stress[1][n], nodes.stress[2][n], nodes.stress[3][n]}});
    }
    if (!result.elements) throw std::invalid_argument("malformed result document: /elements is missing or not an array");
    const io::ResultElements& elements = *result.elements;
    mesh.solids.reserve(elements.size());
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const auto first = elements.node_ids.begin() + static_cast<std::ptrdiff_t>(elements.first_node[e]);
      const auto last = elements.node_ids.begin() + static_cast<std::ptrdiff_t>(elements.first_node[e + 1]);
      mesh.solids.push_back(solid_element(std::vector<int>(first, last), index, elements.id[e], elements.material[e]));
    }
    read_gaps(result.document, index, mesh);
    return mesh;
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("malformed result document: ") + e.what());
  }
}

double ResultMesh::area(const SolidElement& e) const {
  double twice = 0.0;
  for (std::size_t a = 0; a < e.nodes.size(); ++a) {
    const MeshNode& p = nodes[e.nodes[a]];
    const MeshNode& q = nodes[e.nodes[(a + 1) % e.nodes.size()]];
    twice += p.r * q.z - q.r * p.z;
  }
  return std::abs(twice) / 2.0;
}

std::array<double, 2> ResultMesh::position(int node, double scale) const {
  const MeshNode& n = nodes[node];
  return {n.r + scale * n.u_r, n.z + scale * n.u_z};
}

}  // namespace saasgaps::plot
