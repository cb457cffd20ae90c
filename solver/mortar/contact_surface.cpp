#include "solver/mortar/contact_surface.hpp"

#include <cassert>
#include <cstdint>
#include <unordered_map>

#include "solver/fe/element_family.hpp"

namespace saasgaps {

namespace {

std::string summarise(const std::vector<SurfaceEdgeIssue>& issues) {
  std::string text = "invalid contact surface";
  if (issues.empty()) return text;
  text += ": edge " + std::to_string(issues.front().edge) + ": " + issues.front().detail;
  if (issues.size() > 1) text += " (and " + std::to_string(issues.size() - 1) + " more)";
  return text;
}

std::uint64_t side_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32U) | hi;
}

/// Twice the signed area of an element's corner polygon (shoelace): > 0 when counter-clockwise.
double twice_polygon_area(const Model& model, const Element& e) {
  const int corners = family(e.type).corner_count;
  double sum = 0.0;
  for (int k = 0; k < corners; ++k) {
    const Vec2 a = node_position(model.nodes, e.nodes[static_cast<std::size_t>(k)]);
    const Vec2 b = node_position(model.nodes, e.nodes[static_cast<std::size_t>((k + 1) % corners)]);
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

/// The solid elements having side {a, b}, each with that side directed material-on-the-left.
struct SideOwner {
  int element = -1;
  int from = -1;  ///< the side runs from -> to with the element on its left
  int to = -1;
  int middle = -1;  ///< the mid-side node of a 3-node side, -1 for a straight one
};

std::string node_name(const Model& model, int i) {
  return "node " + std::to_string(model.nodes[static_cast<std::size_t>(i)].id);
}

std::string edge_name(const Model& model, const std::array<int, 2>& e) {
  return "[" + std::to_string(model.nodes[static_cast<std::size_t>(e[0])].id) + ", " +
         std::to_string(model.nodes[static_cast<std::size_t>(e[1])].id) + "]";
}

}  // namespace

const char* describe(SurfaceEdgeProblem problem) {
  switch (problem) {
    case SurfaceEdgeProblem::empty: return "the surface has no edges";
    case SurfaceEdgeProblem::degenerate: return "both ends are the same node";
    case SurfaceEdgeProblem::not_a_side: return "not a side of any solid element";
    case SurfaceEdgeProblem::interior: return "not a boundary edge: a side of two solid elements";
    case SurfaceEdgeProblem::repeated: return "the same edge as an earlier one";
    case SurfaceEdgeProblem::branch: return "a third edge at one node: the edges are not a chain";
    case SurfaceEdgeProblem::opposite_side: return "its element is on the other side of the chain";
    case SurfaceEdgeProblem::disconnected: return "not connected to the chain of the first edge";
  }
  return "invalid edge";
}

ContactSurfaceError::ContactSurfaceError(std::vector<SurfaceEdgeIssue> issues)
    : SolverError(summarise(issues)), issues_(std::move(issues)) {}

ContactSurface contact_surface(const Model& model, std::span<const std::array<int, 2>> edges) {
  if (edges.empty()) {
    throw ContactSurfaceError({{0, SurfaceEdgeProblem::empty, describe(SurfaceEdgeProblem::empty)}});
  }
  for (const auto& e : edges) {
    assert(e[0] >= 0 && e[1] >= 0 && static_cast<std::size_t>(e[0]) < model.nodes.size() &&
           static_cast<std::size_t>(e[1]) < model.nodes.size());
    (void)e;
  }

  // Owners of the listed sides only: one pass over the elements.
  std::unordered_map<std::uint64_t, std::vector<SideOwner>> owners;
  for (const auto& e : edges) owners.try_emplace(side_key(e[0], e[1]));
  for (std::size_t i = 0; i < model.elements.size(); ++i) {
    const Element& el = model.elements[i];
    const bool ccw = twice_polygon_area(model, el) > 0.0;
    for (const EdgeNodes& side : family(el.type).edges) {
      const int a = el.nodes[static_cast<std::size_t>(side.first())];
      const int b = el.nodes[static_cast<std::size_t>(side.last())];
      if (a == b) continue;  // a quad with a repeated node is a triangle
      const auto it = owners.find(side_key(a, b));
      if (it == owners.end()) continue;
      const int middle = side.count == 3 ? el.nodes[static_cast<std::size_t>(side.node[1])] : -1;
      it->second.push_back(ccw ? SideOwner{static_cast<int>(i), a, b, middle}
                               : SideOwner{static_cast<int>(i), b, a, middle});
    }
  }

  std::vector<SurfaceEdgeIssue> issues;
  std::vector<SideOwner> owner(edges.size());
  std::unordered_map<std::uint64_t, std::size_t> first_listed;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& e = edges[i];
    const std::string name = "edge " + edge_name(model, e);
    if (e[0] == e[1]) {
      issues.push_back({i, SurfaceEdgeProblem::degenerate, name + ": " + describe(SurfaceEdgeProblem::degenerate)});
      continue;
    }
    const auto [seen, fresh] = first_listed.try_emplace(side_key(e[0], e[1]), i);
    if (!fresh) {
      issues.push_back({i, SurfaceEdgeProblem::repeated,
                        name + ": the same edge as edge " + std::to_string(seen->second)});
      continue;
    }
    const std::vector<SideOwner>& found = owners.at(side_key(e[0], e[1]));
    if (found.empty()) {
      issues.push_back({i, SurfaceEdgeProblem::not_a_side, name + ": " + describe(SurfaceEdgeProblem::not_a_side)});
    } else if (found.size() > 1) {
      issues.push_back({i, SurfaceEdgeProblem::interior,
                        name + ": not a boundary edge: a side of elements " +
                            std::to_string(model.elements[static_cast<std::size_t>(found[0].element)].id) +
                            " and " +
                            std::to_string(model.elements[static_cast<std::size_t>(found[1].element)].id)});
    } else {
      owner[i] = found.front();
    }
  }
  if (!issues.empty()) throw ContactSurfaceError(std::move(issues));

  // Each node may start one edge and end one edge (directed material-on-the-left); a third edge at a
  // node is a branch, a second edge starting (or ending) there has its material on the other side.
  std::unordered_map<int, std::size_t> degree;
  std::unordered_map<int, std::size_t> starting;  // node -> edge leaving it
  std::unordered_map<int, std::size_t> ending;    // node -> edge arriving at it
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (const int n : {owner[i].from, owner[i].to}) {
      if (++degree[n] > 2) {
        throw ContactSurfaceError({{i, SurfaceEdgeProblem::branch,
                                    "edge " + edge_name(model, edges[i]) + ": a third edge at " +
                                        node_name(model, n) + ": the edges are not a chain"}});
      }
    }
    const auto [out, out_fresh] = starting.try_emplace(owner[i].from, i);
    const auto [in, in_fresh] = ending.try_emplace(owner[i].to, i);
    if (!out_fresh || !in_fresh) {
      const std::size_t other = !out_fresh ? out->second : in->second;
      throw ContactSurfaceError({{i, SurfaceEdgeProblem::opposite_side,
                                  "edge " + edge_name(model, edges[i]) + ": its element " +
                                      std::to_string(model.elements[static_cast<std::size_t>(owner[i].element)].id) +
                                      " is on the other side of the chain than edge " + std::to_string(other) +
                                      "'s"}});
    }
  }

  // Walk back from the first edge to the chain's start (or all the way round), then forward.
  std::size_t first = 0;
  for (std::size_t steps = 0; steps < edges.size(); ++steps) {
    const auto prev = ending.find(owner[first].from);
    if (prev == ending.end()) break;  // the open chain's start
    if (prev->second == 0) {          // round a closed chain: start at the first edge listed
      first = 0;
      break;
    }
    first = prev->second;
  }
  ContactSurface surface;
  std::vector<bool> visited(edges.size(), false);
  std::size_t current = first;
  while (!visited[current]) {
    visited[current] = true;
    const SideOwner& o = owner[current];
    // A 3-node side: two segments, corner -> mid-side node -> corner (its halves 0 and 1).
    const std::array<int, 3> along{o.from, o.middle, o.to};
    for (int h = 0; h < (o.middle < 0 ? 1 : 2); ++h) {
      const int from = along[static_cast<std::size_t>(h)];
      const int to = o.middle < 0 ? o.to : along[static_cast<std::size_t>(h + 1)];
      const Vec2 t = node_position(model.nodes, to) - node_position(model.nodes, from);
      if (o.middle >= 0 && surface.halves.size() < surface.element.size() + 1) {
        surface.halves.resize(surface.element.size(), -1);  // the straight edges before the first 3-node one
      }
      if (!surface.halves.empty() || o.middle >= 0) surface.halves.push_back(static_cast<std::int8_t>(o.middle < 0 ? -1 : h));
      surface.nodes.push_back(from);
      surface.element.push_back(o.element);
      surface.edge.push_back(current);
      surface.normal.push_back(Vec2(t.y(), -t.x()).normalized());
    }
    const auto next = starting.find(o.to);
    if (next == starting.end()) {
      surface.nodes.push_back(o.to);  // the open chain's free end
      break;
    }
    current = next->second;
  }
  surface.closed = surface.nodes.size() == surface.element.size();
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!visited[i]) {
      throw ContactSurfaceError({{i, SurfaceEdgeProblem::disconnected,
                                  "edge " + edge_name(model, edges[i]) + ": " +
                                      describe(SurfaceEdgeProblem::disconnected)}});
    }
  }
  return surface;
}

}  // namespace saasgaps
