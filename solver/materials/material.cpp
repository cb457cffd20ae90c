#include "solver/materials/material.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace saasgaps {

namespace {

/// Index of the table segment holding T and the weight of its upper end, clamped to the ends.
template <class Row>
std::pair<std::size_t, double> locate(const std::vector<Row>& table, double T) {
  assert(!table.empty());
  if (table.size() == 1 || T <= table.front().T) return {0, 0.0};
  if (T >= table.back().T) return {table.size() - 2, 1.0};
  const auto upper = std::upper_bound(table.begin(), table.end(), T,
                                      [](double t, const Row& row) { return t < row.T; });
  const auto i = static_cast<std::size_t>(upper - table.begin()) - 1;
  const double span = table[i + 1].T - table[i].T;
  return {i, span > 0.0 ? (T - table[i].T) / span : 0.0};
}

double lerp(double a, double b, double w) { return a + w * (b - a); }

}  // namespace

ElasticConstants interpolate(const std::vector<PropertyRow>& table, double T, bool isotropic) {
  const auto [i, w] = locate(table, T);
  const PropertyRow& a = table[i];
  const PropertyRow& b = table.size() > 1 ? table[i + 1] : table[i];
  ElasticConstants c;
  c.E1 = lerp(a.E1, b.E1, w);
  c.E2 = lerp(a.E2, b.E2, w);
  c.E3 = lerp(a.E3, b.E3, w);
  c.nu12 = lerp(a.nu12, b.nu12, w);
  c.nu13 = lerp(a.nu13, b.nu13, w);
  c.nu23 = lerp(a.nu23, b.nu23, w);
  c.G12 = isotropic ? c.E1 / (2.0 * (1.0 + c.nu12)) : lerp(a.G12, b.G12, w);
  c.alpha1 = lerp(a.alpha1, b.alpha1, w);
  c.alpha2 = lerp(a.alpha2, b.alpha2, w);
  c.alpha3 = lerp(a.alpha3, b.alpha3, w);
  return c;
}

ThermalConstants interpolate_thermal(const std::vector<PropertyRow>& table, double T) {
  const auto [i, w] = locate(table, T);
  const PropertyRow& a = table[i];
  const PropertyRow& b = table.size() > 1 ? table[i + 1] : table[i];
  return {lerp(a.k1, b.k1, w), lerp(a.k2, b.k2, w), lerp(a.k3, b.k3, w), lerp(a.c, b.c, w)};
}

PlasticityRow interpolate(const std::vector<PlasticityRow>& table, double T) {
  const auto [i, w] = locate(table, T);
  const PlasticityRow& a = table[i];
  const PlasticityRow& b = table.size() > 1 ? table[i + 1] : table[i];
  return {T, lerp(a.yield_stress, b.yield_stress, w), lerp(a.hardening_ratio, b.hardening_ratio, w)};
}

DirectionChoice compression_directions(const Vec4& s) {
  DirectionChoice choice = all_tension;
  if (s[0] < 0.0) choice |= 1U;
  if (s[1] < 0.0) choice |= 2U;
  if (s[3] < 0.0) choice |= 4U;
  return choice;
}

ElasticConstants mix_bimodulus(const ElasticConstants& t, const ElasticConstants& c,
                               DirectionChoice choice) {
  const bool c1 = (choice & 1U) != 0;
  const bool c2 = (choice & 2U) != 0;
  const bool c3 = (choice & 4U) != 0;
  const ElasticConstants& d1 = c1 ? c : t;
  const ElasticConstants& d2 = c2 ? c : t;
  const ElasticConstants& d3 = c3 ? c : t;
  ElasticConstants m;
  m.E1 = d1.E1;
  m.E2 = d2.E2;
  m.E3 = d3.E3;
  m.nu12 = d1.nu12;
  m.nu13 = d1.nu13;
  m.nu23 = d2.nu23;
  m.G12 = (c1 == c2) ? d1.G12 : 0.5 * (t.G12 + c.G12);
  m.alpha1 = d1.alpha1;
  m.alpha2 = d2.alpha2;
  m.alpha3 = d3.alpha3;
  return m;
}

ElasticConstants secant(const ElasticConstants& c, double ratio) {
  if (ratio == 1.0) return c;
  ElasticConstants s = c;
  s.E1 *= ratio;
  s.E2 *= ratio;
  s.E3 *= ratio;
  s.G12 *= ratio;
  // Plastic flow is incompressible: the secant Poisson ratio tends to 1/2 as E_s / E falls.
  s.nu12 = 0.5 - (0.5 - c.nu12) * ratio;
  s.nu13 = 0.5 - (0.5 - c.nu13) * ratio;
  s.nu23 = 0.5 - (0.5 - c.nu23) * ratio;
  return s;
}

Mat4 compliance(const ElasticConstants& c) {
  Mat4 S = Mat4::Zero();
  S(0, 0) = 1.0 / c.E1;
  S(1, 1) = 1.0 / c.E2;
  S(2, 2) = 1.0 / c.G12;
  S(3, 3) = 1.0 / c.E3;
  S(0, 1) = S(1, 0) = -c.nu12 / c.E1;
  S(0, 3) = S(3, 0) = -c.nu13 / c.E1;
  S(1, 3) = S(3, 1) = -c.nu23 / c.E2;
  return S;
}

bool positive_definite(const ElasticConstants& c) {
  if (!(c.E1 > 0.0 && c.E2 > 0.0 && c.E3 > 0.0 && c.G12 > 0.0)) return false;
  const Eigen::LLT<Mat4> llt(compliance(c));
  return llt.info() == Eigen::Success;
}

Mat4 strain_rotation(double angle_deg) {
  const double t = angle_deg * std::numbers::pi / 180.0;
  const double c = std::cos(t);
  const double s = std::sin(t);
  Mat4 T;
  // clang-format off
  T <<  c * c,         s * s,         c * s,         0.0,
        s * s,         c * c,        -c * s,         0.0,
       -2.0 * c * s,   2.0 * c * s,   c * c - s * s, 0.0,
        0.0,           0.0,           0.0,           1.0;
  // clang-format on
  return T;
}

Constitutive constitutive(const ElasticConstants& c, AnalysisType analysis, double angle_deg) {
  const Mat4 S = compliance(c);
  Mat4 D_mat = Mat4::Zero();
  if (analysis == AnalysisType::plane_stress) {
    // sigma_3 = 0: invert the in-plane block only; the out-of-plane strain is recovered after.
    D_mat.topLeftCorner<3, 3>() = S.topLeftCorner<3, 3>().inverse();
  } else {
    D_mat = S.inverse();
  }
  const Vec4 alpha_mat(c.alpha1, c.alpha2, 0.0, c.alpha3);
  const Mat4 T = strain_rotation(angle_deg);

  Constitutive law;
  law.D = T.transpose() * D_mat * T;
  law.D = 0.5 * (law.D + law.D.transpose());  // exact symmetry for the assembled matrix
  law.beta = T.transpose() * (D_mat * alpha_mat);
  law.alpha3 = c.alpha3;
  if (analysis == AnalysisType::plane_stress) {
    // eps_3 = S31 sigma_1 + S32 sigma_2, with sigma_mat = T^-T sigma_global.
    const Mat4 T_stress = T.transpose().inverse();
    law.out_of_plane = (S(3, 0) * T_stress.row(0) + S(3, 1) * T_stress.row(1)).transpose();
  }
  return law;
}

double BilinearCurve::stress(double strain) const {
  const double yield_strain = yield_stress / E;
  if (strain <= yield_strain) return E * strain;
  return yield_stress + hardening_ratio * E * (strain - yield_strain);
}

}  // namespace saasgaps
