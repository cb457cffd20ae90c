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

#include "solver/analysis/analysis.hpp"
#include "support/mesh_builder.hpp"
#include "support/quoted_figure.hpp"
#include "support/ring_fit.hpp"

namespace saasgaps {
namespace {

using F = testing::RingFit;
constexpr double E = F::E, nu = F::nu, alpha = F::alpha, dT = F::dT;
constexpr double a1 = F::a1, b1 = F::b1, delta = F::delta, a2 = F::a2, b2 = F::b2;

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

Model axisymmetric_fit(int radial) {
  Model m = testing::axisymmetric_ring_fit(radial, (b1 - a1) / radial);
  exact_gaps(m);
  return m;
}

Model quarter_fit(AnalysisType type, int radial, int hoop) {
  Model m = testing::quarter_ring_fit(type, radial, hoop);
  exact_gaps(m);
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

/// docs/contact.md's errors (%) of the coarse and the fine mesh, each pinned to its quoted digits
/// (which is within 3-4 % of the observed error), and the error falling with refinement.
void expect_converging(const char* name, const Model& coarse, const Model& fine, const char* quoted_coarse,
                       const char* quoted_fine) {
  const double e_coarse = worst_error(coarse, solve(coarse)), e_fine = worst_error(fine, solve(fine));
  std::printf("%s: pressure error %.3e coarse, %.3e fine\n", name, e_coarse, e_fine);
  EXPECT_TRUE(testing::rounds_to(100.0 * e_coarse, quoted_coarse));
  EXPECT_TRUE(testing::rounds_to(100.0 * e_fine, quoted_fine));
  EXPECT_LT(e_fine, e_coarse);
}

TEST(ExactLame, AxisymmetricFitPressureAsDocumentedAndFallingWithRefinement) {
  // Observed 1.989e-4 and 1.246e-5: "0.020 % / 0.0012 %".
  expect_converging("axisymmetric", axisymmetric_fit(6), axisymmetric_fit(24), "0.020", "0.0012");
}

TEST(ExactLame, PlaneStrainFitPressureAsDocumentedAndFallingWithRefinement) {
  // Observed 2.359e-3 and 5.926e-4: "0.24 % / 0.059 %".
  expect_converging("plane strain", quarter_fit(AnalysisType::plane_strain, 4, 24),
                    quarter_fit(AnalysisType::plane_strain, 8, 48), "0.24", "0.059");
}

TEST(ExactLame, PlaneStressFitPressureAsDocumentedAndFallingWithRefinement) {
  // Observed 1.918e-3 and 4.821e-4: "0.19 % / 0.048 %".
  expect_converging("plane stress", quarter_fit(AnalysisType::plane_stress, 4, 24),
                    quarter_fit(AnalysisType::plane_stress, 8, 48), "0.19", "0.048");
}

}  // namespace
}  // namespace saasgaps
