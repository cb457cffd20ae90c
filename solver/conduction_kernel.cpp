#include "conduction_kernel.hpp"

#include <cmath>

namespace saasgaps {

namespace {

using Mat23 = Eigen::Matrix<double, 2, 3>;
using Mat5 = Eigen::Matrix<double, 5, 5>;
using Vec5 = Eigen::Matrix<double, 5, 1>;

/// w G^T k G of one linear triangle, G = the 2 x 3 gradient matrix.
Eigen::Matrix3d triangle_conductance(const Vec2& p0, const Vec2& p1, const Vec2& p2, const ConductionData& e,
                                     const Eigen::Matrix2d& k) {
  const LinearTriangle t = linear_triangle(p0, p1, p2, e.analysis, e.thickness);
  Mat23 G;
  G.row(0) = Eigen::Vector3d(t.dN_dr[0], t.dN_dr[1], t.dN_dr[2]).transpose();
  G.row(1) = Eigen::Vector3d(t.dN_dz[0], t.dN_dz[1], t.dN_dz[2]).transpose();
  return t.w * G.transpose() * (k * G);
}

}  // namespace

Eigen::Matrix2d Conductivity::tensor() const {
  const double a = angle_deg * std::numbers::pi / 180.0;
  const Vec2 e1(std::cos(a), std::sin(a));
  const Vec2 e2(-std::sin(a), std::cos(a));
  return k1 * e1 * e1.transpose() + k2 * e2 * e2.transpose();
}

Eigen::Matrix4d conduction_matrix(const ConductionData& e) {
  const Eigen::Matrix2d k = e.k.tensor();
  Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
  if (e.node_count == 3) {
    K.topLeftCorner<3, 3>() = triangle_conductance(e.x[0], e.x[1], e.x[2], e, k);
    return K;
  }
  const auto p = quad_points(e.x);
  Mat5 Kq = Mat5::Zero();
  for (const auto& tri : quad_triangles) {
    const Eigen::Matrix3d kt = triangle_conductance(p[tri[0]], p[tri[1]], p[tri[2]], e, k);
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) Kq(tri[a], tri[b]) += kt(a, b);
    }
  }
  return condense<4, 1>(Kq, Vec5::Zero()).K;
}

}  // namespace saasgaps
