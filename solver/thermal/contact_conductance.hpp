#pragma once
/// Heat across the contact pairs of model.contact that have a `conductance`, on the mortar rows of
/// the stress analysis (mortar_coupling.hpp, docs/contact-surfaces.md).
///
/// Row j of a pair (node j of side A) measures the weighted jump of temperature across the pair
///   g_j(T) = int_A psi_j (T_B(pi(x)) - T_A(x)) dA = sum_k M_jk T_k - D_j T_j
/// (pi: the projection along A's normals; the same segment-to-segment integration as the gap).
/// With the flux across the interface interpolated in the dual basis, lambda = sum_j psi_j lambda_j,
/// and lambda_j = H_j g_j / D_j (H_j the conductance at node j, power / area / temperature), the heat
/// into node j of A is int_A N_j lambda dA = lambda_j D_j = H_j g_j, and into node k of B it is
/// -sum_j M_jk lambda_j: the interface adds the symmetric, positive semi-definite block
///   K_row = (H_j / D_j) c_j c_j^T,   c_j = (-D_j at node j, M_jk at the nodes k of B)
/// to the conduction matrix (c_j = the row's `mortar` entries). For uniform T_A = a and T_B = b it
/// passes H_j D_j (a - b) from A to B (sum_k M_jk = D_j): h (T_A - T_B) over node j's area.
///
/// H_j: a point in contact (state stick or slip), or with a gap at most touching_gap_fraction of
/// its share of A's length (faces at zero gap touch), conducts h(p) of the `closed` table at its
/// contact pressure p; an open one conducts gas_conductivity / gap.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "solver/model/model.hpp"
#include "solver/mortar/mortar_method.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps {

/// h of a conductance table at contact pressure p: linear between rows, constant beyond the ends.
double closed_conductance(const InterfaceConductance& c, double p);

/// An open point whose gap is at most this fraction of its share of side A's length (D_j / w(r_j))
/// counts as touching at zero pressure: the gap of faces that meet is zero only up to round-off.
inline constexpr double touching_gap_fraction = 1.0e-9;

/// The rows of the model's conducting contact pairs.
class ContactConductance {
 public:
  /// Builds the mortar rows of model.contact (none without it, or when no pair conducts).
  explicit ContactConductance(const Model& model);

  /// Rows of the conducting pairs, pair after pair, each pair's in the order of side A's chain.
  [[nodiscard]] std::size_t row_count() const { return rows_.size(); }
  /// The nodes (indices) row r couples: node j of A first, then the nodes of B.
  [[nodiscard]] std::span<const int> nodes(std::size_t r) const;

  /// H per row from a stress solution's contact results (Solution::contact, one entry per pair,
  /// one point per row); empty results: before any stress solve, each point at its initial gap
  /// g0_j / D_j with zero pressure.
  [[nodiscard]] std::vector<double> conductances(std::span<const ContactPairResult> results) const;

  /// Per row, whether its point conducts as touching faces (the rule above), from the same results.
  [[nodiscard]] std::vector<bool> touching(std::span<const ContactPairResult> results) const;

  /// The block (H / D_j) c_j c_j^T of row r over nodes(r).
  [[nodiscard]] Eigen::MatrixXd block(std::size_t r, double H) const;

 private:
  /// Row r's point: its gap (length), pressure and whether it touches.
  struct Point {
    double gap = 0.0;
    double pressure = 0.0;
    bool touching = false;
  };
  [[nodiscard]] Point point(std::size_t r, std::span<const ContactPairResult> results) const;

  struct Row {
    std::size_t pair = 0;  ///< index into model.contact->pairs
    std::size_t row = 0;   ///< index into that pair's MortarRows
  };
  const Model& model_;
  SurfaceContact surfaces_;
  std::vector<Row> rows_;
};

}  // namespace saasgaps
