#pragma once
/// Segment-to-segment (mortar) discretisation of frictionless normal contact between two contact
/// surfaces in 2D: side A (non-mortar, "slave") and side B (mortar, "master"). Plane analyses integrate
/// over the thickness t, axisymmetric ones over the full ring (2 pi r in every integral). Derivation,
/// choices and the patch-test argument: docs/contact-surfaces.md.
///
/// On A the displacement and the multiplier (contact pressure) are interpolated by
///   N_1 = 1 - xi, N_2 = xi               (x = (1 - xi) x_1 + xi x_2 on a segment, 0 <= xi <= 1)
///   psi_i = A_i1 N_1 + A_i2 N_2           (dual: int_S psi_i N_k dA = delta_ik d_i on every segment)
/// with dA = w ds, w = t or 2 pi r. The gap of a point of A is measured along A's normal field
/// n(xi) = normalize((1 - xi) n_1 + xi n_2), n_j the nodal normals (surface_geometry.hpp). Then node j
/// of A gives ONE constraint row, its weighted gap
///   g_j = int_A psi_j n(xi) . (x_B - x_A) dA,
///   D_j  = int_A psi_j N_j dA = int_A N_j dA    (diagonal: biorthogonality),
///   M_jk = int_A psi_j N_k^B dA                 (k over B's nodes),
/// linear in the displacements: g_j(u) = g0_j + sum_k c_jk . u_k, with a vector c_jk per node of B,
/// of node j and of its neighbours on A: c_jk = int_A psi_j (N_k^B v_B - N_k^A v_A) dA, v = n(xi)
/// plus the bend of each side's smooth curve (its offset from the chord moves with the chord's
/// stretch and rotation; docs/contact-surfaces.md). The initial gap is measured
/// from the geometry the nodes sample, not from the polygons:
///   g0_j = D_j g_j,   g_j = distance from node j along n_j to B's smooth curve through its nodes
/// (circular-arc offsets of B's chords matching B's nodal normals, exact on a circle; corners kept),
/// which is int_A psi_j (N_1 g_1 + N_2 g_2) dA by biorthogonality. The polygons' own weighted gap,
/// n_j . (sum_k M_jk x_k - D_j x_j), differs on curved non-matching sides by the chords' sags,
/// about R (a_A^2 - a_B^2) / 12 for chord angles a_A, a_B on radius R: as large as a press fit's
/// interference on practical meshes, and a fit at zero clearance would carry pressure. It is used only
/// for a node whose normal meets no segment of B (an end only partly facing B). The integrals run over the
/// overlaps of A's segments with the projections of B's segments (each split where the facing
/// B segment changes), 3 Gauss points per overlap, exact for the cubic psi N r on straight sides.
///
/// The rows are built in the order the concepts come: each side's geometry (surface_geometry.hpp),
/// the pieces of A facing B (overlap_search.hpp, along normal_projection.hpp's projections), the
/// integrals over them (segment_quadrature.hpp, dual_basis.hpp), then the rows.

#include <span>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"
#include "solver/mortar/contact_surface.hpp"
#include "solver/mortar/overlap_search.hpp"
#include "solver/mortar/segment_quadrature.hpp"
#include "solver/mortar/surface_geometry.hpp"

namespace saasgaps {

/// The constraint rows of one pair of surfaces, in CSR form, one row per node of A that faces B,
/// in the order of A's chain. Row r holds entries [start[r], start[r + 1]): the node of A first
/// (mortar = -D_j), then, by node index, its neighbours on A (mortar 0) and the nodes of B whose
/// segments overlap the node's support (mortar = M_jk; a node on both sides has the sum). Units: g0
/// and the coefficients are length x area.
///
/// Dividing a row by its weight D_j gives a gap in length units, g_j / D_j, whose multiplier is a force
/// (the exact mode's convention, contact_pairs.hpp): the contact pressure at node j is then
/// force_j / D_j, and the row puts force_j c_jk / D_j on each of its nodes.
struct MortarRows {
  std::vector<int> slave_node;       ///< per row: the node j of A (index)
  std::vector<Vec2> normal;          ///< per row: n_j, A's nodal normal (unit, out of A)
  std::vector<double> g0;            ///< per row: initial weighted gap D_j g_j; < 0 is an interference
  std::vector<double> weight;        ///< per row: D_j = int_A N_j dA > 0, the node's share of A's area
  std::vector<std::size_t> start{0};  ///< size rows + 1
  std::vector<int> node;             ///< per entry: node index
  std::vector<double> mortar;        ///< per entry: M_jk, or -D_j (plus M_jj if j is on both sides)
  std::vector<Vec2> coefficient;     ///< per entry: c_jk = (d g_j / d u_r, d g_j / d u_z); M_jk n_j on flat sides

  [[nodiscard]] std::size_t size() const { return slave_node.size(); }
  /// g_j(u) = g0_j + sum over the row's entries of coefficient . u_node; displacement holds
  /// (u_r, u_z) per node.
  [[nodiscard]] double gap(std::size_t row, std::span<const double> displacement) const;
};

/// A segment of A facing B over less than this share of its length is left out: the dual basis over
/// a sliver of length delta has condition number ~ 12 / delta^2, and at 1e-3 it keeps 9 digits.
inline constexpr double min_covered_fraction = 1.0e-3;

/// The rows coupling side A (slave) to side B (master), from each side's geometry (computed once per
/// surface: surface_contact(), mortar_method.hpp): the pieces of A facing B (overlap_search.hpp; no
/// distance limit, so a row whose initial gap is large just never becomes active), the integrals over
/// them, then one row per node of A with a share of them. Nodes of A that face nothing give no row.
///
/// candidate_checks (optional): add the number of master segments the pairing examined (a segment
/// examined for several slave segments or nodes counts each time).
MortarRows mortar_rows(const SurfaceMeasure& measure, const SurfaceGeometry& slave, const SurfaceGeometry& master,
                       Pairing pairing = Pairing::search, std::size_t* candidate_checks = nullptr);

/// The same for one pair on its own (tests, the benchmark): each side's geometry computed here.
MortarRows mortar_rows(const std::vector<Node>& nodes, const SurfaceMeasure& measure, const ContactSurface& slave,
                       const ContactSurface& master, Pairing pairing = Pairing::search,
                       std::size_t* candidate_checks = nullptr);

}  // namespace saasgaps
