#pragma once
/// Steady heat conduction on the SAAS elements: a pure kernel that fills the element conductance
/// matrix K_ij = integral grad N_i . k grad N_j dV of the temperature field (one unknown per node).
///
/// Geometry is element_geometry.hpp's, as for the solid: a 3-node element is one linear triangle; a
/// 4-node element is four triangles around a centre node at the mean of the corners, whose
/// temperature is condensed out. Weights: plane t A, axisymmetric 2 pi r_c A per triangle (exact:
/// the gradients are constant over a triangle, so the integrand is linear in r). In axisymmetry the
/// temperature does not vary around the axis, so only the (r, z) conductivities enter.

#include <array>

#include "element_geometry.hpp"
#include "model.hpp"
#include "voigt.hpp"

namespace saasgaps {

/// Conductivity k1 along material axis 1 (at angle_deg counter-clockwise from +r, as a solid's
/// material angle) and k2 along axis 2 (power / length / temperature). Isotropic: k1 = k2.
struct Conductivity {
  double k1 = 0.0;
  double k2 = 0.0;
  double angle_deg = 0.0;

  /// The (r, z) tensor k = k1 e1 e1^T + k2 e2 e2^T, e1 = (cos a, sin a), e2 = (-sin a, cos a).
  [[nodiscard]] Eigen::Matrix2d tensor() const;
};

/// Everything the conduction kernel depends on.
struct ConductionData {
  int node_count = 4;
  std::array<Vec2, 4> x{};  ///< corner coordinates (r, z), counter-clockwise
  AnalysisType analysis = AnalysisType::plane_stress;
  double thickness = 1.0;
  Conductivity k;
};

/// The element conductance matrix in the leading n x n block, n = node_count (one unknown per
/// corner, in corner order); the rest stays zero.
Eigen::Matrix4d conduction_matrix(const ConductionData& e);

}  // namespace saasgaps
