/// The face pairs of gaps.method "exact" (docs/import.md) as the model's `contact`: each face a
/// contact surface made of its curve group's line elements, each pair a contact pair of two of them
/// (docs/contact-surfaces.md).
#include "io/import/assembly_importer.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include "io/json/json_pointer.hpp"

namespace saasgaps::io::assembly {

/// Why an exact face pair takes no first_id or tolerance, said after the key.
constexpr std::string_view for_gap_elements_only =
    " concerns generated gap elements, and with gaps.method \"exact\" a face pair becomes contact surfaces instead "
    "(docs/import.md); remove it";

void Importer::contact_pairs(const json& pairs, json& model) {
  json contact = {{"surfaces", json::array()}, {"pairs", json::array()}};
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::string p = pointer_append("/gaps/pairs", i);
    const json& o = pairs[i];
    if (!pair_keys(o, p, {"first_id", "tolerance"}, for_gap_elements_only)) continue;
    if (pair_faces(o, p) == nullptr) continue;
    contact_pair(o, pointer_append(p, "faces"), contact);
  }
  if (!contact["pairs"].empty()) model["contact"] = std::move(contact);
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

}  // namespace saasgaps::io::assembly
