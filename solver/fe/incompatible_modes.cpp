#include "solver/fe/incompatible_modes.hpp"

#include <array>

#include "solver/fe/element_geometry.hpp"
#include "solver/fe/isoparametric_kernel.hpp"

namespace saasgaps {

namespace {

using Mat48 = Eigen::Matrix<double, 4, 8>;
using Mat84 = Eigen::Matrix<double, 8, 4>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

/// The 2 x 2 rule's points: the geometry, weight, compatible B and corrected mode strains G_c.
struct ModePoints {
  std::array<PointGeometry, 4> g;
  std::array<double, 4> w{};
  std::array<Mat48, 4> B;
  std::array<Mat4, 4> G;  ///< columns: a1r, a1z, a2r, a2z
};

ModePoints mode_points(const ElementData& e) {
  const auto rule = family(e.type).stiffness_rule(e.integration);
  const bool axisymmetric = e.analysis == AnalysisType::axisymmetric;
  ModePoints m;
  Mat4 integral = Mat4::Zero();
  double volume = 0.0;
  for (std::size_t p = 0; p < 4; ++p) {
    const double xi = rule[p].xi;
    const double eta = rule[p].eta;
    const PointGeometry& g = m.g[p] = point_geometry(e, xi, eta);
    m.w[p] = volume_weight(e, g, rule[p].weight);
    Mat48& B = m.B[p];
    strain_displacement(g, 4, axisymmetric, B);
    // The bubbles' derivatives through the point's own Jacobian (the same J^-T as the shape functions).
    const std::array<double, 2> P{1.0 - xi * xi, 1.0 - eta * eta};
    const std::array<double, 2> dP_dxi{-2.0 * xi, 0.0};
    const std::array<double, 2> dP_deta{0.0, -2.0 * eta};
    Mat4& G = m.G[p];
    G.setZero();
    for (int i = 0; i < 2; ++i) {
      const Vec2 grad = g.gradient(dP_dxi[static_cast<std::size_t>(i)], dP_deta[static_cast<std::size_t>(i)]);
      const double dr = grad.x();
      const double dz = grad.y();
      G(rr, 2 * i) = dr;
      G(zz, 2 * i + 1) = dz;
      G(rz, 2 * i) = dz;
      G(rz, 2 * i + 1) = dr;
      if (axisymmetric) G(th, 2 * i) = P[static_cast<std::size_t>(i)] / g.r;
    }
    integral += m.w[p] * G;
    volume += m.w[p];
  }
  for (Mat4& G : m.G) G -= integral / volume;
  return m;
}

/// The uncondensed system: 8 nodal unknowns, then the 4 mode amplitudes.
struct FullSystem {
  Mat12 K = Mat12::Zero();
  Vec12 f = Vec12::Zero();
};

FullSystem full_system(const ElementData& e, const ModePoints& m) {
  const bool loaded = e.body_force.x() != 0.0 || e.body_force.y() != 0.0 || e.spin != 0.0;
  FullSystem s;
  for (std::size_t p = 0; p < 4; ++p) {
    Eigen::Matrix<double, 4, 12> BG;
    BG << m.B[p], m.G[p];
    const Constitutive& law = e.law_at(static_cast<int>(p));
    s.K.noalias() += (m.w[p] * BG.transpose()) * (law.D * BG);
    Vec4 stress_free = law.beta * point_temperature_rise(e, m.g[p]);
    if (law.has_initial_strain()) stress_free += law.D * law.initial_strain;
    s.f.noalias() += m.w[p] * (BG.transpose() * stress_free);
    if (loaded) {
      const double br = e.body_force.x() + e.spin * m.g[p].r;
      for (int a = 0; a < 4; ++a) {
        s.f[2 * a] += m.w[p] * m.g[p].shape.N[static_cast<std::size_t>(a)] * br;
        s.f[2 * a + 1] += m.w[p] * m.g[p].shape.N[static_cast<std::size_t>(a)] * e.body_force.y();
      }
    }
  }
  return s;
}

}  // namespace

ElementMatrices incompatible_mode_matrices(const ElementData& e) {
  const ModePoints m = mode_points(e);
  const FullSystem s = full_system(e, m);
  const Condensed<8, 4> c = condense<8, 4>(s.K, s.f);
  ElementMatrices out;
  out.K = c.K;
  out.f = c.f;
  return out;
}

ElementStates incompatible_mode_states(const ElementData& e, std::span<const double> u_span) {
  const ModePoints m = mode_points(e);
  const FullSystem s = full_system(e, m);
  Vec8 u;
  for (int i = 0; i < 8; ++i) u[i] = u_span[static_cast<std::size_t>(i)];
  // K_aa a + K_au u = f_a gives the condensed amplitudes back.
  const Vec4 a = s.K.bottomRightCorner<4, 4>().inverse() * (s.f.tail<4>() - s.K.bottomLeftCorner<4, 8>() * u);
  ElementStates out;
  out.point_count = 4;
  for (std::size_t p = 0; p < 4; ++p) {
    const Vec4 strain = m.B[p] * u + m.G[p] * a;
    out.point[p] = point_state(e, e.law_at(static_cast<int>(p)), strain, point_temperature_rise(e, m.g[p]));
  }
  out.centre = centre_of(e, out);
  return out;
}

}  // namespace saasgaps
