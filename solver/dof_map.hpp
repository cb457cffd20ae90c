#pragma once
/// Global numbering of the unknowns: two per node (r, z); prescribed components are eliminated
/// and their values carried to the right-hand side.

#include <array>
#include <vector>

#include "csc_pattern.hpp"
#include "errors.hpp"
#include "model.hpp"

namespace saasgaps {

class DofMap {
 public:
  static constexpr Index prescribed_dof = -1;  ///< equation number of a prescribed component
  static constexpr Index absent_dof = -2;      ///< the missing 4th corner of a triangle

  explicit DofMap(const Model& model);

  [[nodiscard]] Index size() const { return free_count_; }
  /// Equation number of node's direction (0 = r, 1 = z), or prescribed_dof.
  [[nodiscard]] Index equation(int node, int direction) const { return equation_[2 * node + direction]; }
  [[nodiscard]] double prescribed(int node, int direction) const { return value_[2 * node + direction]; }
  /// The node (by id) and direction of an equation number: the inverse map for error messages.
  [[nodiscard]] NodeDof node_dof(Index equation) const { return owner_[equation]; }

  /// For each equation, the index of its node: the two components of a node share their couplings,
  /// which lets the fill-reducing ordering work on nodes.
  [[nodiscard]] const std::vector<Index>& node_of_equation() const { return node_of_; }

  /// Equation numbers of an element's 8 local DOFs (u_r, u_z per corner).
  [[nodiscard]] std::array<Index, 8> element_equations(const std::array<int, 4>& nodes, int node_count) const;

 private:
  Index free_count_ = 0;
  std::vector<Index> equation_;  // 2 per node
  std::vector<double> value_;    // prescribed values, 2 per node (0 for free components)
  std::vector<NodeDof> owner_;   // per equation
  std::vector<Index> node_of_;   // per equation
};

}  // namespace saasgaps
