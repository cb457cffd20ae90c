/// The assembly's mesh (a Gmsh file read by the sandboxed mesher, io/mesher/gmsh_mesh.hpp), the
/// model's nodes from it, and its physical groups as the sections name them: found by name and
/// dimension, their nodes, and a curve group's line elements as edges of the solid elements that
/// own them.
#include "io/import/assembly_importer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/json/json_pointer.hpp"
#include "io/json/value_quote.hpp"
#include "io/mesher/geo_constants.hpp"
#include "io/mesher/gmsh_mesh.hpp"

namespace saasgaps::io::assembly {

void Importer::load_mesh() {
  const auto name = string(doc_, "", "mesh");
  if (!name) return;
  const auto path = resolve_file(*name, "/mesh");
  // order: the element order a .geo is meshed with (1 or 2; absent: the .geo's own). A .msh file
  // was meshed already: its elements keep the order they were written with.
  static constexpr Range order_range{Bound{1.0, true}, Bound{2.0, true}, "the element order is 1 or 2"};
  const std::optional<double> order = number(doc_, "", "order", order_range);
  if (order && *order != std::floor(*order)) report("/order", "order is 1 or 2, got " + format_number(*order));
  if (order && path && path->extension() == ".msh") {
    report("/order", "order applies to a .geo file, which the import meshes; " + *name +
                         " is a mesh already, with the order it was written with (Mesh.ElementOrder in Gmsh)");
  }
  if (!path) return;
  const std::optional<MeshParameters> parameters = mesh_parameters(*path);
  if (!parameters) return;
  try {
    const auto start = std::chrono::steady_clock::now();
    mesh_ = read_gmsh_mesh(*path, order ? static_cast<int>(*order) : 0, sizes_, *parameters);
    mesh_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } catch (const MeshTooLarge&) {
    throw;  // a limit, not a defect of the assembly: the service answers 413
  } catch (const MeshError& e) {
    report("/mesh", e.what());
    return;
  }
  for (const MeshFace& f : mesh_.faces) {
    if (f.tag > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      report("/mesh", "element tag " + std::to_string(f.tag) + " is beyond the largest element id (2147483647)");
      return;
    }
  }
  mesh_loaded_ = true;
  groups_.emplace(mesh_);
  positions_.reserve(mesh_.r.size());
  for (std::size_t i = 0; i < mesh_.r.size(); ++i) {
    positions_.emplace_back(mesh_.r[i], mesh_.z[i]);
    ids_.push_back(static_cast<int>(mesh_.node_tags[i]));
  }
}

std::optional<MeshParameters> Importer::mesh_parameters(const fs::path& path) {
  MeshParameters out;
  const auto given = doc_.find("mesh_parameters");
  if (given == doc_.end()) return out;
  if (!given->is_object()) {
    report("/mesh_parameters", "mesh_parameters is an object {NAME: number}, got " + describe(*given));
    return std::nullopt;
  }
  if (path.extension() != ".geo") {
    report("/mesh_parameters", "mesh_parameters set the DefineConstant values of a Gmsh geometry (.geo), but the "
                               "mesh " + quote_string(path.filename().string()) + " is meshed already: it has none");
    return std::nullopt;
  }
  // The geometry's declared parameters, from its text (read, not run: io/mesher/geo_constants.hpp).
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::vector<std::string> declared = geo_constants(text);
  std::string known;
  for (const std::string& name : declared) known += (known.empty() ? "" : ", ") + name;
  bool ok = true;
  for (const auto& [name, value] : given->items()) {
    const std::string at = pointer_append("/mesh_parameters", name);
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      report(at, "a mesh parameter is a finite number, got " + describe(value));
      ok = false;
    } else if (std::find(declared.begin(), declared.end(), name) == declared.end()) {
      report(at, "the geometry " + quote_string(path.filename().string()) + " declares no parameter " +
                     quote_string(name) + " (a name it defines with DefineConstant[" + name + " = ...];) " +
                     (known.empty() ? std::string("and declares none") : "; it declares " + known));
      ok = false;
    } else {
      out[name] = value.get<double>();
    }
  }
  if (!ok) return std::nullopt;
  return out;
}

void Importer::adapt_mesh(const AdaptSettings& adapt) {
  const auto name = doc_.find("mesh");
  if (name == doc_.end() || !name->is_string()) return;  // reported by load_mesh()
  const std::string mesh = name->get<std::string>();
  if (fs::path(mesh).extension() != ".geo") {
    report("/adapt", "adapt re-meshes the geometry, but the mesh " + quote_string(mesh) +
                         " is not a Gmsh geometry (.geo): a .msh mesh has nothing to re-mesh; name the .geo it "
                         "was meshed from, or remove adapt");
    return;
  }
  // The first mesh only: a re-mesh may overshoot the node count its sizes aimed at, and the loop
  // stops at the limit with the error reached (adaptive_loop.cpp), not with this error.
  if (mesh_loaded_ && sizes_ == nullptr && mesh_.r.size() > adapt.max_nodes) {
    report("/adapt/max_nodes", "max_nodes = " + std::to_string(adapt.max_nodes) + " is fewer than the first mesh's " +
                                   std::to_string(mesh_.r.size()) + " nodes: nothing could be refined; raise it or "
                                   "coarsen the geometry's sizes");
  }
}

void Importer::nodes(json& model) const {
  if (!mesh_loaded_) return;
  // On the axis of an axisymmetric section Gmsh may place a node a round-off left of r = 0.
  const auto analysis = doc_.find("analysis");
  const bool axisymmetric = analysis != doc_.end() && analysis->is_object() &&
                            analysis->value("type", json()) == "axisymmetric";
  const double scale = extent();
  json& out = model["nodes"] = json::array();
  for (std::size_t n = 0; n < positions_.size(); ++n) {
    double r = positions_[n].x();
    if (axisymmetric && r < 0.0 && r > -1e-12 * scale) r = 0.0;
    out.push_back({{"id", ids_[n]}, {"r", r}, {"z", positions_[n].y()}});
  }
}

double Importer::extent() const {
  double out = 0.0;
  for (const Vec2& x : positions_) out = std::max({out, std::fabs(x.x()), std::fabs(x.y())});
  return out;
}

const PhysicalGroup* Importer::group(const json& o, const std::string& p, const GroupUse& use) {
  const auto it = o.find("group");
  if (it == o.end()) return nullptr;  // reported by object()
  return named_group(*it, pointer_append(p, "group"), use);
}

const PhysicalGroup* Importer::named_group(const json& value, const std::string& at, const GroupUse& use) {
  if (!value.is_string()) {
    report(at, "a physical group name must be a string, got " + describe(value));
    return nullptr;
  }
  if (!groups_) return nullptr;
  std::string problem;
  const PhysicalGroup* g = groups_->find(value.get<std::string>(), use.dims, use.role, use.needs, problem);
  if (g == nullptr) report(at, problem);
  if (g != nullptr && !g->name.empty()) used_groups_.emplace(g->name, g);
  return g;
}

std::vector<int> Importer::group_nodes(const PhysicalGroup& g, const std::string& p) {
  bool off_mesh = false;
  std::vector<int> nodes = groups_->nodes(g, off_mesh);
  if (off_mesh) {
    report(pointer_append(p, "group"), "physical group \"" + g.name + "\" has nodes (or unmeshed points) that no "
                                       "surface element uses; it must lie on the meshed surfaces");
  } else if (nodes.empty()) {
    report(pointer_append(p, "group"), "physical group \"" + g.name + "\" holds no mesh nodes");
  }
  return nodes;
}

std::optional<std::vector<Importer::BoundaryEdge>> Importer::boundary_edges(const PhysicalGroup& g, const std::string& p,
                                                                            std::string_view use) {
  const auto edges = groups_->edges(g);
  if (edges.empty()) {
    report(pointer_append(p, "group"), "physical group \"" + g.name + "\" has no line elements");
    return std::nullopt;
  }
  std::vector<BoundaryEdge> out;
  for (const auto& [a, b] : edges) {
    const std::vector<int> owner = a < 0 || b < 0 ? std::vector<int>{} : groups_->owners(a, b);
    if (owner.size() != 1) {
      report(pointer_append(p, "group"),
             "curve group \"" + g.name + "\" is not on the boundary of the meshed surfaces" +
                 (a >= 0 && b >= 0 ? " (edge " + std::to_string(tag_of(a)) + "-" + std::to_string(tag_of(b)) + " has " +
                                         std::to_string(owner.size()) + " elements; " + std::string(use) +
                                         " acts on an edge of exactly one)"
                                   : std::string()));
      return std::nullopt;
    }
    const MeshFace& f = mesh_.faces[static_cast<std::size_t>(owner.front())];
    const int corners = f.corners();
    const auto k = static_cast<int>(std::find(f.nodes.begin(), f.nodes.begin() + corners, a) - f.nodes.begin());
    const bool along = f.nodes[static_cast<std::size_t>((k + 1) % corners)] == b;
    out.push_back(along ? BoundaryEdge{a, b, owner.front()} : BoundaryEdge{b, a, owner.front()});
  }
  return out;
}

}  // namespace saasgaps::io::assembly
