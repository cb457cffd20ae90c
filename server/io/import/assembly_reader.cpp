#include "io/import/assembly_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "io/import/assembly_importer.hpp"
#include "io/import/gap_generator.hpp"
#include "io/import/mesh_groups.hpp"
#include "io/import/nodal_values_file.hpp"
#include "io/json/json_pointer.hpp"
#include "io/json/value_quote.hpp"
#include "io/json/value_rules.hpp"
#include "io/mesher/gmsh_mesh.hpp"
#include "solver/base/errors.hpp"
#include "solver/model/loads.hpp"

namespace saasgaps::io {

namespace assembly {

constexpr double default_pair_tolerance = 0.1;

// ---- sections

/// One face of a gap pair: a curve group ordered into a chain, with the outward normal of each edge
/// taken from the solid element that owns it.
std::optional<FaceChain> Importer::face(const json& name, const std::string& p) {
  const PhysicalGroup* g = named_group(name, p, {{1}, "a gap face", "a curve (dimension 1)"});
  if (g == nullptr) return std::nullopt;
  const auto edges = groups_->edges(*g);
  for (const auto& [a, b] : edges) {
    if (a < 0 || b < 0) {
      report(p, "curve group \"" + g->name + "\" has nodes no surface element uses; a gap face bounds a meshed surface");
      return std::nullopt;
    }
  }
  const ChainResult chain = order_chain(edges, ids_);
  if (!chain.problem.empty()) {
    report(p, "curve group \"" + g->name + "\" cannot be a gap face: " + chain.problem);
    return std::nullopt;
  }
  FaceChain out;
  out.nodes = chain.nodes;
  for (std::size_t k = 0; k + 1 < out.nodes.size(); ++k) {
    const int a = out.nodes[k], b = out.nodes[k + 1];
    const std::vector<int> owner = groups_->owners(a, b);
    if (owner.size() != 1) {
      report(p, "curve group \"" + g->name + "\" is not on the boundary of the meshed surfaces: its edge " +
                    std::to_string(tag_of(a)) + "-" + std::to_string(tag_of(b)) + " belongs to " +
                    std::to_string(owner.size()) + " elements (a gap face edge belongs to exactly one)");
      return std::nullopt;
    }
    const MeshFace& f = mesh_.faces[static_cast<std::size_t>(owner.front())];
    Vec2 centre = Vec2::Zero();
    for (int c = 0; c < f.count; ++c) centre += positions_[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(c)])];
    centre /= f.count;
    const Vec2 xa = positions_[static_cast<std::size_t>(a)], xb = positions_[static_cast<std::size_t>(b)];
    Vec2 n(xb.y() - xa.y(), xa.x() - xb.x());
    n.normalize();
    if ((centre - xa).dot(n) > 0.0) n = -n;  // point away from the element's centre: outward
    out.outward.push_back(n);
  }
  return out;
}

/// A face pair of the exact method as contact: each face becomes a contact surface named for its
/// curve group (its boundary edges as they are; the model reader judges the chain), the pair a contact
/// pair [A, B], A the first face (the mortar's non-mortar side, docs/contact-surfaces.md), with the
/// pair's friction and conductance as given (the model reader judges them at their pointers).
void Importer::contact_pair(const json& pair, const std::string& p, json& contact) {
  const json& faces = pair["faces"];
  const std::string a_at = pointer_append(p, std::size_t{0}), b_at = pointer_append(p, std::size_t{1});
  const auto a = contact_surface(faces[0], a_at, contact);
  const auto b = contact_surface(faces[1], b_at, contact);
  if (!a || !b) return;
  if (*a == *b) {
    report(b_at, "a face cannot be paired with itself (\"" + faces[1].get<std::string>() +
                     "\" is both faces); name the two curves that face each other");
    return;
  }
  const std::string pair_at = pointer_append("/contact/pairs", contact["pairs"].size());
  origins_.add(pair_at, p.substr(0, p.rfind('/')), true);
  json generated = {{"surfaces", {contact["surfaces"][*a]["name"], contact["surfaces"][*b]["name"]}}};
  for (const char* key : {"friction", "conductance"}) {
    if (pair.contains(key)) generated[key] = pair[key];
  }
  contact["pairs"].push_back(std::move(generated));
}

std::optional<std::size_t> Importer::contact_surface(const json& name, const std::string& p, json& contact) {
  const PhysicalGroup* g = named_group(name, p, {{1}, "a contact face", "a curve (dimension 1)"});
  if (g == nullptr) return std::nullopt;
  json& surfaces = contact["surfaces"];
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    if (surfaces[k]["name"] == g->name) return k;
  }
  json edges = json::array();
  std::set<std::pair<int, int>> seen;  // an edge two curve entities share is one edge
  for (const auto& [a, b] : groups_->edges(*g)) {
    if (a < 0 || b < 0) {
      report(p, "curve group \"" + g->name + "\" has nodes no surface element uses; a contact face bounds a meshed surface");
      return std::nullopt;
    }
    if (seen.insert(std::minmax(a, b)).second) edges.push_back({tag_of(a), tag_of(b)});
  }
  if (edges.empty()) {
    report(p, "curve group \"" + g->name + "\" has no line elements");
    return std::nullopt;
  }
  origins_.add(pointer_append("/contact/surfaces", surfaces.size()), p);
  surfaces.push_back({{"name", g->name}, {"edges", std::move(edges)}});
  return surfaces.size() - 1;
}

/// gaps: the settings pass through; pairs: [{faces: [curve, curve], first_id?, tolerance?}] become
/// gaps.elements, or with method "exact" contact surfaces and pairs (then no gap elements remain and
/// the gaps block, whose settings concern gap elements only, is left out of the model).
void Importer::gaps(json& model) {
  const auto it = doc_.find("gaps");
  if (it == doc_.end()) return;
  if (!it->is_object()) {
    report("/gaps", "expected an object, got " + describe(*it));
    return;
  }
  json settings = *it;
  settings.erase("pairs");
  if (settings.contains("elements")) {
    report("/gaps/elements", "gap elements are generated from /gaps/pairs; remove elements");
  }
  if (!it->contains("pairs")) report("/gaps", "missing required key \"pairs\" (the faces that face each other)");
  const json* list = array(*it, "/gaps", "pairs", true);
  settings["elements"] = json::array();
  if (list == nullptr || !mesh_loaded_) {
    model["gaps"] = std::move(settings);
    return;
  }
  if (settings.value("method", json()) == "exact") {
    json contact = {{"surfaces", json::array()}, {"pairs", json::array()}};
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string p = pointer_append("/gaps/pairs", i);
      const json& o = (*list)[i];
      if (!object(o, p, {"faces"}, {"first_id", "tolerance", "friction", "conductance"})) continue;
      for (const char* key : {"first_id", "tolerance"}) {
        if (o.contains(key)) {
          report(pointer_append(p, key), std::string(key) + " concerns generated gap elements, and with gaps.method "
                 "\"exact\" a face pair becomes contact surfaces instead (docs/import.md); remove it");
        }
      }
      const auto faces = o.find("faces");
      if (faces == o.end()) continue;
      if (!faces->is_array() || faces->size() != 2) {
        report(pointer_append(p, "faces"), "faces must name two curve groups, got " + describe(*faces));
        continue;
      }
      contact_pair(o, pointer_append(p, "faces"), contact);
    }
    if (!contact["pairs"].empty()) model["contact"] = std::move(contact);
    return;
  }
  std::set<long long> used;  // element ids taken
  long long next_id = 1;
  for (const MeshFace& f : mesh_.faces) {
    used.insert(static_cast<long long>(f.tag));
    next_id = std::max(next_id, static_cast<long long>(f.tag) + 1);
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string p = pointer_append("/gaps/pairs", i);
    const json& o = (*list)[i];
    if (!object(o, p, {"faces"}, {"first_id", "tolerance", "friction", "conductance"})) continue;
    for (const char* key : {"friction", "conductance"}) {
      if (o.contains(key)) {
        report(pointer_append(p, key), std::string(key) + " belongs to a contact pair, which a face pair becomes with "
               "gaps.method \"exact\" (docs/import.md); gap elements conduct by gaps.conductance and have no friction");
      }
    }
    const double tolerance = number(o, p, "tolerance", positive).value_or(default_pair_tolerance);
    long long id = next_id;
    if (const auto first = o.find("first_id"); first != o.end()) {
      if (!first->is_number_integer() || first->get<long long>() < 1) {
        report(pointer_append(p, "first_id"), "first_id must be a positive integer, got " + describe(*first));
        continue;
      }
      id = first->get<long long>();
    }
    const auto faces = o.find("faces");
    if (faces == o.end()) continue;
    if (!faces->is_array() || faces->size() != 2) {
      report(pointer_append(p, "faces"), "faces must name two curve groups, got " + describe(*faces));
      continue;
    }
    const auto a = face((*faces)[0], pointer_append(pointer_append(p, "faces"), std::size_t{0}));
    const auto b = face((*faces)[1], pointer_append(pointer_append(p, "faces"), std::size_t{1}));
    if (!a || !b) continue;
    const GapGeneration generated = generate_gaps(*a, *b, positions_, ids_, tolerance);
    const std::string between = "between \"" + (*faces)[0].get<std::string>() + "\" and \"" +
                                (*faces)[1].get<std::string>() + "\": ";
    for (const std::string& problem : generated.problems) report(p, between + problem);
    for (const GeneratedGap& g : generated.gaps) {
      if (id > std::numeric_limits<int>::max() || !used.insert(id).second) {
        report(o.contains("first_id") ? pointer_append(p, "first_id") : p,
               "gap element id " + std::to_string(id) + " is already used by an element or an earlier pair; choose "
               "first_id so the " + std::to_string(generated.gaps.size()) + " ids of this pair are free");
        break;
      }
      json nodes = json::array();
      for (const int n : g.nodes) nodes.push_back(tag_of(n));
      settings["elements"].push_back({{"id", id}, {"nodes", std::move(nodes)}, {"angle", g.angle_deg}});
      ++id;
    }
    next_id = std::max(next_id, id);
  }
  model["gaps"] = std::move(settings);
}

json Importer::run() {
  if (!object(doc_, "", {"schema_version", "title", "mesh", "analysis", "materials", "regions", "constraints"},
              {"description", "units", "loads", "gaps", "thermal", "solver", "output"})) {
    throw ModelError(std::move(issues_), "assembly");
  }
  if (const auto v = doc_.find("schema_version"); v != doc_.end()) {
    check_schema_version(*v, std::string("/schema_version"), reporter());
  }
  json model = json::object();
  model["schema_version"] = 1;
  for (const char* key : {"title", "description", "units", "analysis", "materials"}) {
    if (const auto v = doc_.find(key); v != doc_.end()) model[key] = *v;
  }
  read_material_ids();
  load_mesh();
  nodes(model);
  regions(model);
  gaps(model);
  constraints(model);
  loads(model);
  thermal(model);
  for (const char* key : {"solver", "output"}) {
    if (const auto v = doc_.find(key); v != doc_.end()) model[key] = *v;
  }
  // The model reader judges the result only when the assembly's own checks found nothing: a model
  // generated from a faulty assembly lacks what could not be generated, and its findings would be
  // about that.
  if (issues_.empty()) {
    for (InputIssue& finding : origins_.findings(model)) report(std::move(finding.pointer), std::move(finding.detail));
  }
  if (!issues_.empty()) throw ModelError(std::move(issues_), "assembly");
  return model;
}

}  // namespace assembly

nlohmann::json import_assembly(const nlohmann::json& assembly, const std::filesystem::path& base_directory,
                               FileAccess access) {
  return assembly::Importer(assembly, base_directory, access).run();
}

}  // namespace saasgaps::io
