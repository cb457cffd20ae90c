#pragma once
/// Structured grids of quadratic elements (quad8, quad9) built in code, for benchmarks and tests.

#include <functional>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::testing {

/// Node indices of a quadratic structured grid on the (2 ni + 1) x (2 nj + 1) lattice of corner,
/// mid-side and centre positions; -1 where the family has no node (quad8's centres).
struct QuadraticGrid {
  int ni = 0;
  int nj = 0;
  std::vector<int> nodes;  ///< index of lattice point (i, j) at i + (2 ni + 1) j
  [[nodiscard]] int at(int i, int j) const { return nodes[static_cast<std::size_t>(i + (2 * ni + 1) * j)]; }
};

/// Adds ni x nj elements of `type` (quad8 or quad9) of `material` on map's image of the unit
/// square, every node at map(i / (2 ni), j / (2 nj)) (so edges follow map's curves). Ids continue
/// after the largest in use.
QuadraticGrid add_quadratic_grid(Model& model, int ni, int nj, const std::function<Vec2(double, double)>& map,
                                 int material, ElementType type);

}  // namespace saasgaps::testing
