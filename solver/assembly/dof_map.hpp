#pragma once
/// Global numbering of the unknowns of one nodal field with any number of components per node
/// (1: temperature T; 2: displacement u_r, u_z). Prescribed components are eliminated and their
/// values carried to the right-hand side by the assembler.
///
/// Numbering: node by node in index order, components in order within a node, prescribed
/// components skipped. For the displacement field this is the numbering results and restart
/// fingerprints have always used; keep it.

#include <span>
#include <string_view>
#include <vector>

#include "solver/base/errors.hpp"
#include "solver/lac/csc_pattern.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

class DofMap {
 public:
  static constexpr Index prescribed_dof = -1;  ///< equation number of a prescribed component

  /// A component with a known value.
  struct Prescribed {
    int node = 0;       ///< node index
    int component = 0;  ///< 0 .. components - 1
    double value = 0.0;
  };

  /// node_ids: one per node (the ids messages name); component_names: one letter per component,
  /// e.g. "rz" or "T". A component prescribed twice takes the last value.
  DofMap(std::span<const int> node_ids, std::string_view component_names, std::span<const Prescribed> prescribed);

  /// The displacement field (u_r, u_z) of a model, its constraints prescribed.
  explicit DofMap(const Model& model);

  /// Any field on a model's nodes (e.g. "T", the temperature of a thermal run).
  DofMap(const Model& model, std::string_view component_names, std::span<const Prescribed> prescribed);

  [[nodiscard]] Index size() const { return free_count_; }
  [[nodiscard]] int components() const { return components_; }
  /// Equation number of a node's component (for displacement 0 = r, 1 = z), or prescribed_dof.
  [[nodiscard]] Index equation(int node, int component) const { return equation_[components_ * node + component]; }
  /// The prescribed value of a component (0 for free components).
  [[nodiscard]] double prescribed(int node, int component) const { return value_[components_ * node + component]; }
  /// The node (by id) and component (by name) of an equation number: the inverse map for messages.
  [[nodiscard]] NodeDof node_dof(Index equation) const { return owner_[equation]; }

  /// For each equation, the index of its node: the components of a node share their couplings,
  /// which lets the fill-reducing ordering work on nodes.
  [[nodiscard]] const std::vector<Index>& node_of_equation() const { return node_of_; }

  /// Equation numbers of the components of `nodes`, node-major:
  /// out[components() * a + c] = equation(nodes[a], c). out holds at least components() * nodes.size().
  void equations(std::span<const int> nodes, std::span<Index> out) const;

 private:
  int components_ = 0;
  Index free_count_ = 0;
  std::vector<Index> equation_;  // components_ per node
  std::vector<double> value_;    // prescribed values, components_ per node (0 for free components)
  std::vector<NodeDof> owner_;   // per equation
  std::vector<Index> node_of_;   // per equation
};

}  // namespace saasgaps
