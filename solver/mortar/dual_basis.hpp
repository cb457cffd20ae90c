#pragma once
/// The dual basis of a segment of side A, biorthogonal to its shape functions with the measure
/// included (docs/contact-surfaces.md, section 3): the contact pressure is interpolated in it, so the
/// mortar rows' D is diagonal (mortar_coupling.hpp).

#include <span>

#include "solver/base/voigt.hpp"
#include "solver/mortar/segment_quadrature.hpp"

namespace saasgaps {

/// The dual basis of one segment x_1 -> x_2 over the part of it that `covered` (disjoint pieces) gives:
///   psi_i = A(i, 0) N_1 + A(i, 1) N_2,   A = diag(d) Me^-1,
///   Me_kl = int_covered N_k N_l dA,      d_k = int_covered N_k dA,
/// so that int_covered psi_i N_k dA = delta_ik d_i (and sum_i psi_i = 1). On a whole plane segment
/// A = [[2, -1], [-1, 2]]; on a whole axisymmetric one (radii r_1, r_2, q = r_1^2 + 4 r_1 r_2 + r_2^2)
///   psi_1 = (2 r_1 + r_2) ((r_1 + 3 r_2) N_1 - (r_1 + r_2) N_2) / q,
///   psi_2 = (r_1 + 2 r_2) ((3 r_1 + r_2) N_2 - (r_1 + r_2) N_1) / q.
struct DualBasis {
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  Vec2 d = Vec2::Zero();  ///< d_i = int_covered N_i dA (area: length x thickness, or the ring's)
};

DualBasis dual_basis(const Vec2& x1, const Vec2& x2, std::span<const ParameterInterval> covered,
                     const SurfaceMeasure& measure);

}  // namespace saasgaps
