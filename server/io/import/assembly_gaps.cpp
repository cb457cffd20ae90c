/// The assembly's `gaps` section (docs/import.md): its settings pass through, and its face pairs
/// [{faces: [curve, curve], first_id?, tolerance?}] become the model's gaps.elements, generated
/// between the two faces (gap_generator.hpp), or with method "exact" contact surfaces and pairs
/// (assembly_contact.cpp). What both methods ask of a face pair's shape is here too.
#include "io/import/assembly_importer.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/import/gap_generator.hpp"
#include "io/json/json_pointer.hpp"
#include "io/json/value_quote.hpp"
#include "io/json/value_rules.hpp"

namespace saasgaps::io::assembly {

constexpr double default_pair_tolerance = 0.1;
/// Why a face pair that becomes gap elements takes no friction or conductance, said after the key.
constexpr std::string_view for_contact_pairs_only =
    " belongs to a contact pair, which a face pair becomes with gaps.method \"exact\" (docs/import.md); gap "
    "elements conduct by gaps.conductance and have no friction";

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
    // No gap elements remain, and the gaps block's settings concern gap elements only: it is left out.
    contact_pairs(*list, model);
    return;
  }
  gap_elements(*list, settings["elements"]);
  model["gaps"] = std::move(settings);
}

bool Importer::pair_keys(const json& o, const std::string& p, std::initializer_list<const char*> foreign,
                         std::string_view why) {
  if (!object(o, p, {"faces"}, {"first_id", "tolerance", "friction", "conductance"})) return false;
  for (const char* key : foreign) {
    if (o.contains(key)) report(pointer_append(p, key), std::string(key) + std::string(why));
  }
  return true;
}

const json* Importer::pair_faces(const json& o, const std::string& p) {
  const auto faces = o.find("faces");
  if (faces == o.end()) return nullptr;
  if (!faces->is_array() || faces->size() != 2) {
    report(pointer_append(p, "faces"), "faces must name two curve groups, got " + describe(*faces));
    return nullptr;
  }
  return &*faces;
}

/// Each pair's elements take the ids from its first_id up, or else from the one after the largest
/// id taken; an id may not repeat an element's or an earlier pair's.
void Importer::gap_elements(const json& pairs, json& elements) {
  std::set<long long> used;  // element ids taken
  long long next_id = 1;
  for (const MeshFace& f : mesh_.faces) {
    used.insert(static_cast<long long>(f.tag));
    next_id = std::max(next_id, static_cast<long long>(f.tag) + 1);
  }
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::string p = pointer_append("/gaps/pairs", i);
    const json& o = pairs[i];
    if (!pair_keys(o, p, {"friction", "conductance"}, for_contact_pairs_only)) continue;
    const double tolerance = number(o, p, "tolerance", positive).value_or(default_pair_tolerance);
    long long id = next_id;
    if (const auto first = o.find("first_id"); first != o.end()) {
      if (!first->is_number_integer() || first->get<long long>() < 1) {
        report(pointer_append(p, "first_id"), "first_id must be a positive integer, got " + describe(*first));
        continue;
      }
      id = first->get<long long>();
    }
    const json* faces = pair_faces(o, p);
    if (faces == nullptr) continue;
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
      // The model reader's findings on it (a gap along a quadratic element's edge) are the pair's.
      origins_.add(pointer_append("/gaps/elements", elements.size()), p);
      elements.push_back({{"id", id}, {"nodes", std::move(nodes)}, {"angle", g.angle_deg}});
      ++id;
    }
    next_id = std::max(next_id, id);
  }
}

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

}  // namespace saasgaps::io::assembly
