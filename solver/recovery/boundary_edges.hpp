#pragma once
/// The boundary of a mesh: the edges of solid elements that no other solid element shares (the
/// outline of the body, holes included; an interface between materials is not on it, the faces of
/// separate parts that touch are). Gap elements do not count: the edges they join are boundary edges.

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "solver/fe/element_family.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// The edges of an element: its family's, or tri3's for a report element given 3 nodes.
std::span<const EdgeNodes> edges_of(const Element& el);

/// An edge of a solid element: the element and the edge's index in edges_of.
struct EdgeRef {
  std::uint32_t element = 0;
  std::uint8_t local = 0;
};

/// The edge's nodes by node index, in the element's (counter-clockwise) order; count: 2 or 3.
std::array<int, max_edge_nodes> edge_nodes(const Model& model, EdgeRef edge, int& count);

/// The edges no other solid element shares, and the nodes on them with the edges each lies on.
struct BoundaryEdges {
  std::vector<EdgeRef> edge;
  /// (node, index into `edge`) for every node of every boundary edge, sorted by node.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> node_edge;
};

/// The boundary edges of the model's solid elements: O(edges) time (a counting sort by node), and
/// memory for the boundary beside one pass's.
BoundaryEdges boundary_edges(const Model& model);

}  // namespace saasgaps
