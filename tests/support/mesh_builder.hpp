#pragma once
/// Models built in code for tests and benchmarks: structured grids mapped onto any shape.

#include <array>
#include <functional>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::testing {

/// Node indices of a structured grid, (ni + 1) x (nj + 1) nodes.
struct Grid {
  int ni = 0;
  int nj = 0;
  std::vector<int> nodes;  ///< index of node (i, j) at i + (ni + 1) j
  [[nodiscard]] int at(int i, int j) const { return nodes[static_cast<std::size_t>(i + (ni + 1) * j)]; }
};

/// Adds (ni + 1) x (nj + 1) nodes at map(i / ni, j / nj) and ni x nj quadrilaterals of `material`
/// (counter-clockwise when map preserves orientation). Ids continue after the largest in use.
Grid add_grid(Model& model, int ni, int nj, const std::function<Vec2(double, double)>& map, int material,
              double angle_deg = 0.0);

/// Node indices of a structured grid of quadratic elements on half-steps: node (I, J), I = 0..2 ni,
/// J = 0..2 nj, at map(I / (2 ni), J / (2 nj)) (so a curved map puts mid-side nodes on its curves);
/// -1 where the family has no node (quad8's cell centres).
struct QuadraticGrid {
  int ni = 0;
  int nj = 0;
  std::vector<int> nodes;
  /// Per cell (i + ni j): its elements (one quadrilateral, or two tri6: corners (0, 1, 2) and (0, 2, 3)
  /// of the cell, the second -1 for quadrilaterals).
  std::vector<std::array<int, 2>> cells;
  [[nodiscard]] int at(int I, int J) const { return nodes[static_cast<std::size_t>(I + (2 * ni + 1) * J)]; }
  /// Corner (i, j) of the cell grid, i in 0..ni, j in 0..nj.
  [[nodiscard]] int corner(int i, int j) const { return at(2 * i, 2 * j); }
  /// The corner pairs of the element edges along corner row j (i = 0..ni-1): a contact surface's edges.
  [[nodiscard]] std::vector<std::array<int, 2>> row_edges(int j) const;
  /// Every node of corner row j (corners and, for the quadratic families, mid-side nodes), I from 0 up.
  [[nodiscard]] std::vector<int> row_nodes(int j) const;
};

/// Adds ni x nj cells of tri6, quad8 or quad9 (quad4i and saas: the corners only) of `material`,
/// counter-clockwise when map preserves orientation, nodes at map(s, t) + offset(I, J) (offset: to
/// distort a patch; zero when empty). Ids continue after the largest in use.
QuadraticGrid add_quadratic_grid(Model& model, ElementType type, int ni, int nj,
                                 const std::function<Vec2(double, double)>& map, int material,
                                 const std::function<Vec2(int, int)>& offset = {});

/// The element edges along a side of the grid, 'b' (J = 0), 'r' (I = 2 ni), 't' (J = 2 nj) or 'l'
/// (I = 0), as thermal edges (element index, corner a, corner b).
std::vector<ThermalEdge> quadratic_grid_side(const Model& model, const QuadraticGrid& grid, char side);

/// A ring r0..r1 meshed on its own: `radial` x `around` quadrilaterals (grid i radial, j round).
/// Plane analyses: the whole ring about the origin, closed round (grid row `around` is row 0, so
/// column_edges(g, i) of stacked_blocks.hpp is a closed chain). Axisymmetric: a slice r0..r1 of height 0.2 along z.
Grid add_ring(Model& m, double r0, double r1, int radial, int around, int material);

/// Adds gap elements joining two node rows a[k] (one face) and b[k] (other face), k = 0..n,
/// as quads (a[k], a[k+1], b[k+1], b[k]) with M axis at angle_of(k) degrees.
void add_gap_row(Model& model, const std::vector<int>& a, const std::vector<int>& b,
                 const std::function<double(int)>& angle_of);

/// An isotropic material with one table row.
Material isotropic_material(int id, double E, double nu, double alpha = 0.0);

/// Makes loads.node_temperature one per node (new nodes at `temperature`).
void fill_temperatures(Model& model, double temperature);

/// Fixes the given components of a node.
void constrain(Model& model, int node, std::optional<double> u_r, std::optional<double> u_z);

/// Largest node / element id in use.
int max_node_id(const Model& model);
int max_element_id(const Model& model);

}  // namespace saasgaps::testing
