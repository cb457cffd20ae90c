#include "io/sections/section_reader.hpp"

#include "io/json/value_quote.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/fe/element_geometry.hpp"
#include "solver/fe/element_kernel.hpp"
#include "solver/gaps/gap_faces.hpp"

namespace saasgaps::io {

bool SectionReader::is_new(const Registry& registry, int id, const Where& pointer, std::string_view what) {
  const Entry* found = registry.find(id);
  if (found == nullptr) return true;
  const Entry& first = *found;
  const std::string list = what == "node"       ? "/nodes"
                           : what == "material" ? "/materials"
                           : first.gap          ? "/gaps/elements"
                                                : "/elements";
  report(pointer, std::string(what) + " id " + std::to_string(id) + " is already used by " +
                      pointer_append(list, static_cast<std::size_t>(first.item)) +
                      "; ids must be unique");
  return false;
}

const Entry* SectionReader::resolve(const Registry& registry, bool complete, const json& value,
                             const Where& pointer, std::string_view what, std::string_view where) {
  const auto id = integer(value, pointer, what, 1);
  if (!id) return nullptr;
  if (const Entry* found = registry.find(*id)) return found;
  if (complete) {
    report(pointer, std::string(what) + " " + std::to_string(*id) + " is not defined: no entry of " +
                        std::string(where) + " has id " + std::to_string(*id));
  }
  return nullptr;
}

std::optional<int> SectionReader::new_element_id(const Obj& o) {
  const auto id = integer_field(o, "id", 1);
  if (!id || !is_new(elements_, *id, Where(o.pointer, "id"), "element")) return std::nullopt;
  return id;
}

std::optional<NodeList> SectionReader::read_node_list(const Obj& o, std::size_t min_count, std::size_t max_count,
                                               std::string_view expectation) {
  const json* ids = o.find("nodes");
  if (ids == nullptr) return std::nullopt;
  const std::string pointer = o.at("nodes");
  if (!ids->is_array()) {
    report(pointer, "nodes must be an array of node ids, got " + describe(*ids));
    return std::nullopt;
  }
  if (ids->size() < min_count || ids->size() > max_count) {
    report(pointer, "nodes " + quote(*ids) + " lists " + std::to_string(ids->size()) + " ids, but " +
                        std::string(expectation));
    return std::nullopt;
  }
  NodeList list;
  list.count = as_index(ids->size());
  for (std::size_t k = 0; k < ids->size(); ++k) {
    const Where item(pointer, k);
    const Entry* node = resolve_node((*ids)[k], item);
    if (node == nullptr) continue;
    const auto end = list.nodes.begin() + static_cast<std::ptrdiff_t>(k);
    if (std::find(list.nodes.begin(), end, node->index) != end) {
      report(item, "node " + quote((*ids)[k]) + " appears twice in " + quote(*ids) + "; the nodes must be distinct");
      continue;
    }
    list.nodes[k] = node->index;
  }
  return list;
}

std::optional<NodeList> SectionReader::read_corners(const Obj& o) {
  auto corners = read_node_list(o, 3, 4, "a gap element has 3 (triangle) or 4 (quadrilateral) nodes");
  if (!corners || !corners->complete()) return corners;
  const bool placed = std::all_of(corners->nodes.begin(), corners->nodes.begin() + corners->count,
                                  [&](int n) { return node_placed_[static_cast<std::size_t>(n)]; });
  if (placed) check_shape(*corners, *o.find("nodes"), Where(o.pointer, "nodes"));
  return corners;
}

void SectionReader::check_shape(const NodeList& corners, const json& ids, const Where& pointer) {
  const auto n = static_cast<std::size_t>(corners.count);
  // Eigen leaves default-constructed vectors uninitialised; the unused corner of a triangle too.
  std::array<Vec2, 4> x;
  x.fill(Vec2::Zero());
  std::array<Vec2, 4> reversed = x;
  for (std::size_t k = 0; k < n; ++k) {
    const Node& node = model_.nodes[static_cast<std::size_t>(corners.nodes[k])];
    x[k] = Vec2(node.r, node.z);
    reversed[n - 1 - k] = x[k];
  }
  const double smallest = min_twice_area(corners.count, x);
  if (smallest > 0.0) return;
  double twice_area = 0.0;  // shoelace formula
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = x[k];
    const Vec2& b = x[(k + 1) % n];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  const std::string area = "signed area " + format_number(0.5 * twice_area);
  // A shape that is fine the other way round is only listed clockwise: say how to list it.
  if (min_twice_area(corners.count, reversed) > 0.0) {
    json fixed = json::array();
    for (std::size_t k = n; k-- > 0;) fixed.push_back(ids[k]);
    report(pointer, "nodes " + quote(ids) + " are clockwise (" + area + "); list them counter-clockwise, e.g. " +
                        quote(fixed));
  } else if (corners.count == 3) {
    report(pointer, "nodes " + quote(ids) + " are collinear (" + area + "); a triangle needs a positive area");
  } else {
    report(pointer, "nodes " + quote(ids) + " do not form a convex, non-degenerate quadrilateral in this order (" +
                        area + ", smallest triangle around the centre node has twice area " +
                        format_number(smallest) +
                        "); the SAAS element needs all 4 triangles between its edges and the centre of its "
                        "corners to have positive area, counter-clockwise");
  }
}

bool SectionReader::gap_axis_judgeable(const NodeList& corners) const {
  if (!corners.complete()) return false;
  const auto placed = [&](int n) { return node_placed_[static_cast<std::size_t>(n)]; };
  if (!std::all_of(corners.nodes.begin(), corners.nodes.begin() + corners.count, placed)) return false;
  // A shape check_shape refused has no faces to judge.
  return min_twice_area(corners.count, corner_coordinates(model_, corners.nodes, corners.count)) > 0.0;
}

void SectionReader::check_gap_axes(std::span<const GapElement> gaps, std::span<const std::string> angle_pointers) {
  const std::vector<std::optional<std::string>> problems = gap_axis_problems(model_, gaps);
  for (std::size_t k = 0; k < problems.size(); ++k) {
    if (problems[k]) report(angle_pointers[k], *problems[k]);
  }
}

SectionReader::EdgeOwners SectionReader::solid_edge_owners() const {
  EdgeOwners owners;
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const Element& element = model_.elements[e];
    // An edge is named by its end corners; a quadratic edge's mid-side node goes with it.
    for (const EdgeNodes& edge : family(element.type).edges) {
      const int a = element.nodes[static_cast<std::size_t>(edge.first())];
      const int b = element.nodes[static_cast<std::size_t>(edge.last())];
      if (a >= 0 && b >= 0) owners[std::minmax(a, b)].push_back(as_index(e));
    }
  }
  return owners;
}

}  // namespace saasgaps::io
