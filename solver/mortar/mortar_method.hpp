#pragma once
/// Contact surfaces (model.contact) solved exactly: the mortar rows of every pair
/// (mortar_coupling.hpp) as unilateral constraints of ExactContact, the active-set solver of the
/// exact gap mode. docs/contact-surfaces.md.
///
/// Row j of a pair, divided by its weight D_j, is a ContactPair of the exact mode's convention:
///   g_j(u) / D_j = g0_j / D_j + sum_k (c_jk / D_j) . u_k     (length units),
/// gradients c_jk / D_j per node (ContactPair::gradient; on flat sides (M_jk / D_j) n_j on side B's
/// nodes and -n_j on node j), weights M_jk / D_j, normal n_j, area D_j, so that the
/// multiplier is a force and the contact pressure at node j is force_j / D_j (stress units). The
/// division also scales the rows: their coefficients are O(1) whatever the thickness or the 2 pi r
/// of the measure, and ExactContact's penalty rho_j = 1e4 c_j^T diag(K) c_j follows K's own scale
/// (an unscaled axisymmetric saddle point loses pivots). A negative g0 (an interference) is a
/// penetration that the first solve removes.
///
/// Rows couple nodes of two meshes that no element joins: contact_couplings() lists each row's
/// equations for the Assembler's extra couplings, so the pattern (and the factorization's) holds
/// them.
///
/// Friction (docs/contact.md, section 9): when some pair has friction > 0, every row of every pair
/// gets a tangential row beside it (the same weights M_jk / D_j along t_j = (-n_z, n_r), side A's
/// chain direction) and FrictionalContact solves them all (mu = 0 on the frictionless pairs), its
/// FrictionState in RestartState::friction; the first iteration of each increment ends the previous
/// increment there (finish_increment: the slip history). Without friction ExactContact solves them,
/// exactly as before. Friction needs this method to solve the rows itself: with exact gaps the
/// NodePairMethod's frictionless ExactContact would, so that combination is refused.
///
/// Composition with gap elements (model.gaps and model.contact together): MortarMethod wraps the
/// gap elements' method. The exact gap mode's NodePairMethod is built with these rows appended to its
/// node pairs, so one ExactContact solves both (one active set, one factorization); with the classic
/// mode the gap moduli go into K and this method's own ExactContact solves the rows on that K.

#include <memory>
#include <optional>
#include <vector>

#include "solver/contact/contact_method.hpp"
#include "solver/contact/exact_contact.hpp"
#include "solver/contact/frictional_contact.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "solver/mortar/contact_surface.hpp"
#include "solver/mortar/mortar_coupling.hpp"

namespace saasgaps {

/// The rows of model.contact, built once per run from the reference geometry.
struct SurfaceContact {
  std::vector<ContactSurface> surfaces;  ///< per model.contact.surfaces, validated and oriented
  std::vector<MortarRows> rows;          ///< per model.contact.pairs
  std::vector<std::size_t> first{0};     ///< per pair: its first row in `pairs` (size pairs + 1)
  ContactPairs pairs;                    ///< every row of every pair, pair after pair, as ContactPairs
  [[nodiscard]] std::size_t pair_count() const { return rows.size(); }
};

/// The surfaces and rows of model.contact; empty without it. Throws ContactSurfaceError for a
/// surface that is not a chain of boundary edges (the reader refuses those first).
SurfaceContact surface_contact(const Model& model);

/// One clique per row: the free equations of its nodes (prescribed components left out).
Cliques contact_couplings(const SurfaceContact& surfaces, const DofMap& dofs);

/// Per pair of model.contact, its rows' current gap (length), pressure (>= 0, force per unit area of
/// side A) and state, at side A's nodes in chain order; with `friction` (the rows' FrictionState, or
/// null) also the shear, stick / slip and accumulated slip. `pairs` holds the rows at `offset` (the
/// node pairs of exact gaps come first); forces and active set from `contact` (open and zero before
/// the first solve).
std::vector<ContactPairResult> contact_pair_results(const Model& model, const SurfaceContact& surfaces,
                                                    std::size_t offset, const ContactState& contact,
                                                    std::span<const double> displacement,
                                                    const FrictionState* friction = nullptr);

class MortarMethod final : public ContactMethod {
 public:
  /// gaps: the gap elements' method, or null. rows_solved_by_gaps: gaps is a NodePairMethod built
  /// with surfaces.pairs appended (it solves them); otherwise this method solves them itself.
  MortarMethod(const ContactSetup& setup, const SurfaceContact& surfaces, std::unique_ptr<ContactMethod> gaps,
               bool rows_solved_by_gaps);

  void begin_iteration(RestartState& state, StiffnessSystem& system) override;
  void solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
             RestartState& state, std::span<double> u) override;
  /// The gap elements' outcome (none without gaps); the rows are solved exactly, so no veto of theirs.
  void evaluate(RestartState& state, ContactOutcome& outcome) const override;
  void check_solved(const RestartState& state, const ContactOutcome& outcome) const override;
  void add_columns(const RestartState& state, IterationRecord& row) const override;
  /// The gap method's forces, then the rows' contact forces when this method solves them.
  void add_nodal_forces(const RestartState& state, std::span<double> forces) const override;
  /// The gap method's note, then "(contact surfaces: N of M points in contact, ...)", and a warning
  /// for each pair whose surfaces never face each other (it has no rows).
  [[nodiscard]] std::string converged_note(const RestartState& state, const ContactOutcome& outcome) const override;
  [[nodiscard]] std::vector<ContactPairResult> surface_results(const RestartState& state) const override;

 private:
  const Model& model_;
  const SurfaceContact& surfaces_;
  std::unique_ptr<ContactMethod> gaps_;
  /// The rows' contact forces and active set of `state` as ExactContact's (friction: from its state).
  [[nodiscard]] ContactState rows_state(const RestartState& state) const;

  std::optional<ExactContact> exact_;  // when the gaps' method does not solve the rows, and no friction
  ContactReport report_;               // of the last solve of exact_
  std::optional<FrictionalContact> friction_;  // when some pair has friction > 0
  FrictionReport friction_report_;             // of the last solve of friction_
};

}  // namespace saasgaps
