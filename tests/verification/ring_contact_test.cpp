// Our own closed-form check of the gap iteration: two concentric steel rings, the inner one heated
// across a small radial gap into the outer one, in plane strain along z. Lame's solution gives the
// contact pressure p from
//   u_inner(b1) - u_outer(a2) = closure * delta,
//   u_inner(b1) = (1 + nu) alpha dT b1 + (1 + nu)/E [(1 - 2 nu) A_i b1 + B_i / b1],  A_i = -p b1^2/(b1^2 - a1^2),
//                                                                                    B_i = A_i a1^2,
//   u_outer(a2) = (1 + nu)/E [(1 - 2 nu) A_o a2 + B_o / a2],  A_o = p a2^2/(b2^2 - a2^2), B_o = A_o b2^2,
// (plane strain: u = (1 + nu)/E [(1 - 2 nu) A r + B / r] for sigma_r = A - B/r^2). The gaps' normal
// stress must be within 2 % of -p and every gap's closure within the tolerance, both in axisymmetry
// (a slice of the rings held in z) and in plane strain (a quarter annulus, gap elements at many angles).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis.hpp"
#include "support/mesh_builder.hpp"
#include "support/ring_fit.hpp"

namespace saasgaps {
namespace {

using F = testing::RingFit;
constexpr double E = F::E, nu = F::nu, alpha = F::alpha, dT = F::dT;
constexpr double a1 = F::a1, b1 = F::b1, delta = F::delta, a2 = F::a2, b2 = F::b2;

/// Lame contact pressure when the gap closes to `closure` (fraction) of delta.
double lame_contact_pressure(double closure) {
  const double free_growth = (1.0 + nu) * alpha * dT * b1;
  // Radial displacements per unit pressure.
  const double Ai = -b1 * b1 / (b1 * b1 - a1 * a1), Bi = Ai * a1 * a1;
  const double inner = (1.0 + nu) / E * ((1.0 - 2.0 * nu) * Ai * b1 + Bi / b1);
  const double Ao = a2 * a2 / (b2 * b2 - a2 * a2), Bo = Ao * b2 * b2;
  const double outer = (1.0 + nu) / E * ((1.0 - 2.0 * nu) * Ao * a2 + Bo / a2);
  return (closure * delta - free_growth) / (inner - outer);
}

void set_gaps(Model& m, double xfact) {
  m.gaps->initial_modulus = 100.0;
  m.gaps->tensile_schedule = {20.0, 5.0, 1.0};
  m.gaps->extrapolation_factor = xfact;
  m.solver.max_iterations = 40;
}

Model axisymmetric_rings(int radial_elements) {
  Model m = testing::axisymmetric_ring_fit(radial_elements, 0.05);
  set_gaps(m, 0.0);
  return m;
}

Model quarter_annulus_rings(int radial_elements, int hoop_elements, double xfact) {
  Model m = testing::quarter_ring_fit(AnalysisType::plane_strain, radial_elements, hoop_elements);
  set_gaps(m, xfact);
  return m;
}

void expect_lame_contact(const Model& m, const Solution& s) {
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const double tolerance = m.gaps->closure_tolerance;
  double closure_sum = 0.0;
  for (const GapResult& g : s.gaps) {
    EXPECT_GT(g.eps_m, -1.0 - tolerance) << "gap " << g.id;
    EXPECT_LT(g.eps_m, -1.0 + tolerance) << "gap " << g.id;
    closure_sum += g.closure / 100.0;
  }
  const double p = lame_contact_pressure(closure_sum / static_cast<double>(s.gaps.size()));
  ASSERT_GT(p, 0.0);
  for (const GapResult& g : s.gaps) {
    EXPECT_LT(std::abs(-g.sigma_m - p) / p, 0.02) << "gap " << g.id << ": " << g.sigma_m << " vs " << -p;
  }
}

TEST(RingContact, AxisymmetricContactPressureMatchesLame) {
  const Model m = axisymmetric_rings(12);
  expect_lame_contact(m, solve(m));
}

TEST(RingContact, PlaneStrainQuarterAnnulusWithGapsAtManyAngles) {
  const Model m = quarter_annulus_rings(8, 24, 0.0);
  expect_lame_contact(m, solve(m));
}

TEST(RingContact, ExtrapolationReachesTheSameContactSooner) {
  const Model plain = quarter_annulus_rings(8, 24, 0.0);
  const Model extrapolating = quarter_annulus_rings(8, 24, 0.5);
  const Solution without = solve(plain);
  const Solution with = solve(extrapolating);
  expect_lame_contact(extrapolating, with);
  bool used = false;
  for (const IterationRecord& row : with.history) used = used || row.extrapolated;
  EXPECT_TRUE(used);
  EXPECT_LE(with.iterations, without.iterations);
}

}  // namespace
}  // namespace saasgaps
