#pragma once
/// Assembly of element matrices of any size into a symmetric sparse system, for any nodal field.
///
/// The Assembler owns the global side of assembly (after DOLFINx's assemble_matrix / mat_set): the
/// upper-triangular CSC pattern, and for every clique its equation numbers and the value positions
/// of its upper triangle, computed once. Adding an element is then an indexed scatter: no search,
/// no triplets, no allocation. Kernels stay pure functions that fill a local n x n matrix
/// (n = nodes x components) and know nothing of the numbering.
///
/// Cliques are numbered: element cliques 0 .. element_count - 1 (each a list of nodes, expanded
/// through the DofMap), then the extra couplings (lists of equation numbers, e.g. a constraint row
/// of any width across any nodes), which the pattern holds and add() may fill like elements.
///
/// Prescribed components: an element clique's local unknown that is prescribed has no position;
/// add() moves its column to the right-hand side, rhs -= K_fp u_p, when u_p != 0.

#include <functional>
#include <span>
#include <vector>

#include "solver/assembly/dof_map.hpp"
#include "solver/lac/csc_pattern.hpp"

namespace saasgaps {

/// One local block to add: an n x n matrix (column-major, leading dimension ld >= n; only its upper
/// triangle a <= b is read) and an n-vector f, n = the clique's size. Views, not copies: the
/// kernel's fixed-size Eigen matrices are read where they are.
struct ElementBlock {
  const double* K = nullptr;
  Index ld = 0;
  const double* f = nullptr;

  /// A block over Eigen matrices (Mat8 and Vec8 for a solid, Matrix4d and Vector4d for conduction, ...).
  template <class Matrix, class Vector>
  static ElementBlock of(const Matrix& K, const Vector& f) {
    static_assert(!Matrix::IsRowMajor, "column-major element matrices");
    return {K.data(), static_cast<Index>(K.outerStride()), f.data()};
  }
};

/// The sink the Assembler adds into: values on its pattern() and a right-hand side over the free
/// equations of its DofMap.
struct SystemSink {
  std::span<double> values;
  std::span<double> rhs;
};

class Assembler {
 public:
  /// The nodes of element clique e (any count; the DofMap supplies the components).
  using NodesOf = std::function<std::span<const int>(std::size_t)>;

  /// Pattern and scatter positions of element_count elements and the extra couplings. The DofMap
  /// is read only here. Negative entries in couplings (prescribed unknowns) are skipped.
  Assembler(const DofMap& dofs, std::size_t element_count, const NodesOf& nodes_of, const Cliques& couplings = {});

  [[nodiscard]] const CscPattern& pattern() const { return pattern_; }
  [[nodiscard]] std::size_t clique_count() const { return equations_.size(); }
  /// Equation numbers of a clique's local unknowns (prescribed_dof where prescribed).
  [[nodiscard]] std::span<const Index> equations(std::size_t clique) const { return equations_[clique]; }
  /// Value positions of a clique's upper triangle, column by column: (0,0), (0,1), (1,1), (0,2), ...;
  /// -1 where either unknown is prescribed.
  [[nodiscard]] std::span<const Index> positions(std::size_t clique) const { return positions_[clique]; }

  /// values += K and rhs += f - K_fp u_p at the clique's positions.
  void add(std::size_t clique, const ElementBlock& block, const SystemSink& sink) const;
  /// rhs += f - K_fp u_p only: add() without the values (K is read only where lifted()).
  void add_rhs(std::size_t clique, const ElementBlock& block, std::span<double> rhs) const;
  /// Whether a clique has a nonzero prescribed value, so that its rhs needs its K.
  [[nodiscard]] bool lifted(std::size_t clique) const { return lifted_[clique]; }

 private:
  CscPattern pattern_;
  Cliques equations_;
  Cliques positions_;
  // The local unknowns with a nonzero prescribed value, in local order (the rhs is lifted in the
  // same order as always), for the few cliques that have any: a bit per clique, and CSR over the
  // lifted cliques only, so that a model pays 1 bit per element, not an offset.
  std::vector<bool> lifted_;
  std::vector<std::size_t> lift_clique_;  // ascending
  std::vector<Index> lift_start_;         // lift_clique_.size() + 1
  std::vector<int> lift_local_;
  std::vector<double> lift_value_;
};

}  // namespace saasgaps
