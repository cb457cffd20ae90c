#include "solver/recovery/boundary_edges.hpp"

#include <algorithm>

namespace saasgaps {

std::span<const EdgeNodes> edges_of(const Element& el) {
  const ElementType type = el.type == ElementType::saas && el.node_count == 3 ? ElementType::tri3 : el.type;
  return family(type).edges;
}

std::array<int, max_edge_nodes> edge_nodes(const Model& model, EdgeRef edge, int& count) {
  const Element& el = model.elements[edge.element];
  const EdgeNodes& local = edges_of(el)[edge.local];
  std::array<int, max_edge_nodes> out{-1, -1, -1};
  count = local.count;
  for (int k = 0; k < local.count; ++k) out[static_cast<std::size_t>(k)] = el.nodes[static_cast<std::size_t>(local.node[static_cast<std::size_t>(k)])];
  return out;
}

BoundaryEdges boundary_edges(const Model& model) {
  // Each element edge is filed under its smaller end corner (a counting sort by node, O(edges)): an
  // edge is on the boundary when no other edge filed there ends at the same larger corner. Only the
  // boundary's edges and nodes are kept.
  const auto each_edge = [&](const auto& visit) {
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
      const Element& el = model.elements[e];
      const auto edges = edges_of(el);
      for (std::size_t l = 0; l < edges.size(); ++l) {
        const int a = el.nodes[static_cast<std::size_t>(edges[l].first())];
        const int b = el.nodes[static_cast<std::size_t>(edges[l].last())];
        visit(static_cast<std::size_t>(std::min(a, b)), std::max(a, b), static_cast<std::uint32_t>(8 * e + l));
      }
    }
  };
  std::vector<std::uint32_t> first(model.nodes.size() + 1, 0);
  each_edge([&](std::size_t low, int, std::uint32_t) { ++first[low + 1]; });
  for (std::size_t n = 0; n < model.nodes.size(); ++n) first[n + 1] += first[n];
  struct Filed {
    int high;
    std::uint32_t edge;  // 8 element + local (at most 4 edges an element)
  };
  std::vector<Filed> filed(first.back());
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    each_edge([&](std::size_t low, int high, std::uint32_t edge) { filed[next[low]++] = {high, edge}; });
  }
  BoundaryEdges out;
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    for (std::uint32_t i = first[n]; i < first[n + 1]; ++i) {
      int same = 0;
      for (std::uint32_t j = first[n]; j < first[n + 1]; ++j) same += filed[j].high == filed[i].high ? 1 : 0;
      if (same == 1) out.edge.push_back({filed[i].edge / 8, static_cast<std::uint8_t>(filed[i].edge % 8)});
    }
  }
  for (std::size_t k = 0; k < out.edge.size(); ++k) {
    int count = 0;
    const auto nodes = edge_nodes(model, out.edge[k], count);
    for (int i = 0; i < count; ++i) {
      out.node_edge.emplace_back(static_cast<std::uint32_t>(nodes[static_cast<std::size_t>(i)]), static_cast<std::uint32_t>(k));
    }
  }
  std::sort(out.node_edge.begin(), out.node_edge.end());
  return out;
}

}  // namespace saasgaps
