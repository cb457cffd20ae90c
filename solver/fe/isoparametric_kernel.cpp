#include "solver/fe/isoparametric_kernel.hpp"

#include <cassert>

#include "solver/fe/element_geometry.hpp"

namespace saasgaps {

PointGeometry point_geometry(ElementType type, int node_count, const std::array<Vec2, max_element_nodes>& x_nodes,
                             double xi, double eta) {
  PointGeometry g;
  family(type).shape(xi, eta, g.shape);
  double& j11 = g.j11;
  double& j12 = g.j12;
  double& j21 = g.j21;
  double& j22 = g.j22;
  for (int a = 0; a < node_count; ++a) {
    const auto k = static_cast<std::size_t>(a);
    const Vec2& x = x_nodes[k];
    j11 += x.x() * g.shape.dN_dxi[k];
    j12 += x.x() * g.shape.dN_deta[k];
    j21 += x.y() * g.shape.dN_dxi[k];
    j22 += x.y() * g.shape.dN_deta[k];
    g.r += g.shape.N[k] * x.x();
    g.z += g.shape.N[k] * x.y();
  }
  g.det_J = j11 * j22 - j12 * j21;
  // (dN/dr, dN/dz) = J^-T (dN/dxi, dN/deta).
  const double inv = 1.0 / g.det_J;
  for (int a = 0; a < node_count; ++a) {
    const auto k = static_cast<std::size_t>(a);
    g.dN_dr[k] = inv * (j22 * g.shape.dN_dxi[k] - j21 * g.shape.dN_deta[k]);
    g.dN_dz[k] = inv * (-j12 * g.shape.dN_dxi[k] + j11 * g.shape.dN_deta[k]);
  }
  return g;
}

double volume_weight(const ElementData& e, const PointGeometry& g, double weight) {
  return weight * g.det_J * (e.analysis == AnalysisType::axisymmetric ? two_pi * g.r : e.thickness);
}

double point_temperature_rise(const ElementData& e, const PointGeometry& g) {
  double dT = 0.0;
  for (int a = 0; a < e.node_count; ++a) dT += g.shape.N[static_cast<std::size_t>(a)] * e.dT[static_cast<std::size_t>(a)];
  return dT;
}

Vec4 point_strain(const ElementData& e, const PointGeometry& g, std::span<const double> u) {
  Vec4 strain = Vec4::Zero();
  const bool axisymmetric = e.analysis == AnalysisType::axisymmetric;
  for (int a = 0; a < e.node_count; ++a) {
    const auto k = static_cast<std::size_t>(a);
    const double ur = u[2 * k];
    const double uz = u[2 * k + 1];
    strain[rr] += g.dN_dr[k] * ur;
    strain[zz] += g.dN_dz[k] * uz;
    strain[rz] += g.dN_dz[k] * ur + g.dN_dr[k] * uz;
    if (axisymmetric) strain[th] += g.shape.N[k] / g.r * ur;
  }
  return strain;
}

ElementState point_state(const ElementData& e, const Constitutive& law, const Vec4& strain, double dT) {
  ElementState s;
  s.strain = strain;
  s.stress = law.D * strain - law.beta * dT;
  if (law.has_initial_strain()) s.stress -= law.D * law.initial_strain;
  if (e.analysis == AnalysisType::plane_stress) {
    s.strain[th] = law.out_of_plane.dot(s.stress) + law.alpha3 * dT;
    if (law.has_initial_strain()) s.strain[th] += law.initial_strain[th];
  }
  return s;
}

ElementState centre_of(const ElementData& e, const ElementStates& s) {
  const std::span<const double> w = centre_weights(e.type, e.integration);
  ElementState c;
  for (int p = 0; p < s.point_count; ++p) {
    const auto k = static_cast<std::size_t>(p);
    c.strain += w[k] * s.point[k].strain;
    c.stress += w[k] * s.point[k].stress;
  }
  return c;
}

namespace {

/// K and f on fixed-size matrices of N nodes (the hot path of assembly).
template <int N>
ElementMatrices matrices(const ElementData& e) {
  constexpr int n = 2 * N;
  using MatK = Eigen::Matrix<double, n, n>;
  using VecK = Eigen::Matrix<double, n, 1>;
  using MatB = Eigen::Matrix<double, 4, n>;
  assert(e.node_count == N);
  const ElementFamily& f = family(e.type);
  const bool axisymmetric = e.analysis == AnalysisType::axisymmetric;
  const bool loaded = e.body_force.x() != 0.0 || e.body_force.y() != 0.0 || e.spin != 0.0;
  MatK K = MatK::Zero();
  VecK load = VecK::Zero();
  const auto rule = f.stiffness_rule(e.integration);
  for (std::size_t p = 0; p < rule.size(); ++p) {
    const PointGeometry g = point_geometry(e, rule[p].xi, rule[p].eta);
    const double w = volume_weight(e, g, rule[p].weight);
    MatB B;
    strain_displacement(g, N, axisymmetric, B);
    const Constitutive& law = e.law_at(static_cast<int>(p));
    const Eigen::Matrix<double, 4, n> DB = law.D * B;
    K.noalias() += (w * B.transpose()) * DB;
    Vec4 stress_free = law.beta * point_temperature_rise(e, g);  // beta dT + D eps0: the stress a free strain relieves
    if (law.has_initial_strain()) stress_free += law.D * law.initial_strain;
    load.noalias() += w * (B.transpose() * stress_free);
    if (loaded) {
      const double br = e.body_force.x() + e.spin * g.r;
      for (int a = 0; a < N; ++a) {
        load[2 * a] += w * g.shape.N[static_cast<std::size_t>(a)] * br;
        load[2 * a + 1] += w * g.shape.N[static_cast<std::size_t>(a)] * e.body_force.y();
      }
    }
  }
  ElementMatrices m;
  m.K = K;
  m.f = load;
  return m;
}

}  // namespace

ElementMatrices isoparametric_matrices(const ElementData& e) {
  switch (e.node_count) {
    case 4: return matrices<4>(e);
    case 6: return matrices<6>(e);
    case 8: return matrices<8>(e);
    case 9: return matrices<9>(e);
    default: assert(false && "isoparametric families have 4, 6, 8 or 9 nodes"); return {};
  }
}

ElementStates isoparametric_states(const ElementData& e, std::span<const double> u) {
  const auto rule = family(e.type).material_points(e.integration);
  ElementStates s;
  s.point_count = static_cast<int>(rule.size());
  for (std::size_t p = 0; p < rule.size(); ++p) {
    const PointGeometry g = point_geometry(e, rule[p].xi, rule[p].eta);
    s.point[p] = point_state(e, e.law_at(static_cast<int>(p)), point_strain(e, g, u), point_temperature_rise(e, g));
  }
  s.centre = centre_of(e, s);
  return s;
}

}  // namespace saasgaps
