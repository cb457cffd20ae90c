#pragma once
/// Gathers one element's kernel input from the model: coordinates, temperatures, body forces.

#include <span>

#include "solver/fe/element_kernel.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Mean temperature of an element's nodes: the temperature the report's elements read their
/// properties at.
double element_temperature(const Model& model, std::span<const int> nodes);

/// Solid element e's geometry as the kernels take it: family, integration, coordinates, analysis,
/// thickness; no temperatures, body force or law (what a field recovered from it needs).
ElementData solid_element_geometry(const Model& model, std::size_t e);

/// Kernel input of solid element e with one constitutive law at every material point.
ElementData solid_element_data(const Model& model, std::size_t e, const Constitutive& law);

/// Kernel input of solid element e with a law per material point (viewed, not copied: point_laws
/// must outlive the ElementData; a single law is copied and stands for every point).
ElementData solid_element_data(const Model& model, std::size_t e, std::span<const Constitutive> point_laws);

/// Kernel input of gap element g: no thermal strain and no body force (its properties are fictitious).
ElementData gap_element_data(const Model& model, std::size_t g, const Constitutive& law);

/// The element's nodal displacements (u_r, u_z per node, in the element's order) from the full vector
/// of (u_r, u_z) per node.
ElementVector element_displacements(std::span<const double> u, std::span<const int> nodes);

/// An element vector as the span the kernels take.
inline std::span<const double> values(const ElementVector& v) {
  return std::span<const double>(v.data(), static_cast<std::size_t>(v.size()));
}

/// An edge of a solid element by node indices, from node_a to node_b (the order asked for), its
/// mid-side node between them on a quadratic edge.
struct ElementEdge {
  std::array<int, max_edge_nodes> node{-1, -1, -1};
  int count = 2;
};

/// The edge of solid element e whose end corners are node_a and node_b (in either order; asserted
/// to exist: the reader checks edges).
ElementEdge element_edge(const Model& model, std::size_t e, int node_a, int node_b);

/// The coordinates of the first `count` (at most 4) nodes: a gap element's corners, or a report
/// element's as its conduction kernel reads them.
template <std::size_t N>
std::array<Vec2, 4> corner_coordinates(const Model& model, const std::array<int, N>& nodes, int count) {
  std::array<Vec2, 4> x{};
  for (std::size_t a = 0; a < static_cast<std::size_t>(count) && a < 4; ++a) {
    const auto n = static_cast<std::size_t>(nodes[a]);
    x[a] = Vec2(model.nodes[n].r, model.nodes[n].z);
  }
  return x;
}

/// Node coordinates of an element by node indices (unused entries zero).
std::array<Vec2, max_element_nodes> node_coordinates(const Model& model, std::span<const int> nodes);

}  // namespace saasgaps
