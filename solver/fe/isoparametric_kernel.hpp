#pragma once
/// The isoparametric solid kernel of tri6, quad8 and quad9 (and the bilinear part of quad4i): at each
/// point of the family's rule (element_family.hpp)
///   J = sum_a x_a (dN_a/dxi, dN_a/deta)^T,  (dN/dr, dN/dz) = J^-T (dN/dxi, dN/deta),  r = sum_a N_a r_a,
///   B rows (rr, zz, rz, th): dN_a/dr on u_r; dN_a/dz on u_z; dN_a/dz on u_r + dN_a/dr on u_z;
///                            N_a / r on u_r (axisymmetric; 0 in plane analyses),
///   dV = w det J t (plane) or w det J 2 pi r (axisymmetric, the full ring),
///   K = sum B^T D B dV,  f = sum B^T (beta dT + D eps0) dV + sum N_a (b + spin r e_r) dV,
/// with dT = sum_a N_a dT_a the temperature rise interpolated by the element's own shape functions and
/// D, beta, eps0 the law of that point. Stresses: sigma = D (B u - eps0) - beta dT at each point;
/// plane stress reports eps_th = out_of_plane . sigma + alpha3 dT (+ eps0_th). The centre state is the
/// polynomial through the points' states evaluated at the centre (element_family.hpp).

#include <span>

#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

/// The geometry of one point of an element: shape functions, their (r, z) derivatives, r, det J.
struct PointGeometry {
  ShapeValues shape;
  std::array<double, max_element_nodes> dN_dr{};
  std::array<double, max_element_nodes> dN_dz{};
  double r = 0.0;
  double z = 0.0;
  /// J = [dr/dxi dr/deta; dz/dxi dz/deta] and its determinant.
  double j11 = 0.0, j12 = 0.0, j21 = 0.0, j22 = 0.0;
  double det_J = 0.0;

  /// (d/dr, d/dz) of a function whose reference derivatives are (d/dxi, d/deta): J^-T times them.
  [[nodiscard]] Vec2 gradient(double d_dxi, double d_deta) const {
    return Vec2(j22 * d_dxi - j21 * d_deta, -j12 * d_dxi + j11 * d_deta) / det_J;
  }
};

/// Geometry at reference point (xi, eta) of an element of `type` with nodes x (node_count of them).
PointGeometry point_geometry(ElementType type, int node_count, const std::array<Vec2, max_element_nodes>& x, double xi,
                             double eta);

/// Geometry at reference point (xi, eta) of element e's family and nodes.
inline PointGeometry point_geometry(const ElementData& e, double xi, double eta) {
  return point_geometry(e.type, e.node_count, e.x, xi, eta);
}

/// The volume weight of a rule point: weight det J t, or weight det J 2 pi r.
double volume_weight(const ElementData& e, const PointGeometry& g, double weight);

/// The strain-displacement matrix of the first `nodes` shape functions at a point, into the first
/// 2 x nodes columns of B (zeroed first): rows (rr, zz, rz, th), columns [u_r0, u_z0, u_r1, ...];
/// eps_th = u_r / r in axisymmetry.
template <class Matrix>
void strain_displacement(const PointGeometry& g, int nodes, bool axisymmetric, Matrix& B) {
  B.setZero();
  for (int a = 0; a < nodes; ++a) {
    const auto k = static_cast<std::size_t>(a);
    B(rr, 2 * a) = g.dN_dr[k];
    B(zz, 2 * a + 1) = g.dN_dz[k];
    B(rz, 2 * a) = g.dN_dz[k];
    B(rz, 2 * a + 1) = g.dN_dr[k];
    if (axisymmetric) B(th, 2 * a) = g.shape.N[k] / g.r;
  }
}

/// Strain of one point from the element's displacements (B u, rows rr, zz, rz, th).
Vec4 point_strain(const ElementData& e, const PointGeometry& g, std::span<const double> u);

/// The state at a point from its total strain B u: stress and (plane stress) eps_th.
ElementState point_state(const ElementData& e, const Constitutive& law, const Vec4& strain, double dT);

/// Temperature rise at a point: sum_a N_a dT_a.
double point_temperature_rise(const ElementData& e, const PointGeometry& g);

/// The centre state from the points' states (centre_weights of the family and rule).
ElementState centre_of(const ElementData& e, const ElementStates& s);

/// K and f of an isoparametric element.
ElementMatrices isoparametric_matrices(const ElementData& e);

/// Its states at the rule's points and at the centre.
ElementStates isoparametric_states(const ElementData& e, std::span<const double> u);

}  // namespace saasgaps
