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
#include <Eigen/Dense>

#include "solver/base/voigt.hpp"
#include "solver/fe/element_geometry.hpp"
#include "solver/model/model.hpp"

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

/// What a conduction step adds to the element besides K: a heat source s (power / volume) and,
/// for an implicit time step, the capacity rate m = density c / dt with the previous temperatures.
struct ConductionLoad {
  double source = 0.0;
  double capacity_rate = 0.0;        ///< density c / dt; 0 for a steady solve
  std::array<double, max_element_nodes> previous{};  ///< node temperatures of the previous step (capacity_rate > 0)
};

/// The element block of one conduction solve, condensed to the corners:
///   A = K + m C,  f = integral s N dV + m C T_previous,
/// C_ij = integral N_i N_j dV the consistent capacity matrix. Per linear triangle (corners i, j, k):
///   plane:        C = t A / 12 [2 1 1; 1 2 1; 1 1 2],       integral N_i dV = t A / 3;
///   axisymmetric: C_ii = 2 pi A (3 r_i + r_j + r_k) / 30,   C_ij = 2 pi A (2 r_i + 2 r_j + r_k) / 60,
///                 integral N_i dV = 2 pi A (2 r_i + r_j + r_k) / 12
/// (from integral N_i^a N_j^b N_k^c dA = 2 A a! b! c! / (a + b + c + 2)!, r = sum r_m N_m). In a quad
/// K and the source are condensed to the corners as for the solid; the capacity takes the centre
/// temperature as the mean of the corners' (the value the quad interpolates there) at every time,
/// C4 = P^T C5 P with P the 5 x 4 map of that interpolation, so the centre stores no heat of its own
/// between steps (a condensed centre with capacity would need its previous value kept per element).
struct ConductionBlock {
  Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
  Eigen::Vector4d f = Eigen::Vector4d::Zero();
};
ConductionBlock conduction_block(const ConductionData& e, const ConductionLoad& load);

/// What conduction_block's f is made of, constant while the element's geometry, k and source are:
/// f = source_load + m (C T_previous) (the second term only when m > 0), C the corner capacity
/// matrix (C4 for a quad), zero-padded to 4 x 4 for a triangle.
struct ConductionLoadParts {
  Eigen::Matrix4d C = Eigen::Matrix4d::Zero();
  Eigen::Vector4d source_load = Eigen::Vector4d::Zero();
};
ConductionLoadParts conduction_load_parts(const ConductionData& e, double source);

/// f of conduction_block from its parts: the same operations, so the same bits, without the kernel.
Eigen::Vector4d conduction_load(const ConductionLoadParts& parts, const ConductionLoad& load);

/// The heat flux q = -k grad T of the element (power / area): per triangle constant; for a quad the
/// area-weighted mean of its four triangles with the centre at the mean of the corner temperatures.
Vec2 conduction_flux(const ConductionData& e, const std::array<double, 4>& T);

/// A convection film on the element edge a-b: the edge matrix h integral N_a N_b dS and the load
/// h T_ambient integral N_a dS (dS = t ds, or 2 pi r ds in axisymmetry):
///   plane:        h t L / 6 [2 1; 1 2];
///   axisymmetric: 2 pi h L / 12 [3 r_a + r_b, r_a + r_b; r_a + r_b, r_a + 3 r_b].
struct EdgeBlock {
  Eigen::Matrix2d K = Eigen::Matrix2d::Zero();
  Eigen::Vector2d f = Eigen::Vector2d::Zero();
};
EdgeBlock film_block(const Vec2& a, const Vec2& b, AnalysisType analysis, double thickness, double film,
                     double ambient);

}  // namespace saasgaps
