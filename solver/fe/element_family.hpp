#pragma once
/// The element families, as one table the whole program reads: what an element of each family is
/// (node count and layout, edges, reference shape functions, integration rules, the Gmsh and VTK
/// type codes, the extrapolation from its material points to its nodes) and which kernel fills its
/// matrices. Kernels, assembly, loads, results, import, VTU and plots ask the family, never a node
/// count.
///
/// Node order (Gmsh, VTK and CalculiX alike): the corners counter-clockwise, then the mid-side
/// nodes in the order of the edges (1-2, 2-3, 3-1 or 1-2, 2-3, 3-4, 4-1), then the centre node.
/// Reference cells: triangles on (xi, eta) with xi, eta >= 0, xi + eta <= 1, corners (0,0), (1,0),
/// (0,1); quadrilaterals on [-1, 1]^2, corners (-1,-1), (1,-1), (1,1), (-1,1).
///
/// Material points: where an element keeps its material state (secant ratio, bimodulus choice,
/// plastic history) and where its stresses are computed. The report's two elements keep one, at
/// the centre (saas: the weighted mean of its four triangles; tri3: its only strain); the others
/// keep one per point of their integration rule.
///
/// A new family is a file pair in fe/families/ that defines its ElementFamily and one line in
/// element_family.cpp's table (docs/architecture.md, "Element families").

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "solver/base/voigt.hpp"
#include "solver/model/element_type.hpp"

namespace saasgaps {

inline constexpr int max_element_dofs = 2 * max_element_nodes;
inline constexpr int max_material_points = 9;
inline constexpr int max_edge_nodes = 3;

enum class CellShape : std::uint8_t { triangle, quadrilateral };

/// A point of the reference cell and its weight (the reference cell's area is the sum of weights:
/// 1/2 for triangles, 4 for quadrilaterals).
struct ReferencePoint {
  double xi = 0.0;
  double eta = 0.0;
  double weight = 0.0;
};

/// The local node indices of one edge, from corner to corner along the counter-clockwise boundary:
/// (a, b) for a straight 2-node edge, (a, m, b) for a 3-node edge through its mid-side node m.
struct EdgeNodes {
  std::array<int, max_edge_nodes> node{-1, -1, -1};
  int count = 2;
  [[nodiscard]] int first() const { return node[0]; }
  [[nodiscard]] int last() const { return node[count - 1]; }
};

/// Shape functions at one reference point: N_a and their derivatives along xi and eta, a < node_count.
struct ShapeValues {
  std::array<double, max_element_nodes> N{};
  std::array<double, max_element_nodes> dN_dxi{};
  std::array<double, max_element_nodes> dN_deta{};
};

struct ElementData;
struct ElementMatrices;
struct ElementStates;

/// One family. Plain data and function pointers, defined once per family (fe/families/).
struct ElementFamily {
  ElementType type = ElementType::saas;
  CellShape cell = CellShape::quadrilateral;
  int node_count = 4;
  int corner_count = 4;
  int order = 1;  ///< polynomial order of its edges: 1 straight, 2 quadratic
  std::span<const EdgeNodes> edges;
  std::span<const std::array<double, 2>> node_positions;  ///< (xi, eta) of each node
  int gmsh_type = 0;  ///< Gmsh's element type number
  int vtk_type = 0;   ///< VTK's cell type number
  /// Shape functions at (xi, eta). For saas: piecewise linear on its four triangles with the centre
  /// value the mean of the corners (how it interpolates temperatures and how plots draw it).
  void (*shape)(double xi, double eta, ShapeValues& out) = nullptr;
  /// Material points (see the file comment) for each integration setting; saas and tri3 ignore it.
  std::span<const ReferencePoint> (*material_points)(Integration integration) = nullptr;
  /// The rule its kernel integrates the stiffness with (what a Jacobian check must visit).
  std::span<const ReferencePoint> (*stiffness_rule)(Integration integration) = nullptr;
  /// The kernel: condensed stiffness and nodal loads; stresses at its material points and centre.
  ElementMatrices (*matrices)(const ElementData& e) = nullptr;
  ElementStates (*states)(const ElementData& e, std::span<const double> u) = nullptr;
  /// The report's elements (saas, tri3): constant-strain triangles with one material point at the
  /// centre, whose stresses (the recovery's samples, the error estimate's field) come from their
  /// displacements and law, not from the material points' states.
  bool report_element = false;

  [[nodiscard]] int dof_count() const { return 2 * node_count; }
  [[nodiscard]] int edge_count() const { return static_cast<int>(edges.size()); }
  [[nodiscard]] bool quadratic() const { return order == 2; }
  [[nodiscard]] int point_count(Integration integration) const {
    return static_cast<int>(material_points(integration).size());
  }
};

/// The family of a type (every ElementType has one).
const ElementFamily& family(ElementType type);

/// The default family for a node count: 3 tri3, 4 saas, 6 tri6, 8 quad8, 9 quad9; none for others.
std::optional<ElementType> default_element_type(int node_count);

/// The family whose Gmsh type number this is, if any.
std::optional<ElementType> element_type_of_gmsh(int gmsh_type);

/// Extrapolation from material points to nodes: value at node a = sum_p E[a][p] value at point p,
/// the polynomial through the points (constant for one point, linear for three, bilinear for
/// 2 x 2, biquadratic for 3 x 3) evaluated at the nodes.
struct Extrapolation {
  std::array<std::array<double, max_material_points>, max_element_nodes> E{};
  int nodes = 0;
  int points = 0;
};
const Extrapolation& extrapolation(ElementType type, Integration integration);

/// The coefficients that give a value at the element's centre from its material points' values
/// (the same polynomial evaluated at the centre): what `elements[]` reports for families with
/// several points.
std::span<const double> centre_weights(ElementType type, Integration integration);

/// The reference centre of a family's cell: (1/3, 1/3) for triangles, (0, 0) for quadrilaterals.
std::array<double, 2> reference_centre(CellShape shape);

}  // namespace saasgaps
