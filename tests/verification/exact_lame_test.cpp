// The exact contact mode against Lame: a heated ring fitted in a ring across a small radial gap.
//
// Closed form (derived here; docs/contact.md repeats it). Inner ring a1..b1 heated by dT, outer ring
// a2..b2 at the reference temperature, a2 = b1 + delta. Lame: sigma_r = A - B/r^2, sigma_t = A + B/r^2,
//   plane stress   u(r) = r/E [(1 - nu) A + (1 + nu) B / r^2],
//   plane strain   u(r) = (1 + nu) r/E [(1 - 2 nu) A + B / r^2]   (also the axisymmetric slice held in z),
// free thermal growth u_T(r) = k alpha dT r with k = 1 (plane stress) or 1 + nu (plane strain).
// Inner ring under external pressure p_i (A = -p_i b1^2/(b1^2 - a1^2), B = A a1^2) moves inward by
// C_i p_i at b1; the outer ring under internal pressure p_o (A = p_o a2^2/(b2^2 - a2^2), B = A b2^2)
// moves outward by C_o p_o at a2:
//   plane stress  C_i = b1 [(1 - nu) b1^2 + (1 + nu) a1^2] / (E (b1^2 - a1^2)),
//                 C_o = a2 [(1 - nu) a2^2 + (1 + nu) b2^2] / (E (b2^2 - a2^2)),
//   plane strain  C_i = (1 + nu) b1 [(1 - 2 nu) b1^2 + a1^2] / (E (b1^2 - a1^2)),
//                 C_o = (1 + nu) a2 [(1 - 2 nu) a2^2 + b2^2] / (E (b2^2 - a2^2)).
// The two faces carry the same force per radian, P = p_i b1 = p_o a2, and the reported pressure is
// that force over the mid-surface of the gap, p = P / r_m, r_m = (b1 + a2)/2 (the pairs' face area is
// the mean of the two faces'). Contact, u_i(b1) - u_o(a2) = delta:
//   u_T(b1) - P C_i / b1 - P C_o / a2 = delta  =>  P = (u_T(b1) - delta) / (C_i / b1 + C_o / a2).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

constexpr double E = 30.0e6, nu = 0.3, alpha = 6.5e-6, dT = 400.0;
constexpr double a1 = 1.0, b1 = 1.5, delta = 0.002, a2 = b1 + delta, b2 = 2.2;

double lame_fit_pressure(AnalysisType type) {
  const bool stress = type == AnalysisType::plane_stress;
  const double growth = (stress ? 1.0 : 1.0 + nu) * alpha * dT * b1;
  const double Ci = stress ? b1 * ((1 - nu) * b1 * b1 + (1 + nu) * a1 * a1) / (E * (b1 * b1 - a1 * a1))
                           : (1 + nu) * b1 * ((1 - 2 * nu) * b1 * b1 + a1 * a1) / (E * (b1 * b1 - a1 * a1));
  const double Co = stress ? a2 * ((1 - nu) * a2 * a2 + (1 + nu) * b2 * b2) / (E * (b2 * b2 - a2 * a2))
                           : (1 + nu) * a2 * ((1 - 2 * nu) * a2 * a2 + b2 * b2) / (E * (b2 * b2 - a2 * a2));
  const double P = (growth - delta) / (Ci / b1 + Co / a2);
  return P / (0.5 * (b1 + a2));
}

void exact_gaps(Model& m) {
  m.gaps->method = GapMethod::exact;
  m.gaps->initial_modulus = 100.0;
  m.gaps->tensile_schedule = {20.0, 5.0, 1.0};
}

void heat_inner(Model& m, const testing::Grid& inner) {
  testing::fill_temperatures(m, 0.0);
  for (int n : inner.nodes) m.loads.node_temperature[n] = dT;
}

Model axisymmetric_fit(int radial) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {testing::isotropic_material(1, E, nu, alpha)};
  const double h = (b1 - a1) / radial;
  const auto slab = [h](double r0, double r1) { return [=](double s, double t) { return Vec2(r0 + s * (r1 - r0), t * h); }; };
  const testing::Grid inner = testing::add_grid(m, radial, 1, slab(a1, b1), 0);
  const testing::Grid outer = testing::add_grid(m, radial, 1, slab(a2, b2), 0);
  m.gaps.emplace();
  testing::add_gap_row(m, {outer.at(0, 0), outer.at(0, 1)}, {inner.at(radial, 0), inner.at(radial, 1)},
                       [](int) { return 0.0; });  // counter-clockwise: outer face first
  exact_gaps(m);
  heat_inner(m, inner);
  for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) testing::constrain(m, n, std::nullopt, 0.0);
  return m;
}

Model quarter_fit(AnalysisType type, int radial, int hoop) {
  Model m;
  m.analysis = type;
  m.materials = {testing::isotropic_material(1, E, nu, alpha)};
  const auto annulus = [](double r0, double r1) {
    return [=](double s, double t) {
      const double r = r0 + s * (r1 - r0), angle = t * std::numbers::pi / 2.0;
      return Vec2(r * std::cos(angle), r * std::sin(angle));
    };
  };
  const testing::Grid inner = testing::add_grid(m, radial, hoop, annulus(a1, b1), 0);
  const testing::Grid outer = testing::add_grid(m, radial, hoop, annulus(a2, b2), 0);
  m.gaps.emplace();
  std::vector<int> face_a, face_b;
  for (int j = 0; j <= hoop; ++j) {
    face_a.push_back(inner.at(radial, j));
    face_b.push_back(outer.at(0, j));
  }
  // add_gap_row makes (a_k, a_k+1, b_k+1, b_k): clockwise here, so give the rows swapped.
  testing::add_gap_row(m, face_b, face_a, [hoop](int k) { return 90.0 * (k + 0.5) / hoop; });
  exact_gaps(m);
  heat_inner(m, inner);
  for (const testing::Grid* ring : {&inner, &outer}) {
    for (int i = 0; i <= radial; ++i) {
      testing::constrain(m, ring->at(i, 0), std::nullopt, 0.0);
      testing::constrain(m, ring->at(i, hoop), 0.0, std::nullopt);
    }
  }
  return m;
}

/// Largest relative error of the gaps' contact pressure against Lame.
double worst_error(const Model& m, const Solution& s) {
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  const double p = lame_fit_pressure(m.analysis == AnalysisType::axisymmetric ? AnalysisType::plane_strain : m.analysis);
  double worst = 0.0;
  for (const GapResult& g : s.gaps) {
    EXPECT_EQ(g.state, GapState::closed) << "gap " << g.id;
    EXPECT_NEAR(g.closure, 100.0, 1e-6) << "gap " << g.id;
    worst = std::max(worst, std::abs(-g.sigma_m - p) / p);
  }
  return worst;
}

TEST(ExactLame, AxisymmetricFitPressureWithinAThirdOfAPercentAndFallingWithRefinement) {
  const Model coarse = axisymmetric_fit(6), fine = axisymmetric_fit(24);
  const double e_coarse = worst_error(coarse, solve(coarse)), e_fine = worst_error(fine, solve(fine));
  std::printf("axisymmetric: %.3e %.3e\n", e_coarse, e_fine);
  EXPECT_LT(e_coarse, 0.003);
  EXPECT_LT(e_fine, e_coarse);
}

TEST(ExactLame, PlaneStrainFitPressureWithinAThirdOfAPercentAndFallingWithRefinement) {
  const Model coarse = quarter_fit(AnalysisType::plane_strain, 4, 24);
  const Model fine = quarter_fit(AnalysisType::plane_strain, 8, 48);
  const double e_coarse = worst_error(coarse, solve(coarse)), e_fine = worst_error(fine, solve(fine));
  std::printf("plane strain: %.3e %.3e\n", e_coarse, e_fine);
  EXPECT_LT(e_coarse, 0.003);
  EXPECT_LT(e_fine, e_coarse);
}

TEST(ExactLame, PlaneStressFitPressureWithinAThirdOfAPercentAndFallingWithRefinement) {
  const Model coarse = quarter_fit(AnalysisType::plane_stress, 4, 24);
  const Model fine = quarter_fit(AnalysisType::plane_stress, 8, 48);
  const double e_coarse = worst_error(coarse, solve(coarse)), e_fine = worst_error(fine, solve(fine));
  std::printf("plane stress: %.3e %.3e\n", e_coarse, e_fine);
  EXPECT_LT(e_coarse, 0.003);
  EXPECT_LT(e_fine, e_coarse);
}

}  // namespace
}  // namespace saasgaps
