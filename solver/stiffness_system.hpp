#pragma once
/// The assembled system K u = f over the free unknowns. The sparsity pattern and each element's
/// scatter positions are built once per model; assembly adds element matrices by index, with no
/// triplets and no allocation.
///
/// K is the sum of two parts. The solid part changes only when secant or bimodulus moduli change;
/// the gap part changes every iteration. assemble_gaps() restores just the entries that gap
/// elements touch to their solid values and adds the gaps again, so a gap-only iteration costs
/// O(gap elements), not O(model).

#include <functional>
#include <span>
#include <vector>

#include "csc_pattern.hpp"
#include "dof_map.hpp"
#include "element_kernel.hpp"
#include "model.hpp"

namespace saasgaps {

/// The constitutive law of element (or gap) number i.
using LawOf = std::function<Constitutive(std::size_t)>;

class StiffnessSystem {
 public:
  StiffnessSystem(const Model& model, const DofMap& dofs);

  /// Solid elements with law_of(e): K_solid, and f = external loads + element loads (thermal, body
  /// force) - K_fp u_p for prescribed displacements u_p.
  void assemble_solids(const LawOf& law_of);

  /// Gap elements with law_of(g), on top of the last solid assembly.
  void assemble_gaps(const LawOf& law_of);

  [[nodiscard]] const CscPattern& pattern() const { return pattern_; }
  /// The matrix values (empty before the first assemble_solids()).
  [[nodiscard]] std::span<const double> values() const { return values_; }
  [[nodiscard]] std::span<const double> rhs() const { return rhs_; }

 private:
  /// Adds one element's matrices at its slot (solids first, then gaps) into values / rhs.
  void scatter(std::size_t slot, const ElementMatrices& m, std::vector<double>& rhs);
  void assemble_external_loads();

  /// The corner nodes of a slot: solid elements first, then gap elements.
  struct SlotNodes {
    const std::array<int, 4>& nodes;
    int count;
  };
  [[nodiscard]] SlotNodes slot_nodes(std::size_t slot) const;

  const Model& model_;
  const DofMap& dofs_;
  CscPattern pattern_;
  std::vector<std::array<Index, 8>> equations_;  // per slot
  std::vector<Index> scatter_;                   // 36 upper-triangle positions per slot, -1 = none
  std::vector<bool> has_prescribed_;             // per slot: touches a nonzero prescribed value
  std::vector<double> values_;
  std::vector<double> rhs_;
  std::vector<double> solid_rhs_;
  std::vector<double> external_;
  std::vector<Index> gap_positions_;        // value positions that gap elements touch
  std::vector<double> solid_at_gap_positions_;
};

/// The 36 (a, b), a <= b, pairs of an 8x8 element matrix, in scatter order.
struct LocalPair {
  int a;
  int b;
};
extern const std::array<LocalPair, 36> upper_pairs;

}  // namespace saasgaps
