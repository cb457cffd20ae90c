#pragma once
/// The geometry every SAAS element kernel shares, whatever field it carries: linear triangles, the
/// SAAS quadrilateral as four triangles around a centre node, integration weights, static
/// condensation of the centre, edge weights. Nothing here knows about materials or unknowns.
///
/// Coordinates are (r, z); plane analyses read r as x and z as y. Corners are counter-clockwise.
/// Weights: plane analyses integrate over thickness t (w = t A); axisymmetric ones over the full
/// ring (w = 2 pi r_c A, r_c the triangle centroid). For a linear triangle, integral r dA = r_c A
/// exactly, so w is exact for any integrand that is constant over the triangle times r.

#include <Eigen/LU>
#include <array>
#include <numbers>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

inline constexpr double two_pi = 2.0 * std::numbers::pi;

/// A linear (3-node) triangle: N_i = (a_i + b_i r + c_i z) / 2A with constant gradients.
struct LinearTriangle {
  std::array<double, 3> dN_dr{};  ///< b_i / 2A
  std::array<double, 3> dN_dz{};  ///< c_i / 2A
  double area = 0.0;
  double r_centroid = 0.0;
  double w = 0.0;  ///< volume weight: t A (plane) or 2 pi r_c A (axisymmetric)
};

/// Shape-function gradients and weight of triangle (p0, p1, p2). Asserts it is counter-clockwise
/// and not degenerate (the reader and the restraint check refuse such elements before).
LinearTriangle linear_triangle(const Vec2& p0, const Vec2& p1, const Vec2& p2, AnalysisType analysis,
                               double thickness);

/// Twice the signed area of triangle (a, b, c): positive when counter-clockwise.
double twice_signed_area(const Vec2& a, const Vec2& b, const Vec2& c);

/// The smallest twice-signed-area of an element's triangles (the four around the centre for a quad):
/// positive exactly when the element is counter-clockwise and, for a quad, convex enough for SAAS.
double min_twice_area(int node_count, const std::array<Vec2, 4>& x);

/// The SAAS quadrilateral: corners 0..3 and centre node 4 at the mean of the corners, split into
/// the four triangles (i, i+1, 4). A nodal field at the centre that the quad interpolates is the
/// mean of its corner values (quad_values); the centre's unknowns are condensed out.
inline constexpr std::array<std::array<int, 3>, 4> quad_triangles{{{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}};

/// Corners and centre of a quad.
std::array<Vec2, 5> quad_points(const std::array<Vec2, 4>& x);

/// Corner values and their mean at the centre.
std::array<double, 5> quad_values(const std::array<double, 4>& v);

/// Static condensation of the last C unknowns of an (N + C) system:
/// K* = K_ee - K_ec K_cc^-1 K_ce, f* = f_e - K_ec K_cc^-1 f_c; G = K_ec K_cc^-1 is returned for
/// recovering u_c = K_cc^-1 (f_c - K_ce u_e). K* is exactly K_ee - G K_ec^T (not symmetrized: the
/// assembly reads the upper triangle only).
template <int N, int C>
struct Condensed {
  Eigen::Matrix<double, N, N> K;
  Eigen::Matrix<double, N, 1> f;
};

template <int N, int C>
Condensed<N, C> condense(const Eigen::Matrix<double, N + C, N + C>& K, const Eigen::Matrix<double, N + C, 1>& f) {
  const Eigen::Matrix<double, C, C> Kcc_inv = K.template bottomRightCorner<C, C>().inverse();
  const Eigen::Matrix<double, N, C> Kec = K.template topRightCorner<N, C>();
  const Eigen::Matrix<double, N, C> G = Kec * Kcc_inv;
  Condensed<N, C> out;
  out.K = K.template topLeftCorner<N, N>() - G * Kec.transpose();
  out.f = f.template head<N>() - G * f.template tail<C>();
  return out;
}

/// Consistent weights integral N_a w ds of a linear edge a-b: plane: L t / 2 each; axisymmetric:
/// 2 pi L (2 r_a + r_b) / 6 at a, and mirrored at b.
std::array<double, 2> edge_weights(const Vec2& a, const Vec2& b, AnalysisType analysis, double thickness);

}  // namespace saasgaps
