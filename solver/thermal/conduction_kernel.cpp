#include "solver/thermal/conduction_kernel.hpp"

#include <cmath>
#include <utility>

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

/// The conductance, capacity and source vector of one linear triangle (the class comment's formulas).
struct TriangleBlock {
  Eigen::Matrix3d K;
  Eigen::Matrix3d C;
  Eigen::Vector3d source;  ///< integral N_i dV
};

TriangleBlock triangle_block(const Vec2& p0, const Vec2& p1, const Vec2& p2, const ConductionData& e,
                             const Eigen::Matrix2d& k) {
  TriangleBlock b;
  b.K = triangle_conductance(p0, p1, p2, e, k);
  const double area = 0.5 * twice_signed_area(p0, p1, p2);
  if (e.analysis != AnalysisType::axisymmetric) {
    b.C = Eigen::Matrix3d::Constant(e.thickness * area / 12.0);
    b.C.diagonal() *= 2.0;
    b.source = Eigen::Vector3d::Constant(e.thickness * area / 3.0);
    return b;
  }
  const std::array<double, 3> r{p0.x(), p1.x(), p2.x()};
  const double sum = r[0] + r[1] + r[2];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      b.C(i, j) = i == j ? two_pi * area * (2.0 * r[i] + sum) / 30.0 : two_pi * area * (r[i] + r[j] + sum) / 60.0;
    }
    b.source[i] = two_pi * area * (r[i] + sum) / 12.0;
  }
  return b;
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

namespace {

/// K and the parts of f: conduction_block's kernel.
std::pair<Eigen::Matrix4d, ConductionLoadParts> conduction_parts(const ConductionData& e, double source) {
  const Eigen::Matrix2d k = e.k.tensor();
  Eigen::Matrix4d K4 = Eigen::Matrix4d::Zero();
  ConductionLoadParts parts;
  if (e.node_count == 3) {
    const TriangleBlock t = triangle_block(e.x[0], e.x[1], e.x[2], e, k);
    K4.topLeftCorner<3, 3>() = t.K;
    parts.C.topLeftCorner<3, 3>() = t.C;
    parts.source_load.head<3>() = source * t.source;
    return {K4, parts};
  }
  // The conduction is condensed statically; the capacity reads the centre as the mean of the
  // corners at every time (C4 = P^T C5 P), so the centre keeps no heat of its own between steps.
  const auto p = quad_points(e.x);
  Mat5 K = Mat5::Zero();
  Mat5 C = Mat5::Zero();
  Vec5 f = Vec5::Zero();
  for (const auto& tri : quad_triangles) {
    const TriangleBlock t = triangle_block(p[tri[0]], p[tri[1]], p[tri[2]], e, k);
    for (int i = 0; i < 3; ++i) {
      f[tri[i]] += source * t.source[i];
      for (int j = 0; j < 3; ++j) {
        K(tri[i], tri[j]) += t.K(i, j);
        C(tri[i], tri[j]) += t.C(i, j);
      }
    }
  }
  const auto condensed = condense<4, 1>(K, f);
  K4 = condensed.K;
  parts.source_load = condensed.f;
  Eigen::Matrix<double, 5, 4> P = Eigen::Matrix<double, 5, 4>::Zero();
  P.topRows<4>() = Eigen::Matrix4d::Identity();
  P.row(4).setConstant(0.25);
  parts.C = P.transpose() * C * P;
  return {K4, parts};
}

}  // namespace

ConductionLoadParts conduction_load_parts(const ConductionData& e, double source) {
  return conduction_parts(e, source).second;
}

Eigen::Vector4d conduction_load(const ConductionLoadParts& parts, const ConductionLoad& load) {
  Eigen::Vector4d f = parts.source_load;
  if (load.capacity_rate > 0.0) {
    const Eigen::Vector4d previous(load.previous[0], load.previous[1], load.previous[2], load.previous[3]);
    f += load.capacity_rate * (parts.C * previous);
  }
  return f;
}

ConductionBlock conduction_block(const ConductionData& e, const ConductionLoad& load) {
  const auto [K, parts] = conduction_parts(e, load.source);
  ConductionBlock out;
  out.K = K;
  if (load.capacity_rate > 0.0) out.K += load.capacity_rate * parts.C;
  out.f = conduction_load(parts, load);
  return out;
}

Vec2 conduction_flux(const ConductionData& e, const std::array<double, 4>& T) {
  const Eigen::Matrix2d k = e.k.tensor();
  const auto gradient = [&](const Vec2& p0, const Vec2& p1, const Vec2& p2, const std::array<double, 3>& t) {
    const LinearTriangle tri = linear_triangle(p0, p1, p2, e.analysis, e.thickness);
    Vec2 g = Vec2::Zero();
    for (int i = 0; i < 3; ++i) g += Vec2(tri.dN_dr[i], tri.dN_dz[i]) * t[i];
    return std::pair{g, tri.area};
  };
  if (e.node_count == 3) return -k * gradient(e.x[0], e.x[1], e.x[2], {T[0], T[1], T[2]}).first;
  const auto p = quad_points(e.x);
  const auto t = quad_values(T);
  Vec2 sum = Vec2::Zero();
  double area = 0.0;
  for (const auto& tri : quad_triangles) {
    const auto [g, a] = gradient(p[tri[0]], p[tri[1]], p[tri[2]], {t[tri[0]], t[tri[1]], t[tri[2]]});
    sum += a * g;
    area += a;
  }
  return -k * (sum / area);
}

EdgeBlock film_block(const Vec2& a, const Vec2& b, AnalysisType analysis, double thickness, double film,
                     double ambient) {
  const double length = (b - a).norm();
  EdgeBlock out;
  if (analysis == AnalysisType::axisymmetric) {
    const double s = two_pi * film * length / 12.0;
    out.K << s * (3.0 * a.x() + b.x()), s * (a.x() + b.x()), s * (a.x() + b.x()), s * (a.x() + 3.0 * b.x());
  } else {
    const double s = film * thickness * length / 6.0;
    out.K << 2.0 * s, s, s, 2.0 * s;
  }
  const auto w = edge_weights(a, b, analysis, thickness);
  out.f << film * ambient * w[0], film * ambient * w[1];
  return out;
}

}  // namespace saasgaps
