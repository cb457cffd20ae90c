#pragma once
/// The assembled displacement system K u = f over the free unknowns: the solid and gap element sets
/// of a model through one Assembler (assembler.hpp), which builds the pattern and each element's
/// scatter positions once per model.
///
/// K is the sum of two parts. The solid part changes only when secant or bimodulus moduli change;
/// the gap part changes every iteration. assemble_gaps() restores just the entries that gap
/// elements touch to their solid values and adds the gaps again, so a gap-only iteration costs
/// O(gap elements), not O(model).

#include <functional>
#include <span>
#include <vector>

#include "solver/assembly/assembler.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/fe/element_kernel.hpp"
#include "solver/lac/csc_pattern.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// The constitutive law of element (or gap) number i.
using LawOf = std::function<Constitutive(std::size_t)>;

/// The laws of every material point of solid element e (fe/material_points.hpp), in the element's
/// point order: written into `scratch` (max_material_points long) or held elsewhere; one law stands
/// for every point.
using PointLawsOf = std::function<std::span<const Constitutive>(std::size_t e, std::span<Constitutive> scratch)>;

/// One law per element, at every point.
PointLawsOf at_every_point(const LawOf& law_of);

/// A PointLawsOf for one thread of a parallel pass, made once per range: each may keep what it
/// computed last between its calls (SolidMaterials::LawMemo: an element of the same material and
/// temperature as the one before takes its law again instead of computing it).
using PointLawsFactory = std::function<PointLawsOf()>;

/// The model's nodal forces and the consistent nodal loads of its edge tractions, one add(node index,
/// (f_r, f_z)) per node and load, in assembly order: f_loads of K u = f (element loads apart).
void for_each_external_load(const Model& model, const std::function<void(int node, const Vec2& force)>& add);

class StiffnessSystem {
 public:
  /// couplings: constraint rows across nodes no element joins (contact surfaces' rows), held by the
  /// pattern and never assembled here.
  StiffnessSystem(const Model& model, const DofMap& dofs, const Cliques& couplings = {});

  /// Solid elements with law_of(e): K_solid, and f = external loads + element loads (thermal, body
  /// force) - K_fp u_p for prescribed displacements u_p.
  void assemble_solids(const LawOf& law_of);
  /// The same with a law per material point.
  void assemble_solids(const PointLawsOf& laws_of);

  /// Gap elements with law_of(g), on top of the last solid assembly.
  void assemble_gaps(const LawOf& law_of);

  [[nodiscard]] const CscPattern& pattern() const { return assembler_.pattern(); }
  /// The matrix values (empty before the first assemble_solids()).
  [[nodiscard]] std::span<const double> values() const { return values_; }
  [[nodiscard]] std::span<const double> rhs() const { return rhs_; }

 private:
  void assemble_external_loads();

  const Model& model_;
  const DofMap& dofs_;
  Assembler assembler_;  // cliques: solid elements first, then gap elements, then the couplings
  std::vector<double> values_;
  std::vector<double> rhs_;
  std::vector<double> solid_rhs_;
  std::vector<double> external_;
  std::vector<Index> gap_positions_;  // value positions that gap elements touch
  std::vector<double> solid_at_gap_positions_;
};

}  // namespace saasgaps
